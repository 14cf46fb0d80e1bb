#!/usr/bin/env python3
"""LAMMPS and LIGGGHTS at parity on the core's rules (issue 17 item 2).

One input for both engines: law richefeu (gamma 0.0728 N/m, theta 0), grains of radii
0.8 to 1.2 mm (density 2500), k_n = 1 N/m, and
  fixed:     a bridge volume V = 1e-11 m^3 for every pair, grains apart, dt = 1e-3 s;
  protocol2: 1e-11 m^3 of liquid as free liquid in proportion to the grains' masses, one
             grain A (1.2 mm) overlapping three dry grains (0.8, 0.9, 1.0 mm) by 1 um: the
             three bridges form in one step;
  beyond:    Protocol 2 with vmax 1e-12 m^3 for the reach, grains of 1.2 and 0.8 mm
             touching (gap -0.5 um), all 1e-11 m^3 of liquid in their bridge, the small one
             pulled away at 1 um a step (fix move).
Each engine's numbers are checked against the core's, computed here independently (the
rupture distance from the capbridge CLI, the formulas of capbridge.h's "engines' checks"):
  the reach: d, the largest rupture distance of the design volume over the 5 x 5 grid of
    the radius range (Richefeu eq. 6: (1 + theta/2) V^(1/3) at every radius), and the reach
    1.05 d (CB_REACH_MARGIN).  LAMMPS: its neighbor cutoff minus the largest radius sum and
    the skin (fixed, protocol2 with the design volume max(2 V_total / N (r_max/r_min)^3,
    2 x the largest free liquid)).  Both engines (LIGGGHTS prints no reach): a bridge
    above the design volume ruptures at the first step its gap exceeds d (beyond);
  the time-step bound 0.1 pi sqrt(m_min / k), k the capillary stiffness bound, the largest
    |dF/dgap| over the corners of the radius range (at contact for Richefeu's law, from the
    CLI's curve): both engines print it in their warning (fixed);
  Protocol 2's k-way share: a grain with k new contacts in one step gives each 1/k of its
    free liquid, so A's bridge to grain j holds free_A / 3 + free_j (protocol2; LAMMPS:
    compute pair/local, LIGGGHTS: twice the partner's bridgedLiquid).

usage: parity.py CAPBRIDGE_CLI LAMMPS_ENV PLUGIN [LIGGGHTS_ENV] [--workdir DIR]
(without LIGGGHTS_ENV: the LAMMPS half alone)
"""
import argparse
import math
import os
import re
import subprocess
import sys
import tempfile

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "liggghts"))
import liggghts_common  # noqa: E402  (its check that LIGGGHTS holds this checkout's model)

R_SMALL, R_LARGE, RHO, GAMMA, VOLUME, SKIN = 0.8e-3, 1.2e-3, 2500.0, 0.0728, 1e-11, 1e-4
PARTNERS = (0.8e-3, 0.9e-3, 1.0e-3)    # the radii of A's three partners (x, y, z)
LIQUID, OVERLAP, MARGIN, DT = 1e-11, 1e-6, 0.05, 1e-3
FAILURES = []


def check(label, got, expected, tolerance):
    ok = got is not None and abs(got - expected) <= tolerance * abs(expected)
    print("%-58s %-22s core %-22r %s" % (label, got, expected, "ok" if ok else "FAIL"))
    if not ok:
        FAILURES.append(label)


def read_env(path):
    env = {}
    with open(path) as f:
        for line in f:
            line = line.strip()
            if line and not line.startswith("#") and "=" in line:
                key, value = line.split("=", 1)
                env[key] = value.strip('"')
    return env


# ---------------------------------------------------------------- the core's numbers

def cli_rupture(cli, r1, r2, volume):
    out = subprocess.run([cli, "force", "richefeu", "--r1", repr(r1), "--r2", repr(r2),
                          "--volume", repr(volume), "--gap", "0"],
                         capture_output=True, text=True, check=True).stdout
    return float(out.strip().splitlines()[-1].split(",")[3])


def cli_contact_stiffness(cli, r1, r2, volume):
    out = subprocess.run([cli, "curve", "richefeu", "--r1", repr(r1), "--r2", repr(r2),
                          "--volume", repr(volume), "--points", "2", "--to", "1e-6"],
                         capture_output=True, text=True, check=True).stdout
    return abs(float(out.strip().splitlines()[1].split(",")[2]))


