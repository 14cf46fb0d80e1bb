#!/usr/bin/env python3
"""A bridge held beyond the reach is ruptured there, its liquid released (Protocol 2).

Three spheres of radius 1 mm in a row, A - B - C, each touching the middle one, 1 nl of free
liquid each, every motion prescribed (fix move; B stays at rest). The reach of the run is
built at its start for the core's design volume of that liquid (cb_protocol_design_volume:
2 V0 here, with the rupture distance d_design). Bridges AB and BC form (1.5 V0 each: B's
liquid split between its two new bridges); C leaves, BC breaks; A leaves, AB breaks; B now
has 1.5 V0 of free liquid, A 0.75 V0. A comes back: the new bridge AB takes 2.25 V0, more
than the reach was built for, and A leaves again, slowly. Checked:
  - the bridge is ruptured at the first step its gap exceeds d_design (from `capbridge
    rupture`, the design volume from the core's rule), before its own rupture distance
    (2.25 V0)^(1/3), and its liquid is released as at any rupture: A and B get 1.125 V0;
  - liquid (free + bridges) conserved to 1e-12 relative at every step;
  - one warning, giving the number of such bridges (1);
  - the same on 2 ranks (A on one, B and C on the other), step for step.

usage: beyond_reach.py CAPBRIDGE LIGGGHTS_ENV [--workdir DIR]
"""
import argparse
import os
import re
import subprocess
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import liggghts_common as lc  # noqa: E402

R, V0, OVERLAP, SLOW = 1e-3, 1e-12, 1e-6, 1e-7   # SLOW: A's last speed, m per step
XB = 1.2e-3            # B; A on the other side of x = 0 (2 ranks: 2 1 1)
STEPS = 2300
DECK = """pair_style      gran model hooke/stiffness tangential history cohesion capillary &
                law richefeu liquid protocol2 start free tally on
pair_coeff      * *
timestep        1e-6
create_atoms    1 single {xa!r} 0 0 units box
create_atoms    1 single {xb!r} 0 0 units box
create_atoms    1 single {xc!r} 0 0 units box
set             atom * diameter {d!r} density 2500
group           a id 1
group           c id 3
# A: still to step 300, away at 1 um/step to 500, back to 700, still to 720, away slowly
# (min and max are not functions of a LIGGGHTS formula: clamp(x, 0, 200) with abs)
variable        s equal step
variable        out equal "(abs(v_s-300)-abs(v_s-500)+200)/2"
variable        back equal "(abs(v_s-500)-abs(v_s-700)+200)/2"
variable        da equal "-1e-6*(v_out-v_back)-{slow!r}*(v_s-720+abs(v_s-720))/2"
fix             movea a move variable v_da NULL NULL NULL NULL NULL
fix             movec c move linear 1.0 0 0
compute         free all reduce sum f_freeLiquid
compute         bridged all reduce sum f_bridgedLiquid
variable        xa equal x[1]
variable        xb equal x[2]
variable        fa equal f_freeLiquid[1]
variable        fb equal f_freeLiquid[2]
variable        fc equal f_freeLiquid[3]
thermo_style    custom step v_xa v_xb c_free c_bridged v_fa v_fb v_fc
thermo_modify   format float %.17g norm no
thermo          1
run             {steps}
"""


def rupture_distance(cli, volume):
    result = subprocess.run([cli, "rupture", "richefeu", "gamma", "0.0728", "--r1", repr(R),
                             "--r2", repr(R), "--volume", repr(volume)],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            universal_newlines=True)
    if result.returncode != 0:
        lc.fail("capbridge rupture failed: " + result.stderr)
    return float(result.stdout.split()[-1])


