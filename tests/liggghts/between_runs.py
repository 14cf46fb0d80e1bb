#!/usr/bin/env python3
"""A bridge's force follows the coefficients changed between two runs.

A bridge keeps its force at contact, derived from its volume, the radii and the law when it
forms (cb_bridge); the model derives it again in the setup pass of every run. Two spheres
of radius 1 mm overlap by 10 um (linear spring k_n, no motion: `run 0`); the surface tension
is 0.0728 N/m in the first run and 0.05 N/m in the second (fix property/global redefined).
In both, the capillary force read from the force on sphere 1 must be Richefeu's value in
overlap, 2 pi gamma R (eq. 10 at contact), for that run's gamma.

usage: between_runs.py LIGGGHTS_ENV [--workdir DIR]
"""
import math
import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import liggghts_common as lc  # noqa: E402

KN, R, OVERLAP = 1000.0, 1e-3, 1e-5
GAMMAS = (0.0728, 0.05)
DECK_RUNS = """variable        x1 equal x[1]
variable        x2 equal x[2]
variable        fx1 equal fx[1]
thermo_style    custom step v_x1 v_x2 v_fx1
thermo_modify   format float %.17g
run             0
fix m6 all property/global surfaceTension scalar {gamma2!r}
run             0
"""


def main():
    parser = lc.argument_parser(__doc__)
    args = parser.parse_args()
    env, workdir = lc.start(args.env, args.workdir, "between-runs")
    deck = os.path.join(workdir, "in.between_runs")
    with open(deck, "w") as f:
        f.write(lc.two_spheres_deck(KN, 0.5, GAMMAS[0], "law richefeu", 2 * R - OVERLAP, 2 * R) +
                DECK_RUNS.format(gamma2=GAMMAS[1]))
    code, log = lc.liggghts(env, deck, [], workdir, log="log.between_runs")
    rows = lc.thermo_rows(log)
    if code != 0 or len(rows) != 2:
        lc.fail("between runs: %s" % (lc.error_line(log) or log[-1500:]))
    ok = True
    for gamma, row in zip(GAMMAS, rows):
        x1, x2, fx1 = [float(v) for v in row[1:4]]
        capillary = fx1 + KN * (2 * R - (x2 - x1))  # f on sphere 1 = f_c - repulsion
        expected = 2 * math.pi * gamma * R
        good = abs(capillary - expected) <= 1e-9 * expected
        ok = ok and good
        print("gamma %.4g N/m: capillary force %.12e N, 2 pi gamma R %.12e N %s" % (
            gamma, capillary, expected, "ok" if good else "FAIL"))
    print("between runs: %s (files in %s)" % ("PASS" if ok else "FAIL", workdir))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
