#!/usr/bin/python3
"""capbridge benchmarks (issue 6): every figure is a ratio or a curve measured in one run of
this command on one machine, the ratio of each repeat formed before the median, so that a
slow phase of a shared machine falls on both sides.  Part 1 runs each side at the same time
as the reference, both pinned to one core, and compares their CPU times (the scheduler
interleaves the two every few milliseconds); parts 2 and 3 alternate the sides, the order
rotating from one repeat to the next.  Nothing here is a test: no time is asserted anywhere.

  1  LAMMPS: gran/capillary with bridges (law richefeu) and with no liquid, against LAMMPS's
     own dry gran/hooke/history, on the cyclic compression scene (bench/in.cycle.lammps);
     beside them what a LAMMPS user picks today: pair_style granular, hooke with tangential
     history (the same physics as gran/hooke/history) and the cohesive jkr; and the
     structure floor, the wet side in a plugin built with CAPBRIDGE_STRUCTURE_FLOOR (the wet
     list and bridge history, the dry forces alone: what a bridge costs beyond its structure)
  2  LIGGGHTS: cohesion capillary against LIGGGHTS's own easo/capillary/viscous on the same
     scene (bench/in.cycle.liggghts)
  3  MPI: the default split-bottom scene (first 0.2 s of rotation) on 1 and 2 ranks, and the
     time per particle-step of the cyclic compression scene (wet) from 2 000 to 64 000 grains
  4  the cost of each law per force call (capbridge bench) and the uniaxial compression
     strength (smoke size, LAMMPS, 2 ranks) against wall time as the time step goes from
     1/10 to 1/100 of the contact time

Usage: bench/run.sh [--parts 1,2,3,4] [--repeats N] [--quick]
  --quick: smaller scenes and fewer points (a check that the benchmark runs, ~5 min)
Writes bench/results/part<N>.md for each part it runs and assembles bench/README.md from
bench/README.head.md and the four parts' latest results (each states its own date, machine and
command), so that one part can be measured again alone.  --quick writes its parts to
out/bench/quick/ and leaves bench/README.md as it is.

       bench/run.sh --compare A.so|stock B.so [--side wet|off] [--repeats N, default 4]
Instead of the parts: two builds of the LAMMPS plugin against each other, by part 1's method,
on one side of its scene (16 000 grains, 2000 steps); A may be stock, LAMMPS's own dry style.
Prints B's CPU time over A's per repeat (copy build/lammps_pair/lammps/capbridgeplugin.so
aside before rebuilding for B).  A developer's tool for a change to the hot path.
"""
import argparse
import datetime
import importlib.util
import os
import platform
import statistics
import subprocess
import sys

import engines

HERE = os.path.dirname(os.path.abspath(__file__))
TOP = os.path.dirname(HERE)
OUT = os.path.join(TOP, "out", "bench")
RESULTS = os.path.join(HERE, "results")    # each part's latest full measurement
PLUGIN = os.path.join(TOP, "build", "lammps_pair", "lammps", "capbridgeplugin.so")
CLI = os.path.join(TOP, "build", "src_c", "cli", "capbridge")


def machine():
    model = "unknown CPU"
    if os.path.isfile("/proc/cpuinfo"):
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    model = line.split(":", 1)[1].strip()
                    break
    load = os.getloadavg()[0]
    return (f"{model}, {os.cpu_count()} cores, {platform.system()} {platform.release()}; "
            f"load average {load:.2f} at the start of the part")


def alternate(sides, repeats, run_side):
    """Runs every side `repeats` times, the order rotating each repeat; returns
    {side: [Loop, ...]} in repeat order."""
    names = list(sides)
    times = {name: [] for name in names}
    for r in range(repeats):
        order = names[r % len(names):] + names[:r % len(names)]
        for name in order:
            loop = run_side(name, sides[name], r)
            times[name].append(loop)
            print(f"  repeat {r + 1}/{repeats} {name}: {loop.seconds:.2f} s, "
                  f"{loop.us_per_particle_step():.3f} us per particle-step", flush=True)
    return times


def ratio_stats(times, side, reference):
    """Median, min and max over the repeats of time(side) / time(reference)."""
    ratios = [a.seconds / b.seconds for a, b in zip(times[side], times[reference])]
    return statistics.median(ratios), min(ratios), max(ratios)


