#!/usr/bin/env python3
"""LAMMPS and LIGGGHTS remove the same bridges (issue 18 item 7, at parity).

One input for both engines: tests/liggghts/remove.py's scene (2000 spheres on a lattice
closer than the diameters, at rest, read from one data file), law richefeu (gamma 0.0728
N/m, theta 0), the same total liquid (LAMMPS: fix capillary/liquid protocol2 liquid V;
LIGGGHTS: V/N free liquid per particle), both starting with bridges (Protocol 1 at the
setup), once without and once with remove 0.5 and seed 7723 (LAMMPS: remove 0.5 7723;
LIGGGHTS: remove 0.5 remove_seed 7723).  Each engine dumps its pairs at step 0 (LAMMPS:
compute property/local patom1 patom2 beside compute pair/local; LIGGGHTS: compute
pair/gran/local id history).  Checks:
  - the bridged pairs (id, id) after the start are the same set in both engines;
  - the removed pairs (bridged without remove, dry with it) are the same set in both;
  - that set is the draw computed here, independently of both engines and of the core's
    code: the pairs whose splitmix64 hash of (seed, smaller id, larger id) (capbridge.h,
    cb_bridge_removal_chosen) maps below 0.5 in [0, 1);
  - LIGGGHTS marks removed pairs only (rupture -1: the pair of a removed bridge that still
    overlaps), and some;
  - LAMMPS's columns line up: the radii pair/local gives each pair are its two atoms'.
And the removal between runs, at the same state (the start's bridges, after a run 0):
LAMMPS's fix_modify liq remove 0.5 7723 and LIGGGHTS's fix property/global capillaryRemove
vector 0.5 7723, each followed by a second run 0 whose pairs are dumped: the removed pairs
are the same set in both engines, and the draw computed here.

usage: removal.py LAMMPS_ENV PLUGIN LIGGGHTS_ENV [--workdir DIR]
"""
import argparse
import os
import subprocess
import sys
import tempfile

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "liggghts"))
import liggghts_common  # noqa: E402
import remove as liggghts_remove  # noqa: E402  (the scene and the LIGGGHTS deck)

FRACTION, SEED = 0.5, 7723
MASK = (1 << 64) - 1

LAMMPS_DECK = """units           si
atom_style      sphere
atom_modify     map array
boundary        p p p
comm_modify     vel yes
read_data       {data}
plugin          load {plugin}
pair_style      gran/capillary
pair_coeff      * * 100 40 0.3 0.4 law richefeu gamma 0.0728
fix             liq all capillary/liquid protocol2 liquid {liquid!r} {remove}
neighbor        1e-4 bin
timestep        1e-5
fix             integrate all nve/sphere
compute         ids all property/local patom1 patom2
compute         pl all pair/local p4 p5 p6
dump            pairs all local 1 {dump} c_ids[1] c_ids[2] c_pl[1] c_pl[2] c_pl[3]
dump_modify     pairs format float %.17g
run             0
"""


def mix(z):
    """splitmix64's finaliser (Steele, Lea & Flood 2014)"""
    z = (z + 0x9e3779b97f4a7c15) & MASK
    z = ((z ^ (z >> 30)) * 0xbf58476d1ce4e5b9) & MASK
    z = ((z ^ (z >> 27)) * 0x94d049bb133111eb) & MASK
    return z ^ (z >> 31)


def drawn(pair):
    low, high = pair
    h = mix(mix(mix(SEED) ^ low) ^ high)
    return (h >> 11) * 2.0 ** -53 < FRACTION


def entries(path):
    """the rows of the last snapshot of a dump local"""
    with open(path) as f:
        lines = f.read().splitlines()
    start = max(k for k, line in enumerate(lines) if line.startswith("ITEM: ENTRIES"))
    return [[float(x) for x in line.split()] for line in lines[start + 1:] if line.strip()]


def key(a, b):
    return (min(int(a), int(b)), max(int(a), int(b)))


# after LAMMPS_DECK's run 0: the removal asked for between runs, the pairs dumped again
LAMMPS_LATER = """fix_modify      liq remove {fraction!r} {seed}
undump          pairs
dump            later all local 1 {dump} c_ids[1] c_ids[2] c_pl[1] c_pl[2] c_pl[3]
dump_modify     later format float %.17g
run             0
"""
# LIGGGHTS: in.remove up to its run, then a run 0, the request and a run 0 that dumps again
LIGGGHTS_LATER = """run             0
fix             capillaryRemove all property/global capillaryRemove vector {fraction!r} {seed}
undump          pairs
dump            later all local 100000 ${{local}} c_pairs[1] c_pairs[2] c_pairs[4] c_pairs[5] c_pairs[6]
run             0
"""


