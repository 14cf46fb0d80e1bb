#!/usr/bin/env python3
"""Protocol 3's receiver in LIGGGHTS against the core's, computed without LIGGGHTS.

Six spheres placed by hand, each pair that touches overlapping by 1 um, no gravity, none
integrated: B (ID 2, radius 1 mm) at the origin holds bridges to A (1, 0.8 mm) on its left,
to C (3) low on its right (75 degrees from the downward vertical) and to D (4) and E (5),
mirror images 30 degrees either side of the downward vertical (their contact points on B
at the same height, to the last bit); G (6) sits on top of A (C, D, E, G: 0.5 mm). Free
liquid A 2, B 4, C 1, D 3, E 0.5, G 1 nl: every bridge forms at the setup, each grain's
liquid split among its new bridges. A and G then move left together at 1 um per step until
A-B breaks. Richefeu 2007 §4.2 and the core's tie-break (capbridge.h, cb_protocol3_better):
B's share goes to its lowest contact on its lower hemisphere, D or E, of equal heights the
smaller partner ID: D; A's only other bridge (to G) is on its upper hemisphere, so A's share
is A's free liquid. The reference is protocol3_reference.c (the core's functions over the
dumped spheres, formation to rupture); checked at the step A-B breaks:
  - D's and E's positions mirror images to the last bit (a tie), the reference's receivers
    B: D and A: none;
  - every bridge's volume and every sphere's free liquid within 1e-12 relative of the
    reference's (1e-12 of the total for the free liquid), and only B-D grown;
  - the step after, each sphere's half of its bridges (f_bridgedLiquid, which each rank
    sums from its own copies of the bridges of its spheres) within 1e-12 of the total;
  - the liquid (free + bridges) of the steps around the rupture, 11.5 nl to 1e-12.
On 1 rank and on 2 (the boundary at x = -0.5 mm: A, D and G on one rank, B, C and E on the
other; the broken bridge and B's receiver B-D are held by both ranks, D a ghost of B's rank).

usage: protocol3_receiver.py REFERENCE_PROGRAM LIGGGHTS_ENV [--workdir DIR]
"""
import argparse
import math
import os
import subprocess
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import liggghts_common as lc  # noqa: E402

TOLERANCE = 1e-12
V0, OVERLAP, STEPS = 1e-12, 1e-6, 300
RB, RA, RS = 1.0e-3, 0.8e-3, 0.5e-3  # B, A, the small ones
# (name, radius, free liquid in V0), in ID order
SPHERES = [("A", RA, 2.0), ("B", RB, 4.0), ("C", RS, 1.0), ("D", RS, 3.0), ("E", RS, 0.5),
           ("G", RS, 1.0)]
TOTAL = sum(f for _, _, f in SPHERES) * V0
EXPECTED_RECEIVERS = {1: 0, 2: 4}  # A: none, B: D (the smaller ID of D and E)


def positions():
    """The spheres' centres: B at the origin, the others touching it (or A) by OVERLAP."""
    def around(radius, degrees):  # touching B, `degrees` from the downward vertical, +x side
        d = RB + radius - OVERLAP
        return (d * math.sin(math.radians(degrees)), 0.0, -d * math.cos(math.radians(degrees)))
    xa = -(RA + RB - OVERLAP)
    dx, _, dz = around(RS, 30.0)
    return [(xa, 0.0, 0.0), (0.0, 0.0, 0.0), around(RS, 75.0), (-dx, 0.0, dz), (dx, 0.0, dz),
            (xa, 0.0, RA + RS - OVERLAP)]


def deck(ranks):
    atoms = "".join("create_atoms    1 single %r %r %r units box\n" % p for p in positions())
    radii = "".join("set             atom %d diameter %r density 2500\n" % (k + 1, 2 * s[1])
                    for k, s in enumerate(SPHERES))
    free = "".join("set             atom %d property/atom freeLiquid %r\n" % (k + 1, s[2] * V0)
                   for k, s in enumerate(SPHERES))
    return lc.free_liquid_header(ranks, ("-0.0105", "0.0095"), "2e-4", "100", "0.3", 0) + """{atoms}{radii}timestep        1e-6
# the per-atom free liquid can be set only after a run: a dry one first
pair_style      gran model hooke/stiffness tangential history
pair_coeff      * *
run             0
{free}pair_style      gran model hooke/stiffness tangential history cohesion capillary &
                law richefeu liquid protocol3 start free tally on
pair_coeff      * *
group           moving id 1 6
fix             move moving move linear -1.0 0 0
compute         pairs all pair/gran/local id history
dump            pairs all local 1 pairs.dump c_pairs[1] c_pairs[2] c_pairs[4] c_pairs[5]
dump_modify     pairs format "%.17g %.17g %.17g %.17g"
dump            atoms all custom 1 atoms.dump id radius x y z f_freeLiquid f_bridgedLiquid
dump_modify     atoms format "%d %.17g %.17g %.17g %.17g %.17g %.17g" sort id
compute         free all reduce sum f_freeLiquid
compute         bridged all reduce sum f_bridgedLiquid
thermo_style    custom step c_free c_bridged
thermo_modify   format float %.17g norm no
thermo          1
run             {steps}
""".format(atoms=atoms, radii=radii, free=free, steps=STEPS)


def snapshots(path):
    """{step: [rows]} of a dump with one block per step."""
    result, step, rows, lines = {}, None, None, open(path).read().splitlines()
    k = 0
    while k < len(lines):
        if lines[k].startswith("ITEM: TIMESTEP"):
            step = int(lines[k + 1])
            k += 2
            continue
        if lines[k].startswith("ITEM: ATOMS") or lines[k].startswith("ITEM: ENTRIES"):
            rows = result.setdefault(step, [])
            k += 1
            while k < len(lines) and not lines[k].startswith("ITEM:"):
                if lines[k].strip():
                    rows.append(lines[k].split())
                k += 1
            continue
        k += 1
    return result