def median_us(loops):
    return statistics.median(l.us_per_particle_step() for l in loops)


def header(part, title, command):
    return (f"## {part}. {title}\n\nMeasured {datetime.datetime.now():%Y-%m-%d %H:%M} on "
            f"{machine()}.\nCommand: `{command}`\n\n")


def base_packing(ctx):
    """The jammed 2000-grain packing both engines' cycle decks read (made once)."""
    data = os.path.join(OUT, "base.data")
    if not os.path.isfile(data):
        print("bench: preparing the base packing (2000 grains, LAMMPS, ~10 s)", flush=True)
        engines.run(ctx.lammps, 1, os.path.join(HERE, "in.cycle.lammps"), OUT, "prep.log",
                    {"stage": "prep", "data": data})
    return data


# ---------------------------------------------------------------------------------------------
def instructions(ctx, sides, data, work):
    """The instructions each side of part 1 executes in one cycle of the base packing (2000
    grains; --quick: a quarter cycle), counted by callgrind: the same count on a busy or an
    idle machine, where the times of part 1 carry a few per cent from run to run.  Two sides
    at a time (one per core).  Returns {side: (whole run, pair style's compute inclusive)}."""
    steps = 500 if ctx.quick else 2000
    counts = {}
    names = list(sides)
    for first in range(0, len(names), 2):
        started = {}
        for name in names[first:first + 2]:
            out = os.path.join(work, f"{name}.callgrind")
            tool = ["valgrind", "--tool=callgrind", f"--callgrind-out-file={out}"]
            started[name] = (out, engines.start(ctx.lammps, 1, os.path.join(HERE,
                                                "in.cycle.lammps"), work,
                                                f"{name}.callgrind.log",
                                                dict(sides[name], data=data, steps=steps),
                                                tool=tool))
        for name, (out, run) in started.items():
            engines.finish(run)
            report = subprocess.run(["callgrind_annotate", "--inclusive=yes", out],
                                    capture_output=True, text=True, check=True).stdout
            total = pair = None
            for line in report.splitlines():
                words = line.split()
                if not words or not words[0].replace(",", "").isdigit():
                    continue
                if "PROGRAM TOTALS" in line:
                    total = int(words[0].replace(",", ""))
                elif pair is None and "Pair" in line and "::compute(int, int)" in line:
                    pair = int(words[0].replace(",", ""))
            if total is None or pair is None:
                engines.fail(f"{out}: no program total or pair compute in callgrind's report")
            counts[name] = (total, pair)
            print(f"  instructions {name}: {total:.4g} in all, {pair:.4g} in the pair style",
                  flush=True)
    return counts, steps


def floor_plugin(ctx):
    """The plugin of part 1's structure floor: lammps_pair/lammps built on its own with
    CAPBRIDGE_STRUCTURE_FLOOR in out/bench/floor-build (incremental: a rebuild after a source
    change only), the build type of build/."""
    work = os.path.join(OUT, "floor-build")
    build_type = "Release"
    cache = os.path.join(TOP, "build", "CMakeCache.txt")
    if os.path.isfile(cache):
        with open(cache) as f:
            for line in f:
                if line.startswith("CMAKE_BUILD_TYPE:STRING="):
                    build_type = line.split("=", 1)[1].strip() or build_type
    print("bench: building the structure-floor plugin (CAPBRIDGE_STRUCTURE_FLOOR)", flush=True)
    for command in (["cmake", "-S", os.path.join(TOP, "lammps_pair", "lammps"), "-B", work,
                     f"-DCAPBRIDGE_LAMMPS_ENV={ctx.lammps_env}", "-DCAPBRIDGE_STRUCTURE_FLOOR=ON",
                     f"-DCMAKE_BUILD_TYPE={build_type}"],
                    ["cmake", "--build", work, "-j2"]):
        done = subprocess.run(command, capture_output=True, text=True)
        if done.returncode != 0:
            engines.fail(f"the structure-floor plugin: {' '.join(command)} failed:\n"
                         f"{done.stdout[-2000:]}{done.stderr[-2000:]}")
    return os.path.join(work, "capbridgeplugin.so")