def lammps_pairs(env, plugin, workdir, name, data, liquid, remove, radii, failures, after=""):
    """the bridged pairs of LAMMPS at step 0 (after `after`, LAMMPS_DECK's commands that
    follow its run 0, if given)"""
    dump = os.path.join(workdir, name + ".local")
    deck = os.path.join(workdir, "in." + name)
    with open(deck, "w") as f:
        f.write(LAMMPS_DECK.format(data=data, plugin=plugin, liquid=liquid, remove=remove,
                                   dump=dump) + after.format(fraction=FRACTION, seed=SEED,
                                                             dump=dump))
    log = os.path.join(workdir, name + ".log")
    done = subprocess.run([env["LAMMPS_BINARY"], "-in", deck, "-log", log, "-nocite",
                           "-screen", "none"], capture_output=True, text=True)
    if done.returncode != 0:
        liggghts_common.fail("LAMMPS %s: %s" % (name, done.stdout[-1500:] + done.stderr))
    bridged, misaligned = set(), 0
    for a, b, bridge, r1, r2 in entries(dump):
        if sorted((r1, r2)) != sorted((radii[int(a)], radii[int(b)])):
            misaligned += 1
        if bridge == 1.0:
            bridged.add(key(a, b))
    if misaligned:
        failures.append("LAMMPS %s: %d pairs whose radii are not their atoms'" % (
            name, misaligned))
    return bridged


def liggghts_later(env, workdir, name, free):
    """LIGGGHTS's bridged pairs after the request's removal, at the second run 0's step 0"""
    with open(os.path.join(liggghts_common.HERE, "in.remove")) as f:
        text = f.read()
    deck = os.path.join(workdir, "in." + name)
    with open(deck, "w") as f:
        f.write(text[:text.index("run             ${steps}")] +
                LIGGGHTS_LATER.format(fraction=FRACTION, seed=SEED))
    code, log = liggghts_common.liggghts(
        env, deck, [("px", 1), ("data", os.path.join(workdir, "scene.data")),
                    ("liquid", "protocol2"), ("free", repr(free)), ("local", name + ".local")],
        workdir, log="log." + name)
    if code != 0 or "asked for by fix capillaryRemove" not in log:
        liggghts_common.fail("LIGGGHTS %s: %s" % (name, liggghts_common.error_line(log) or
                                                  "no removal line"))
    return set(key(a, b) for a, b, _v, active, _r in
               entries(os.path.join(workdir, name + ".local")) if active == 1.0)


def liggghts_pairs(env, workdir, name, liquid, free):
    """the bridged and the marked pairs of LIGGGHTS at step 0"""
    liggghts_remove.run(env, workdir, name, liquid, free)
    bridged, marked = set(), set()
    for a, b, _volume, active, rupture in entries(os.path.join(workdir, name + ".local")):
        if active == 1.0:
            bridged.add(key(a, b))
        elif rupture == -1.0:
            marked.add(key(a, b))
    return bridged, marked


def compare(label, first, second, failures, names=("LAMMPS", "LIGGGHTS")):
    same = first == second
    print("%-36s %s %5d  %s %5d  %s" % (
        label, names[0], len(first), names[1], len(second), "the same ok" if same else
        "FAIL: %d only in %s, %d only in %s" % (len(first - second), names[0],
                                                len(second - first), names[1])))
    if not same:
        failures.append(label)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("lammps_env")
    parser.add_argument("plugin")
    parser.add_argument("liggghts_env")
    parser.add_argument("--workdir", default="")
    args = parser.parse_args()
    workdir = args.workdir or tempfile.mkdtemp(prefix="capbridge-parity-removal.")
    os.makedirs(workdir, exist_ok=True)
    lammps_env = {}
    with open(args.lammps_env) as f:
        for line in f:
            if "=" in line and not line.startswith("#"):
                name, value = line.strip().split("=", 1)
                lammps_env[name] = value.strip('"')
    ligg_env, _ = liggghts_common.start(args.liggghts_env, workdir, "parity-removal")
    data = os.path.join(workdir, "scene.data")
    radii = liggghts_remove.scene_data(data)
    free = liggghts_remove.free_per_particle(radii)
    liquid = len(radii) * free
    failures = []
    lmp_all = lammps_pairs(lammps_env, args.plugin, workdir, "lammps-all", data, liquid, "",
                           radii, failures)
    lmp_kept = lammps_pairs(lammps_env, args.plugin, workdir, "lammps-remove", data, liquid,
                            "remove %r %d" % (FRACTION, SEED), radii, failures)
    lig_all, _ = liggghts_pairs(ligg_env, workdir, "liggghts-all", "protocol2", free)
    lig_kept, marked = liggghts_pairs(
        ligg_env, workdir, "liggghts-remove",
        "protocol2 remove %r remove_seed %d" % (FRACTION, SEED), free)
    compare("bridged pairs after the start", lmp_all, lig_all, failures)
    compare("removed pairs", lmp_all - lmp_kept, lig_all - lig_kept, failures)
    expected = set(p for p in lmp_all if drawn(p))
    compare("removed pairs, the draw computed here", lmp_all - lmp_kept, expected, failures,
            ("LAMMPS", "here"))
    lmp_later = lammps_pairs(lammps_env, args.plugin, workdir, "lammps-later", data, liquid,
                             "", radii, failures, LAMMPS_LATER)
    lig_later = liggghts_later(ligg_env, workdir, "liggghts-later", free)
    compare("removed between runs", lmp_all - lmp_later, lig_all - lig_later, failures)
    compare("removed between runs, the draw here", lmp_all - lmp_later, expected, failures,
            ("LAMMPS", "here"))
    marks_ok = marked and marked <= lig_all - lig_kept
    print("%-36s %d marked, all removed ones %s" % ("LIGGGHTS's marks", len(marked),
                                                    "ok" if marks_ok else "FAIL"))
    if not marks_ok:
        failures.append("marks")
    print("parity removal: %s (files in %s)" % (
        "FAIL: " + ", ".join(failures) if failures else "PASS", workdir))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