def grid(lo, hi):
    return [hi if a == 4 else lo + (hi - lo) * a / 4 for a in range(5)]


def design_rupture(cli, volume):
    radii = grid(R_SMALL, R_LARGE)
    return max(cli_rupture(cli, r1, r2, volume) for r1 in radii for r2 in radii)


def timestep_bound(cli, volume):
    corners = (R_SMALL, R_LARGE)
    k = max(cli_contact_stiffness(cli, r1, r2, volume) for r1 in corners for r2 in corners)
    m = 4.0 / 3.0 * math.pi * R_SMALL ** 3 * RHO
    return 0.1 * math.pi * math.sqrt(m / k), k


def protocol2_free():
    """The grains' free liquid at the start, in proportion to their masses: A, its partners."""
    masses = [R_LARGE ** 3] + [r ** 3 for r in PARTNERS]
    return [LIQUID * m / sum(masses) for m in masses]


def protocol2_design_volume():
    """The larger of the Protocol 1 volume and twice the largest free liquid (A's, which
    does not decide here: 0.87 of the liquid against 1.69)."""
    protocol1 = 2.0 * LIQUID / 4 * (R_LARGE / R_SMALL) ** 3
    return max(protocol1, 2.0 * max(protocol2_free()))


# ---------------------------------------------------------------------------- LAMMPS

LAMMPS_DECK = """units           si
atom_style      sphere
atom_modify     map array
boundary        f f f
comm_modify     vel yes
region          box block -0.01 0.01 -0.01 0.01 -0.01 0.01 units box
create_box      1 box
create_atoms    1 single 0 0 0 units box
create_atoms    1 single {x[0]!r} 0 0 units box
create_atoms    1 single 0 {x[1]!r} 0 units box
create_atoms    1 single 0 0 {x[2]!r} units box
set             atom 1 diameter {d[0]!r}
set             atom 2 diameter {d[1]!r}
set             atom 3 diameter {d[2]!r}
set             atom 4 diameter {d[3]!r}
set             atom * density {rho!r}
plugin          load {plugin}
pair_style      gran/capillary
pair_coeff      * * 1 0.4 0 0.5 law richefeu gamma {gamma!r} {volume_keyword}
{fix}
neighbor        {skin!r} bin
timestep        {dt!r}
compute         pl all pair/local p3 p4 p5 p6
dump            bridges all local 1 {dump} c_pl[1] c_pl[2] c_pl[3] c_pl[4]
dump_modify     bridges format float %.17g
run             0
"""


def lammps_run(env, plugin, workdir, name, volume_keyword, fix, separated):
    x = [0.009 if separated else R_LARGE + r - OVERLAP for r in PARTNERS]
    deck = LAMMPS_DECK.format(
        x=x, d=[2 * r for r in (R_LARGE,) + PARTNERS], rho=RHO, plugin=plugin,
        gamma=GAMMA, volume_keyword=volume_keyword, fix=fix, skin=SKIN, dt=DT,
        dump=os.path.join(workdir, name + ".local"))
    path = os.path.join(workdir, "in." + name)
    with open(path, "w") as f:
        f.write(deck)
    log = os.path.join(workdir, name + ".log")
    done = subprocess.run([env["LAMMPS_BINARY"], "-in", path, "-log", log, "-nocite",
                           "-screen", "none"], capture_output=True, text=True)
    with open(log) as f:
        text = f.read()
    if done.returncode != 0:
        FAILURES.append("LAMMPS %s" % name)
        print("FAIL: LAMMPS %s: %s" % (name, re.findall(r"ERROR.*", text)[:1]))
        return text, {}
    volumes = {}    # the partner's radius: the volume of its bridge with A
    with open(os.path.join(workdir, name + ".local")) as f:
        lines = f.read().splitlines()
    start = max(k for k, line in enumerate(lines) if line.startswith("ITEM: ENTRIES"))
    for line in lines[start + 1:]:
        volume, bridge, r1, r2 = (float(x) for x in line.split())
        if bridge == 1.0:
            volumes[min(r1, r2)] = volume
    return text, volumes