def part1_copies(ctx):
    """Copies of the base packing along x, y, z in part 1's scene (16 000 grains; --quick
    8 000); --compare runs the full scene."""
    return (2, 2, 1) if ctx.quick else (2, 2, 2)


def part1(ctx):
    copies = part1_copies(ctx)
    data = base_packing(ctx)
    deck = os.path.join(HERE, "in.cycle.lammps")
    work = os.path.join(OUT, "part1")
    sides = {
        "stock": {"side": "stock"},
        "granular": {"side": "granular"},
        "jkr": {"side": "jkr"},
        "off": {"side": "off", "plugin": PLUGIN},
        "wet": {"side": "wet", "plugin": PLUGIN},
        "floor": {"side": "wet", "plugin": floor_plugin(ctx)},
    }

    def beside_stock(name, r):
        """`name` and stock at once on one core (engines.beside); the launch order alternates.
        Returns (stock, name) Loops."""
        runs = [("reference", "stock"), ("measured", name)]
        if r % 2:
            runs.reverse()
        loops = engines.beside(ctx.lammps, deck, work, [
            (label, f"{name}.{label}.{r}.log",
             dict(sides[side], data=data, nx=copies[0], ny=copies[1], nz=copies[2], steps=2000))
            for label, side in runs])
        return loops["reference"], loops["measured"]

    ratios = {name: [] for name in sides}
    cpu_us = {name: [] for name in sides}
    for r in range(ctx.repeats):
        for name in sides:
            stock, measured = beside_stock(name, r)
            ratios[name].append(measured.cpu_seconds() / stock.cpu_seconds())
            for loop, side in ((stock, "stock"), (measured, name)):
                cpu_us[side].append(1e6 * loop.cpu_seconds() / (loop.steps * loop.atoms))
            print(f"  repeat {r + 1}/{ctx.repeats} {name} / stock: {ratios[name][-1]:.3f} "
                  f"(CPU {measured.cpu_seconds():.2f} s / {stock.cpu_seconds():.2f} s)",
                  flush=True)
    n = stock.atoms
    # the interactions each side computes, counted in a run of its own (untimed)
    census_log = engines.run(ctx.lammps, 1, deck, work, "census.log",
                             dict(sides["wet"], data=data, nx=copies[0], ny=copies[1],
                                  nz=copies[2], steps=2000, census="yes"))
    with open(census_log) as f:
        words = [line.split() for line in f if line.startswith("CENSUS")][-1]
    contacts, bridges = float(words[2]), float(words[4])

    counted, counted_steps = instructions(ctx, sides, data, work)

    wet_over_floor = [w / f for w, f in zip(ratios["wet"], ratios["floor"])]

    def cell(name):
        values = ratios[name]
        return (f"**{statistics.median(values):.3f}** ({min(values):.3f}-{max(values):.3f})")

    def us(name):
        return f"{statistics.median(cpu_us[name]):.3f}"

    text = header(1, "Wet and dry against LAMMPS's own dry contact", ctx.command)
    text += (f"Scene: bench/in.cycle.lammps, {n} grains (1.0 and 1.2 mm, jammed, periodic), "
             f"2000 steps = one compression cycle of 3 %, 1 rank.  Each side runs at the same "
             f"time as a stock run, both pinned to one core, and the ratio is of their CPU "
             f"times (the loop's wall time times its CPU use); {ctx.repeats} repeats, median "
             "and min-max.  The first row, stock beside stock, is the method's control.  The "
             "times per particle-step are CPU times while sharing the core with the stock "
             "run (the two share its caches).\n\n"
             f"Census of the wet side, averaged over the cycle (a run of its own, untimed): "
             f"{contacts:.2f} contacts and {bridges:.2f} bridges per grain (pairs / grains), so "
             f"{bridges - contacts:.2f} stretched bridges per grain beside the contacts, which "
             "every side computes.\n\n"
             "| side | pair style | CPU us per particle-step, sharing (median) | "
             "time / stock: median (min-max) | target |\n|---|---|---:|---:|---|\n"
             f"| stock | gran/hooke/history (dry), beside itself | {us('stock')} | "
             f"{cell('stock')} | 1 |\n"
             f"| granular | granular: hooke, tangential linear_history, damping "
             f"mass_velocity (dry, the stock physics) | {us('granular')} | "
             f"{cell('granular')} | — |\n"
             f"| jkr | granular: jkr (E 1e6 Pa, Poisson 0.3, 0.1 J/m^2), the same tangential "
             f"and damping (cohesive) | {us('jkr')} | {cell('jkr')} | — |\n"
             f"| off | gran/capillary, volume 0 | {us('off')} | {cell('off')} | <= 1.02 |\n"
             f"| wet | gran/capillary, law richefeu, 1e-11 m^3 on every contact | {us('wet')} "
             f"| {cell('wet')} | <= 1.10 (aim 1.05) |\n"
             f"| floor | the wet side's list and history, dry forces (build option "
             f"CAPBRIDGE_STRUCTURE_FLOOR) | {us('floor')} | {cell('floor')} | — |\n\n"
             f"Wet over the structure floor, per repeat (each over its own stock run): "
             f"**{statistics.median(wet_over_floor):.3f}** ({min(wet_over_floor):.3f}-"
             f"{max(wet_over_floor):.3f}); target <= 1.05 (issue 20: the bridge physics nearly "
             "free on top of the structure it needs).\n\n"
             f"Instructions executed, counted by callgrind (valgrind) in a run of its own: the "
             f"base packing (2000 grains), {counted_steps} steps.  A count, not a time: it is "
             "the same on a busy or an idle machine, but it does not see cache misses or "
             "mispredicted branches, which a time does.\n\n"
             "| side | instructions, whole run | / stock | in the pair style's compute "
             "(inclusive) | / stock |\n|---|---:|---:|---:|---:|\n")
    for name in sides:
        total, pair = counted[name]
        text += (f"| {name} | {total:.4g} | **{total / counted['stock'][0]:.3f}** | {pair:.4g} "
                 f"| **{pair / counted['stock'][1]:.3f}** |\n")
    text += "\n"
    summary = (f"LAMMPS, {n} grains: wet / stock dry **{statistics.median(ratios['wet']):.2f}** "
               f"(target 1.10), liquid off / stock dry "
               f"**{statistics.median(ratios['off']):.3f}** (target 1.02); the same method "
               f"gives stock / stock {statistics.median(ratios['stock']):.3f}; LAMMPS's "
               f"granular hooke / stock {statistics.median(ratios['granular']):.2f}, granular "
               f"jkr / stock {statistics.median(ratios['jkr']):.2f}; wet / structure floor "
               f"{statistics.median(wet_over_floor):.3f} (target 1.05); instructions "
               f"(callgrind, 2000 grains) wet / stock "
               f"{counted['wet'][0] / counted['stock'][0]:.2f}, off / stock "
               f"{counted['off'][0] / counted['stock'][0]:.3f}")
    return text, summary