def run(env, workdir, ranks):
    deck = os.path.join(workdir, "in.beyond_%d" % ranks)
    with open(deck, "w") as f:
        f.write(lc.free_liquid_header(ranks, ("-0.01", "0.01"), "1e-4", "100", "0.3", V0) +
                DECK.format(xa=XB - 2 * R + OVERLAP, xb=XB,
                            xc=XB + 2 * R - OVERLAP, d=2 * R, slow=SLOW, steps=STEPS))
    code, log = lc.liggghts(env, deck, [], workdir, ranks=ranks, log="log.beyond_%d" % ranks)
    # the warning interrupts the thermo block: every row of 8 numbers
    rows = [line.split() for line in log.splitlines()]
    rows = [r for r in rows if len(r) == 8 and r[0].isdigit() and r[1] != "by"]
    if code != 0 or len(rows) != STEPS + 1:
        lc.fail("%d rank(s): %s" % (ranks, lc.error_line(log) or log[-1500:]))
    return [[float(v) for v in row] for row in rows], log


def check_run(rows, log, design, own, ranks):
    ok = True

    def check(good, text):
        nonlocal ok
        ok = ok and good
        print("%d rank(s): %s %s" % (ranks, text, "ok" if good else "FAIL"))

    total = 3 * V0
    worst = max(abs(r[3] + r[4] - total) for r in rows) / total
    check(worst <= 1e-12, "liquid (free + bridges) conserved: worst %.2e relative" % worst)
    # the bridge of A's return: formed by step 720 with 2.25 V0 (A and B: 0 free)
    at = {int(r[0]): r for r in rows}
    check(abs(at[720][4] - 2.25 * V0) <= 1e-12 * V0 and at[720][5] == 0.0 and
          at[720][6] == 0.0, "step 720: A and B hold one bridge of 2.25 V0 (%.6g m^3)" %
          at[720][4])
    broke = next((r for r in rows if r[0] > 720 and r[4] < 2.25 * V0 * (1 - 1e-9)), None)
    if broke is None:
        check(False, "the 2.25 V0 bridge broke")
        return ok
    gap = lambda r: (r[2] - r[1]) - 2 * R  # noqa: E731
    before = at[int(broke[0]) - 1]
    check(gap(before) <= design < gap(broke) < own,
          "ruptured at step %d, gap %.9e m: the first step beyond d_design %.9e m (the step "
          "before: %.9e m), before its own rupture distance %.9e m" % (
              broke[0], gap(broke), design, gap(before), own))
    check(broke[4] == 0.0 and abs(broke[5] - 1.125 * V0) <= 1e-12 * V0 and
          abs(broke[6] - 1.125 * V0) <= 1e-12 * V0 and abs(broke[7] - 0.75 * V0) <= 1e-12 * V0,
          "its liquid released to A and B, 1.125 V0 each (A %.6g, B %.6g, C %.6g m^3)" % (
              broke[5], broke[6], broke[7]))
    warnings = re.findall(r"WARNING: cohesion model capillary: (\d+) bridge\(s\) held beyond "
                          r"the reach", log)
    check(warnings == ["1"], "warned once with the count: %s" % warnings)
    return ok


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("capbridge")
    parser.add_argument("env")
    parser.add_argument("--workdir", default="")
    args = parser.parse_args()
    env, workdir = lc.start(args.env, args.workdir, "beyond_reach")
    cli = os.path.abspath(args.capbridge)
    # the design volume of the run: cb_protocol_design_volume's rule, 3 V0 over 3 equal
    # spheres (2 x 3 V0 / 3) or twice the largest free liquid (2 V0)
    design = rupture_distance(cli, 2 * V0)
    own = rupture_distance(cli, 2.25 * V0)
    ok = True
    results = {}
    for ranks in (1, 2):
        rows, log = run(env, workdir, ranks)
        results[ranks] = rows
        ok = check_run(rows, log, design, own, ranks) and ok
    same = all(abs(a - b) <= 1e-12 * max(abs(a), 1e-30)
               for ra, rb in zip(results[1], results[2]) for a, b in zip(ra, rb))
    ok = ok and same
    print("1 and 2 ranks: the same at every step %s" % ("ok" if same else "FAIL"))
    print("beyond the reach: %s (files in %s)" % ("PASS" if ok else "FAIL", workdir))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
