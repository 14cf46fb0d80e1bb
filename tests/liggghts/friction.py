#!/usr/bin/env python3
"""The Coulomb limit with and without the capillary attraction (Richefeu 2007 eq. 12).

Two spheres of radius 1 mm overlap by 10 um (linear spring k_n, tangential history with
friction coefficient mu); sphere 2 slides along y until the tangential spring is at the
Coulomb limit. With `capillary_friction on` (the default) the sliding force must be
mu (f_n + f_c) (f_n the spring's repulsion, f_c the capillary attraction); with
`capillary_friction off` it must be mu f_n. Both are read from the force on sphere 1.

usage: friction.py LIGGGHTS_ENV [--workdir DIR]
"""
import math
import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import liggghts_common as lc  # noqa: E402

KN, MU, R = 1000.0, 0.5, 1e-3
DECK_RUN = """group           sphere2 id 2
fix             slide sphere2 move linear 0 0.01 0
variable        x1 equal x[1]
variable        y1 equal y[1]
variable        x2 equal x[2]
variable        y2 equal y[2]
variable        fx1 equal fx[1]
variable        fy1 equal fy[1]
thermo_style    custom step v_x1 v_y1 v_x2 v_y2 v_fx1 v_fy1
thermo_modify   format float %.17g
thermo          200
run             200
"""


def measure(env, switch, workdir):
    deck = os.path.join(workdir, "in.friction_" + switch)
    with open(deck, "w") as f:
        f.write(lc.two_spheres_deck(KN, MU, 0.0728, "law richefeu capillary_friction " + switch,
                                    1.99e-3, 2 * R) + DECK_RUN)
    code, log = lc.liggghts(env, deck, [], workdir, log="log.friction_" + switch)
    rows = lc.thermo_rows(log)
    if code != 0 or len(rows) != 2:
        lc.fail("capillary_friction %s: %s" % (switch, lc.error_line(log) or log[-1500:]))
    x1, y1, x2, y2, fx, fy = [float(v) for v in rows[-1][1:7]]
    r = math.hypot(x2 - x1, y2 - y1)
    ux, uy = (x2 - x1) / r, (y2 - y1) / r
    repulsion = KN * (2 * R - r)
    along = fx * ux + fy * uy             # = f_c - repulsion
    capillary = along + repulsion
    tangential = math.hypot(fx - along * ux, fy - along * uy)
    return repulsion, capillary, tangential


def main():
    parser = lc.argument_parser(__doc__)
    args = parser.parse_args()
    env, workdir = lc.start(args.env, args.workdir, "friction")
    ok = True
    kappa_r = 2 * math.pi * 0.0728 * R  # Richefeu eq. 10 in overlap: kappa R
    for switch in ("on", "off"):
        fn, fc, ft = measure(env, switch, workdir)
        limit = MU * (fn + fc) if switch == "on" else MU * fn
        good = abs(ft - limit) <= 1e-9 * limit and abs(fc - kappa_r) <= 1e-9 * kappa_r
        ok = ok and good
        print("capillary_friction %-3s: f_n %.6e N, f_c %.6e N (kappa R %.6e), sliding force "
              "%.9e N, expected %.9e N (%s) %s" % (
                  switch, fn, fc, kappa_r, ft, limit,
                  "mu (f_n + f_c)" if switch == "on" else "mu f_n", "ok" if good else "FAIL"))
    print("friction limit: %s (files in %s)" % ("PASS" if ok else "FAIL", workdir))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