def part2(ctx):
    copies = (2, 1, 1) if ctx.quick else (2, 2, 1)
    data = base_packing(ctx)
    sides = ["easo", "soulie", "protocol2", "richefeu", "dry"]

    def run_side(name, side, r):
        work = os.path.join(OUT, "part2")
        log = engines.run(ctx.liggghts, 1, os.path.join(HERE, "in.cycle.liggghts"), work,
                          f"{name}.{r}.log", {"bench": HERE, "data": data, "side": side,
                                              "nx": copies[0], "ny": copies[1], "nz": copies[2],
                                              "steps": 2000})
        return engines.loops(log)[-1]

    times = alternate({s: s for s in sides}, ctx.repeats, run_side)
    n = times["easo"][0].atoms
    text = header(2, "Against LIGGGHTS's own capillary model", ctx.command)
    text += (f"Scene: bench/in.cycle.liggghts (the LAMMPS scene in LIGGGHTS 3.8.0, contact model "
             f"hooke/stiffness with tangential history), {n} grains, 2000 steps, 1 rank; "
             f"{ctx.repeats} repeats, the five sides alternating. Target: capbridge's time per "
             "particle-step no higher than easo/capillary/viscous's (ratio <= 1).\n\n"
             "| side | cohesion model | us per particle-step (median) | time / easo: median "
             "(min-max) |\n|---|---|---:|---:|\n")
    models = {
        "easo": "easo/capillary/viscous (per-particle liquid, Soulie's law, viscous off)",
        "soulie": "capillary law soulie rupture lian (the same law), fixed volume",
        "protocol2": "capillary law soulie, liquid protocol2 (per-particle liquid, as easo)",
        "richefeu": "capillary law richefeu, fixed volume",
        "dry": "none (the contact model alone)",
    }
    for side in sides:
        cell = "1"
        if side != "easo":
            med, lo, hi = ratio_stats(times, side, "easo")
            cell = f"**{med:.3f}** ({lo:.3f}-{hi:.3f})"
        text += f"| {side} | {models[side]} | {median_us(times[side]):.3f} | {cell} |\n"
    text += "\n"
    soulie = ratio_stats(times, "soulie", "easo")[0]
    protocol2 = ratio_stats(times, "protocol2", "easo")[0]
    summary = (f"LIGGGHTS, {n} grains: capbridge / easo/capillary/viscous **{soulie:.2f}** "
               f"(same law, fixed volume), **{protocol2:.2f}** (Protocol 2) (target <= 1)")
    return text, summary