def lammps_design_rupture(log):
    cutoff = float(re.search(r"master list distance cutoff = (\S+)", log).group(1))
    return (cutoff - SKIN - 2 * R_LARGE) / (1.0 + MARGIN)


def lammps_half(cli, env, plugin, workdir):
    log, _ = lammps_run(env, plugin, workdir, "lammps_fixed", "volume %r" % VOLUME, "", True)
    if log:
        check("LAMMPS fixed: design rupture distance of the reach",
              lammps_design_rupture(log), design_rupture(cli, VOLUME), 1e-6)
        limit, k = timestep_bound(cli, VOLUME)
        warning = re.search(r"time step \S+ s exceeds the limit (\S+) s .* capillary stiffness "
                            r"bound ([^)]+)\)", log)
        check("LAMMPS fixed: time-step bound", warning and float(warning.group(1)), limit, 1e-5)
        check("LAMMPS fixed: capillary stiffness bound", warning and float(warning.group(2)),
              k, 1e-5)
    log, volumes = lammps_run(env, plugin, workdir, "lammps_protocol2", "",
                              "fix liq all capillary/liquid protocol2 liquid %r start free"
                              % LIQUID, False)
    if log:
        check("LAMMPS protocol2: design rupture distance of the reach",
              lammps_design_rupture(log), design_rupture(cli, protocol2_design_volume()), 1e-6)
        free = protocol2_free()
        for k, r in enumerate(PARTNERS):
            check("LAMMPS protocol2: bridge A-%g mm, free_A / 3 + free_j" % (r * 1e3),
                  volumes.get(r), free[0] / 3 + free[k + 1], 1e-12)


# -------------------------------------------------------------------------- LIGGGHTS

LIGGGHTS_DECK = """units           si
atom_style      granular
atom_modify     map array
boundary        f f f
newton          off
communicate     single vel yes
region          box block -0.01 0.01 -0.01 0.01 -0.01 0.01 units box
create_box      1 box
neighbor        {skin!r} bin
neigh_modify    delay 0
fix m1 all property/global kn peratomtypepair 1 1
fix m2 all property/global kt peratomtypepair 1 0.4
fix m3 all property/global gamman peratomtypepair 1 0
fix m4 all property/global gammat peratomtypepair 1 0
fix m5 all property/global coefficientFriction peratomtypepair 1 0.5
fix m6 all property/global surfaceTension scalar {gamma!r}
fix m7 all property/global contactAngle peratomtype 0
fix m8 all property/global bridgeVolume peratomtypepair 1 {volume!r}
{free_fix}
pair_style      gran model hooke/stiffness tangential history cohesion capillary law richefeu {liquid} tally on
pair_coeff      * *
timestep        {dt!r}
{atoms}
set             atom * density {rho!r}
dump            grains all custom 1 {grains} id f_bridgedLiquid
dump_modify     grains format "%d %.17g"
run             1
{phase2}
"""


def liggghts_run(env, workdir, name, protocol2):
    atoms = ["create_atoms    1 single 0 0 0 units box"]
    for axis in range(3):
        where = ["0", "0", "0"]
        where[axis] = "0.009"
        atoms.append("create_atoms    1 single %s units box" % " ".join(where))
    atoms += ["set             atom %d diameter %r" % (k + 1, 2 * r)
              for k, r in enumerate((R_LARGE,) + PARTNERS)]
    phase2 = ""
    if protocol2:
        # the free liquid (settable after a run), then the partners into contact with A
        lines = ["set             atom %d property/atom freeLiquid %r" % (k + 1, v)
                 for k, v in enumerate(protocol2_free())]
        for axis, r in enumerate(PARTNERS):
            lines.append("set             atom %d %s %r" % (axis + 2, "xyz"[axis],
                                                               R_LARGE + r - OVERLAP))
        phase2 = "\n".join(lines + ["run             1"])
    deck = LIGGGHTS_DECK.format(
        skin=SKIN, gamma=GAMMA, volume=VOLUME, dt=DT, rho=RHO, atoms="\n".join(atoms),
        free_fix="fix freeLiquid all property/atom freeLiquid scalar yes yes no 0"
        if protocol2 else "", liquid="liquid protocol2 start free" if protocol2 else "",
        grains=os.path.join(workdir, name + ".grains"), phase2=phase2)
    path = os.path.join(workdir, "in." + name)
    with open(path, "w") as f:
        f.write(deck)
    log = os.path.join(workdir, name + ".log")
    done = subprocess.run([env["LIGGGHTS_BINARY"], "-in", path, "-log", log, "-screen",
                           "none"], capture_output=True, text=True, errors="replace")
    with open(log, errors="replace") as f:
        text = f.read()
    if done.returncode != 0:
        FAILURES.append("LIGGGHTS %s" % name)
        print("FAIL: LIGGGHTS %s: %s" % (name, re.findall(r"ERROR.*", text)[:1]))
        return None
    return text, last_block(os.path.join(workdir, name + ".grains"))