def bridges_of(rows):
    """{(low ID, high ID): [volume of each copy]} of the active bridges in a pairs block."""
    held = {}
    for r in rows:
        if float(r[3]) != 0.0:
            ids = tuple(sorted((int(float(r[0])), int(float(r[1])))))
            held.setdefault(ids, []).append(float(r[2]))
    return held


def run(env, workdir, ranks):
    sub = os.path.join(workdir, "ranks%d" % ranks)
    os.makedirs(sub, exist_ok=True)
    path = os.path.join(sub, "in.protocol3_receiver")
    with open(path, "w") as f:
        f.write(deck(ranks))
    code, log = lc.liggghts(env, path, [], sub, ranks=ranks)
    if code != 0:
        lc.fail("%d rank(s): %s" % (ranks, lc.error_line(log) or log[-2000:]))
    pairs = snapshots(os.path.join(sub, "pairs.dump"))
    atoms = snapshots(os.path.join(sub, "atoms.dump"))
    totals = {int(r[0]): float(r[1]) + float(r[2])
              for r in lc.thermo_rows(log) if len(r) == 3}
    return pairs, atoms, totals


def reference(program, start, now):
    """The reference over the spheres at the setup (with the free liquid they were given:
    the dump at step 0 shows it taken by the bridges) and at the rupture step."""
    text = "".join(" ".join(a[:5] + [repr(s[2] * V0)]) + "\n" for a, s in zip(start, SPHERES))
    text += "---\n"
    text += "".join(" ".join(a[:5]) + "\n" for a in now)
    result = subprocess.run([program, "1", "2"], input=text, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, universal_newlines=True)
    if result.returncode != 0:
        lc.fail("protocol3_reference: " + result.stderr)
    receivers, bridges, free = {}, {}, {}
    for line in result.stdout.splitlines():
        word, *values = line.split()
        if word == "receiver":
            receivers[int(values[0])] = int(values[1])
        elif word == "bridge":
            bridges[(int(values[0]), int(values[1]))] = float(values[2])
        elif word == "free":
            free[int(values[0])] = float(values[1])
    return receivers, bridges, free


def check_run(program, ranks, pairs, atoms, totals):
    ok = True

    def check(good, text):
        nonlocal ok
        ok = ok and good
        print("%d rank(s): %s %s" % (ranks, text, "ok" if good else "FAIL"))

    steps = sorted(pairs)
    broke = next((s for s in steps if (1, 2) not in bridges_of(pairs[s])), None)
    if broke is None or broke == 0:
        check(False, "A-B breaks after the setup (at step %s)" % broke)
        return ok
    d, e = (atoms[0][k] for k in (3, 4))
    check(d[2] == "-" + e[2] and d[3:5] == e[3:5],
          "D and E mirror images to the last bit (x %s and %s, z %s): a tie" % (d[2], e[2], d[4]))
    receivers, expected, free = reference(program, atoms[0], atoms[broke])
    check(receivers == EXPECTED_RECEIVERS,
          "the reference's receivers %s (ID: partner ID, 0: free liquid) are Richefeu's and "
          "the tie-break's %s" % (receivers, EXPECTED_RECEIVERS))
    held = bridges_of(pairs[broke])
    before = bridges_of(pairs[broke - 1])
    worst = max([abs(v - expected[p]) / expected[p] for p in expected for v in held.get(p, [])]
                or [math.inf])
    check(set(held) == set(expected) and worst <= TOLERANCE,
          "step %d, A-B broken: bridges %s, each within %.2e of the reference" % (
              broke, sorted(held), worst))
    grew = sorted(p for p in held if held[p][0] > before[p][0])
    check(grew == [(2, 4)], "the bridge that received liquid: %s (B-D from %.6g to %.6g m^3)"
          % (grew, before[(2, 4)][0], held[(2, 4)][0]))
    got = {int(a[0]): float(a[5]) for a in atoms[broke]}
    worst = max(abs(got[i] - free[i]) for i in free) / TOTAL
    check(set(got) == set(free) and worst <= TOLERANCE,
          "free liquid (A %.6g m^3, reference %.6g) within %.2e of the reference" % (
              got[1], free[1], worst))
    # each owner's half of its bridges (tally), from its own rank's copy of each bridge
    halves = {int(a[0]): float(a[6]) for a in atoms[broke + 1]}
    worst = max(abs(halves[i] - 0.5 * sum(v for p, v in expected.items() if i in p))
                for i in halves) / TOTAL
    check(worst <= TOLERANCE, "step %d: each sphere's half of its bridges (f_bridgedLiquid, "
          "its owner's copies) within %.2e of the reference" % (broke + 1, worst))
    worst = max(abs(totals[s] - TOTAL) for s in (broke - 1, broke, broke + 1)) / TOTAL
    check(worst <= TOLERANCE, "liquid conserved across the rupture: %.2e relative" % worst)
    return ok


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("program")
    parser.add_argument("env")
    parser.add_argument("--workdir", default="")
    args = parser.parse_args()
    env, workdir = lc.start(args.env, args.workdir, "protocol3_receiver")
    ok = True
    for ranks in (1, 2):
        pairs, atoms, totals = run(env, workdir, ranks)
        ok = check_run(os.path.abspath(args.program), ranks, pairs, atoms, totals) and ok
    print("Protocol 3's receiver against the core: %s (files in %s)" % (
        "PASS" if ok else "FAIL", workdir))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