def part3(ctx):
    split = os.path.join(TOP, "inputs", "split_bottom")

    def run_ranks(name, ranks, r):
        work = os.path.join(OUT, "part3", f"split_bottom-np{ranks}-{r}")
        log = engines.run(ctx.lammps, ranks, os.path.join(split, "in.lammps"), work,
                          "log.lammps", {"size": "smoke" if ctx.quick else "default",
                                         "inputs": split, "plugin": PLUGIN,
                                         "tshear": 0.2, "tavg": 0.2})
        return engines.loops(log)[1]  # the rotation (settling is loops[0])

    times = alternate({"1": 1, "2": 2}, ctx.repeats, run_ranks)
    t1, t2 = median_us(times["1"]), median_us(times["2"])
    speedup, slowest, fastest = ratio_stats(times, "1", "2")  # time on 1 rank / on 2
    n = times["1"][0].atoms
    steps = times["1"][0].steps
    text = header(3, "MPI: parallel efficiency and growth with N", ctx.command)
    text += (f"Split-bottom cell, size {'smoke' if ctx.quick else 'default'} (LAMMPS, law "
             f"willett, 13.6 nl, {n} atoms with the wall grains), the first 0.2 s of rotation "
             f"({steps} steps) timed after the settling; {ctx.repeats} repeats, 1 and 2 ranks "
             "alternating.\n\n| ranks | us per particle-step (wall, median) |\n|---:|---:|\n"
             f"| 1 | {t1:.3f} |\n| 2 | {t2:.3f} |\n\n"
             f"Speed-up 2 ranks / 1 rank: **{speedup:.2f}** (min {slowest:.2f}, max "
             f"{fastest:.2f}): parallel efficiency **{100 * speedup / 2:.0f} %**.\n\n")

    data = base_packing(ctx)
    grids = {"1x1x1": (1, 1, 1), "2x1x1": (2, 1, 1), "2x2x1": (2, 2, 1), "2x2x2": (2, 2, 2)}
    if not ctx.quick:
        grids.update({"4x2x2": (4, 2, 2), "4x4x2": (4, 4, 2)})

    def run_size(name, grid, r):
        nx, ny, nz = grid
        work = os.path.join(OUT, "part3", f"cycle-{name}-{r}")
        log = engines.run(ctx.lammps, 2, os.path.join(HERE, "in.cycle.lammps"), work,
                          "log.lammps", {"side": "wet", "plugin": PLUGIN, "data": data,
                                         "nx": nx, "ny": ny, "nz": nz, "steps": 1000})
        return engines.loops(log)[-1]

    # The sizes alternate like the sides of the other parts: one run per size had read
    # 0.42 us at 2 000 grains against 0.21-0.25 above, a slow phase of the machine.
    sizes = alternate(grids, ctx.repeats, run_size)
    first = median_us(sizes["1x1x1"])
    text += ("Cyclic compression scene, wet (gran/capillary, law richefeu), the base packing "
             f"replicated; 1000 steps (half a cycle), 2 ranks; {ctx.repeats} repeats, the sizes "
             "alternating:\n\n| grains | us per particle-step (wall, median) | min-max | "
             "relative to 2 000 grains |\n|---:|---:|---:|---:|\n")
    for name in grids:
        us = [loop.us_per_particle_step() for loop in sizes[name]]
        text += (f"| {sizes[name][0].atoms} | {statistics.median(us):.3f} | "
                 f"{min(us):.3f}-{max(us):.3f} | {statistics.median(us) / first:.2f} |\n")
    text += "\n"
    summary = (f"MPI: split-bottom {'smoke' if ctx.quick else 'default'} 2 ranks / 1 rank "
               f"speed-up **{speedup:.2f}** ({100 * speedup / 2:.0f} % efficiency)")
    return text, summary