def last_block(path):
    """The rows of the last snapshot of a LIGGGHTS dump, as lists of numbers."""
    with open(path) as f:
        lines = f.read().splitlines()
    start = max(k for k, line in enumerate(lines) if line.startswith("ITEM: ATOMS"))
    return [[float(x) for x in line.split()] for line in lines[start + 1:] if line.strip()]


def liggghts_half(cli, env, workdir):
    run = liggghts_run(env, workdir, "liggghts_fixed", False)
    if run:
        log, _ = run
        limit, k = timestep_bound(cli, VOLUME)
        warning = re.search(r"time step \S+ s exceeds the limit (\S+) s .* k = ([^:]+): the "
                            r"capillary stiffness bound", log)
        check("LIGGGHTS fixed: time-step bound", warning and float(warning.group(1)), limit,
              1e-5)
        check("LIGGGHTS fixed: capillary stiffness bound", warning and float(warning.group(2)),
              k, 1e-5)
    run = liggghts_run(env, workdir, "liggghts_protocol2", True)
    if run:
        _, grains = run
        bridged = {int(row[0]): row[1] for row in grains}
        free = protocol2_free()
        for k, r in enumerate(PARTNERS):
            # bridgedLiquid: half of each bridge of the grain (the partner has one, with A)
            got = bridged.get(k + 2)
            check("LIGGGHTS protocol2: bridge A-%g mm, free_A / 3 + free_j" % (r * 1e3),
                  None if got is None else 2.0 * got, free[0] / 3 + free[k + 1], 1e-12)


# ------------------------------------- the reach, seen where a bridge above it ruptures

BEYOND_VMAX, BEYOND_START, BEYOND_STEPS = 1e-12, -0.5e-6, 150

BEYOND_LAMMPS = """units           si
atom_style      sphere
atom_modify     map array
boundary        f f f
comm_modify     vel yes
region          box block -0.01 0.01 -0.01 0.01 -0.01 0.01 units box
create_box      1 box
create_atoms    1 single 0 0 0 units box
create_atoms    1 single {xb!r} 0 0 units box
set             atom 1 diameter {da!r}
set             atom 2 diameter {db!r}
set             atom * density {rho!r}
plugin          load {plugin}
pair_style      gran/capillary
pair_coeff      * * 1 0.4 0 0.5 law richefeu gamma {gamma!r}
fix             liq all capillary/liquid protocol2 liquid {liquid!r} start free vmax {vmax!r}
neighbor        {skin!r} bin
timestep        1e-6
group           puller id 2
fix             pull puller move linear 1.0 0.0 0.0 units box
thermo_style    custom step f_liq[1]
thermo          1
run             {steps}
"""