def uniaxial_post():
    """inputs/uniaxial/post.py, for its strength definition (one place for it)."""
    path = os.path.join(TOP, "inputs", "uniaxial", "post.py")
    spec = importlib.util.spec_from_file_location("uniaxial_post", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def part4(ctx):
    text = header(4, "Cost per law and accuracy against run time", ctx.command)
    cost = subprocess.run([CLI, "bench"], check=True, stdout=subprocess.PIPE, text=True).stdout
    rows = [line.split(",") for line in cost.strip().splitlines()[1:]]
    text += ("Per force call (`capbridge bench`, one run, laws interleaved: 4096 pairs with size "
             "ratios 1-10 and volumes 1e-5 to 0.1 R_h^3 at uniform fractions of the rupture "
             "distance, water, theta = 0; process CPU time; the rupture distance alone, "
             "`cb_rupture_distance`, is what a law pays to place the pair before its force, "
             "for the table law its stencil; the bridge step is the call an engine makes per "
             "step for a stretched bridge, `cb_bridge_force` on a state whose constants were "
             "derived when it got its volume):\n\n"
             "| law | ns per call | / cheapest closed form | rupture distance alone [ns] | "
             "ns per bridge step | / cheapest closed form |\n"
             "|---|---:|---:|---:|---:|---:|\n")
    text += "".join(f"| {law} | {ns} | {ratio} | {rupture} | {step} | {step_ratio} |\n"
                    for law, ns, ratio, rupture, step, step_ratio in rows)

    # One sample, compressed at each time step several times: the compression is chaotic, so
    # that any change of the time step gives another trajectory and another peak.  Replicas
    # at time steps 1e-4 apart (a systematic change far below any shown here) measure that
    # scatter, and each time step's error is its replicas' mean against the smallest step's.
    post = uniaxial_post()
    prepare = 0.095     # the sample's preparation time step / t_c, passed to the deck
    fractions = [0.1, 0.05] if ctx.quick else [0.1, 0.05, 0.025, 0.01]
    replicas = 2 if ctx.quick else 5
    deck_dir = os.path.join(TOP, "inputs", "uniaxial")
    results = []
    for frac in fractions:
        sigmas, walls = [], []
        for k in range(replicas):
            dtcompress = frac * (1.0 + 1e-4 * k)
            work = os.path.join(OUT, "part4", f"uniaxial-dt{frac:g}-{k}")
            log = engines.run(ctx.lammps, 2, os.path.join(deck_dir, "in.lammps"), work,
                              "log.lammps", {"size": "smoke", "inputs": deck_dir,
                                             "plugin": PLUGIN, "dtfrac": repr(prepare),
                                             "dtcompress": repr(dtcompress)})
            walls.append(engines.loops(log)[-1].seconds)    # the compression, the last run
            sigmas.append(post.strength(post.read_curve(work)[:, 3]))
        print(f"  dt = t_c x {frac:g}: sigma_rupt {' '.join(f'{x:.1f}' for x in sigmas)} Pa, "
              f"compression {statistics.median(walls):.1f} s", flush=True)
        results.append((frac, statistics.mean(sigmas), min(sigmas), max(sigmas),
                        statistics.median(walls)))
    reference = results[-1][1]

    def error(sigma):
        return 100 * (sigma - reference) / reference

    text += ("\nUniaxial compression, smoke size (600 spheres, w = 2 %, Protocol 1, LAMMPS, 2 "
             f"ranks): one sample, prepared at dt = {prepare:g} t_c in every run (the same pour, "
             "bridges and relaxation), compressed at time steps from 1/10 to "
             f"1/{round(1 / fractions[-1])} of the contact time t_c = pi sqrt(m_min/k_n) "
             f"(the deck's dtcompress), {replicas} times each at time steps 1e-4 apart: the "
             "compression is chaotic, and the replicas' spread is the scatter of the peak "
             "stress of one 600-sphere sample.  Error: the replicas' mean against the "
             "smallest step's; wall time: the compression's (median).\n\n"
             "| dt / t_c | sigma_rupt [Pa], mean (min-max) | error of the mean | spread | "
             "wall time of the compression [s] |\n|---:|---:|---:|---:|---:|\n")
    for frac, mean, low, high, wall in results:
        text += (f"| 1/{round(1 / frac)} | {mean:.1f} ({low:.1f}-{high:.1f}) | "
                 f"{error(mean):+.1f} % | {100 * (high - low) / reference:.1f} % | {wall:.1f} |\n")
    text += ("\nNo mass scaling: Richefeu 2007 runs the compression quasi-statically at the "
             "grains' real density, and the sample's relaxation under gravity before the "
             "compression (part of the scene) depends on it.\n\n")
    table = next(r for r in rows if r[0] == "table")
    summary = (f"laws: {min(float(r[1]) for r in rows):.0f}-{max(float(r[1]) for r in rows):.0f} "
               f"ns per call, table {table[2]} x the cheapest ({table[5]} x per bridge step); "
               f"uniaxial smoke at dt = t_c/10: "
               f"{error(results[0][1]):+.1f} % (replicas' spread "
               f"{100 * (results[0][3] - results[0][2]) / reference:.1f} %) in "
               f"{results[0][4] / results[-1][4]:.2f} of the compression time of "
               f"t_c/{round(1 / fractions[-1])}")
    return text, summary


PARTS = {1: part1, 2: part2, 3: part3, 4: part4}


def assemble():
    """bench/README.md: the head, then every part's latest results, then their summaries."""
    with open(os.path.join(HERE, "README.head.md")) as f:
        text = f.read()
    summaries = []
    for part in sorted(PARTS):
        path = os.path.join(RESULTS, f"part{part}.md")
        if os.path.isfile(path):
            with open(path) as f:
                body = f.read()
            text += "\n" + body.split("\n<!-- summary: ")[0]
            summaries.append(body.split("\n<!-- summary: ")[1].split(" -->")[0])
    text += "\n## Summary\n\n" + "".join(f"- {s}\n" for s in summaries)
    with open(os.path.join(HERE, "README.md"), "w") as f:
        f.write(text)
    return summaries


def compare(ctx, a, b, side, options_a=""):
    """Two builds of the LAMMPS plugin against each other on one side of part 1's scene, by
    part 1's method (engines.beside, the launch order alternating); a may be "stock",
    LAMMPS's own dry style.  Prints B's CPU time over A's per repeat, then B's instructions
    over A's (callgrind, as part 1 counts them): a developer's tool for a change to the hot
    path.  Run A against A first: its spread bounds what a comparison
    can resolve.  options_a: words added to A's pair_style (an older build whose defaults
    differ, e.g. "friction dry" for one before the eq. 12 limit), so that both run the same
    physics."""
    data = base_packing(ctx)
    copies = part1_copies(ctx)
    deck = os.path.join(HERE, "in.cycle.lammps")
    work = os.path.join(OUT, "compare")
    builds = {"A": a, "B": b}
    options = {"A": options_a, "B": ""}
    for r in range(ctx.repeats):
        order = ["A", "B"] if r % 2 == 0 else ["B", "A"]
        runs = []
        for label in order:
            build = builds[label]
            variables = ({"side": "stock"} if build == "stock"
                         else {"side": side, "plugin": build, "options": options[label]})
            runs.append((label, f"{label}.log", dict(variables, data=data, nx=copies[0],
                                                      ny=copies[1], nz=copies[2], steps=2000)))
        loops = engines.beside(ctx.lammps, deck, work, runs)
        ta, tb = loops["A"].cpu_seconds(), loops["B"].cpu_seconds()
        print(f"repeat {r + 1}: B/A CPU time {tb / ta:.3f} ({tb:.2f} s / {ta:.2f} s)",
              flush=True)
    # the instruction counts of part 1's method (callgrind, the base packing): the same on a
    # busy machine, where the CPU times above carry a few per cent from repeat to repeat
    sides = {label: ({"side": "stock"} if build == "stock"
                     else {"side": side, "plugin": build, "options": options[label]})
             for label, build in builds.items()}
    counts, steps = instructions(ctx, sides, data, work)
    (ta, pa), (tb, pb) = counts["A"], counts["B"]
    print(f"instructions ({steps} steps of the base packing): B/A {tb / ta:.4f} in all, "
          f"{pb / pa:.4f} in the pair style's compute", flush=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--parts", default="1,2,3,4")
    parser.add_argument("--repeats", type=int, default=None)
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--compare", nargs=2, metavar=("A", "B"),
                        help="instead of the parts: two plugin builds (A may be 'stock') on "
                        "one side of part 1's scene")
    parser.add_argument("--side", help="the side --compare runs: wet (default) or off")
    parser.add_argument("--options-a", default="", metavar="WORDS",
                        help="with --compare: words added to A's pair_style, e.g. 'friction "
                        "dry' for a build before the eq. 12 limit (whose default differs)")
    args = parser.parse_args()
    if args.side is not None and not args.compare:
        engines.fail("--side goes with --compare (the parts run every side)")
    if args.options_a and not args.compare:
        engines.fail("--options-a goes with --compare")
    args.side = args.side or "wet"
    if args.side not in ("wet", "off"):
        engines.fail(f"--side must be wet or off, not '{args.side}'")
    if args.compare:
        for label, build in zip("AB", args.compare):
            if not (build == "stock" and label == "A") and not os.path.isfile(build):
                engines.fail(f"--compare: {label} must be a plugin file"
                             f"{' or stock' if label == 'A' else ''}, not '{build}'")
    try:
        parts = [int(p) for p in args.parts.split(",")]
    except ValueError:
        engines.fail(f"--parts takes numbers from 1 to 4 separated by commas, not '{args.parts}'")
    if any(p not in PARTS for p in parts):
        engines.fail(f"--parts: unknown part in '{args.parts}' (allowed: 1, 2, 3, 4)")
    if args.repeats is not None and args.repeats < 1:
        engines.fail(f"--repeats must be >= 1, not {args.repeats}")
    for path in () if args.compare else (PLUGIN, CLI):
        if not os.path.isfile(path):
            engines.fail(f"no {path}: run scripts/configure.sh first")
    cache = os.environ.get("CAPBRIDGE_CACHE", os.path.join(os.path.expanduser("~"), ".cache",
                                                           "capbridge"))
    lammps, liggghts = engines.engines(cache)

    class Context:
        pass
    ctx = Context()
    ctx.quick = args.quick
    ctx.repeats = args.repeats or (2 if args.quick else 5)
    ctx.command = " ".join(["bench/run.sh"] + sys.argv[1:])
    ctx.lammps = (lammps["LAMMPS_MPIRUN"], [lammps["LAMMPS_BINARY"], "-nocite"])
    ctx.lammps_env = os.path.join(cache, "lammps-20250204", "lammps.env")
    ctx.liggghts = (liggghts["LIGGGHTS_MPIRUN"], [liggghts["LIGGGHTS_BINARY"]])
    os.makedirs(OUT, exist_ok=True)
    if args.compare:
        a, b = (build if build == "stock" else os.path.realpath(build)
                for build in args.compare)
        ctx.repeats = args.repeats or 4
        compare(ctx, a, b, args.side, args.options_a)
        return
    results = os.path.join(OUT, "quick") if ctx.quick else RESULTS
    os.makedirs(results, exist_ok=True)
    for part in parts:
        print(f"bench: part {part}", flush=True)
        text, summary = PARTS[part](ctx)
        with open(os.path.join(results, f"part{part}.md"), "w") as f:
            f.write(text + f"\n<!-- summary: {summary} -->\n")
        print(text, flush=True)
    if ctx.quick:
        print(f"bench: --quick: wrote {results}; bench/README.md left as it is")
        return
    for line in assemble():
        print("bench: " + line)
    print(f"bench: wrote {os.path.join(HERE, 'README.md')}")

if __name__ == "__main__":
    main()