BEYOND_LIGGGHTS = """units           si
atom_style      granular
atom_modify     map array
boundary        f f f
newton          off
communicate     single vel yes
region          box block -0.01 0.01 -0.01 0.01 -0.01 0.01 units box
create_box      1 box
neighbor        {skin!r} bin
neigh_modify    delay 0
fix m1 all property/global kn peratomtypepair 1 1
fix m2 all property/global kt peratomtypepair 1 0.4
fix m3 all property/global gamman peratomtypepair 1 0
fix m4 all property/global gammat peratomtypepair 1 0
fix m5 all property/global coefficientFriction peratomtypepair 1 0.5
fix m6 all property/global surfaceTension scalar {gamma!r}
fix m7 all property/global contactAngle peratomtype 0
fix freeLiquid all property/atom freeLiquid scalar yes yes no 0
pair_style      gran model hooke/stiffness tangential history cohesion capillary &
                law richefeu liquid protocol2 start free vmax {vmax!r} tally on
pair_coeff      * *
timestep        1e-6
create_atoms    1 single 0 0 0 units box
create_atoms    1 single 0.009 0 0 units box
set             atom 1 diameter {da!r}
set             atom 2 diameter {db!r}
set             atom * density {rho!r}
run             0
set             atom 1 property/atom freeLiquid {free_a!r}
set             atom 2 property/atom freeLiquid {free_b!r}
set             atom 2 x {xb!r}
group           puller id 2
fix             pull puller move linear 1.0 0.0 0.0
compute         count all reduce sum f_bridgeCount
thermo_style    custom step c_count
thermo          1
run             {steps}
"""


def beyond_expected(cli):
    """The core's step: the first whose gap (1 um a step from -0.5 um) exceeds the design
    rupture distance of vmax (cb_bridge_beyond_reach), before the bridge's own (of all
    the liquid, 1e-11 m^3)."""
    limit = design_rupture(cli, BEYOND_VMAX)
    return next(n for n in range(BEYOND_STEPS) if BEYOND_START + n * 1e-6 > limit)


def first_dry_step(log, column_ok):
    """The first thermo step with no bridge (rows of two numbers: step, bridges)."""
    for line in log.splitlines():
        words = line.split()
        if len(words) == 2 and words[0].isdigit():
            if column_ok(float(words[1])):
                return int(words[0])
    return None


def beyond_reach(cli, engine, env, plugin, workdir):
    masses = (R_LARGE ** 3, R_SMALL ** 3)
    values = dict(xb=R_LARGE + R_SMALL + BEYOND_START, da=2 * R_LARGE, db=2 * R_SMALL,
                  rho=RHO, plugin=plugin, gamma=GAMMA, liquid=LIQUID, vmax=BEYOND_VMAX,
                  skin=SKIN, steps=BEYOND_STEPS, free_a=LIQUID * masses[0] / sum(masses),
                  free_b=LIQUID * masses[1] / sum(masses))
    deck = (BEYOND_LAMMPS if engine == "LAMMPS" else BEYOND_LIGGGHTS).format(**values)
    name = "beyond_" + engine.lower()
    path = os.path.join(workdir, "in." + name)
    with open(path, "w") as f:
        f.write(deck)
    log = os.path.join(workdir, name + ".log")
    binary = env["LAMMPS_BINARY" if engine == "LAMMPS" else "LIGGGHTS_BINARY"]
    command = [binary, "-in", path, "-log", log, "-screen", "none"]
    subprocess.run(command + (["-nocite"] if engine == "LAMMPS" else []),
                   capture_output=True, text=True, errors="replace")
    with open(log, errors="replace") as f:
        text = f.read()
    got = first_dry_step(text, lambda bridges: bridges == 0.0)
    check("%s beyond: step the bridge above vmax ruptures" % engine, got,
          beyond_expected(cli), 0.0)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("cli")
    parser.add_argument("lammps_env")
    parser.add_argument("plugin")
    parser.add_argument("liggghts_env", nargs="?", default="")
    parser.add_argument("--workdir", default="")
    args = parser.parse_args()
    workdir = args.workdir or tempfile.mkdtemp(prefix="capbridge-parity.")
    os.makedirs(workdir, exist_ok=True)
    lammps_half(args.cli, read_env(args.lammps_env), args.plugin, workdir)
    beyond_reach(args.cli, "LAMMPS", read_env(args.lammps_env), args.plugin, workdir)
    if args.liggghts_env:
        liggghts_common.check_models_current(liggghts_common.read_env(args.liggghts_env))
        liggghts_half(args.cli, read_env(args.liggghts_env), workdir)
        beyond_reach(args.cli, "LIGGGHTS", read_env(args.liggghts_env), "", workdir)
    print("parity: %s (files in %s)" % ("FAIL: " + ", ".join(FAILURES) if FAILURES else "PASS",
                                        workdir))
    return 1 if FAILURES else 0


if __name__ == "__main__":
    sys.exit(main())
