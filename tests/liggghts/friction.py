#!/usr/bin/env python3
"""The Coulomb limit on the contact force (Richefeu 2007 eq. 12 with eq. 1's f_n).

Two spheres of radius 1 mm overlap by 10 um (linear spring k_n, tangential history with
friction coefficient mu) and hold a richefeu bridge; sphere 2 slides along y until the
tangential spring is at the Coulomb limit. Eq. 12's limit mu (f_n - f_n^c), with
f_n = f_n^e + f_n^d + f_n^c (eq. 1), is mu f_contact: the sliding force must be mu times the
spring's repulsion, the capillary attraction (kappa R, eq. 10) not added. Read from the force
on sphere 1. The keyword that added it, capillary_friction (on by default until December
2026: mu (f_contact + f_c)), is refused with either value, naming the limit that applies.

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


def measure(env, extra, workdir, name):
    deck = os.path.join(workdir, "in.friction_" + name)
    with open(deck, "w") as f:
        f.write(lc.two_spheres_deck(KN, MU, 0.0728, "law richefeu " + extra, 1.99e-3, 2 * R) +
                DECK_RUN)
    return lc.liggghts(env, deck, [], workdir, log="log.friction_" + name)


def sliding(env, workdir):
    code, log = measure(env, "", workdir, "default")
    rows = lc.thermo_rows(log)
    if code != 0 or len(rows) != 2:
        lc.fail("friction: %s" % (lc.error_line(log) or log[-1500:]))
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
    kappa_r = 2 * math.pi * 0.0728 * R  # Richefeu eq. 10 in overlap: kappa R
    fn, fc, ft = sliding(env, workdir)
    limit = MU * fn
    ok = abs(ft - limit) <= 1e-9 * limit and abs(fc - kappa_r) <= 1e-9 * kappa_r
    print("default: f_contact %.6e N, f_c %.6e N (kappa R %.6e), sliding force %.9e N, "
          "expected mu f_contact %.9e N (mu (f_contact + f_c) would be %.9e N) %s" % (
              fn, fc, kappa_r, ft, limit, MU * (fn + fc), "ok" if ok else "FAIL"))
    for value in ("on", "off"):
        code, log = measure(env, "capillary_friction " + value, workdir, value)
        error = lc.error_line(log) or ""
        wanted = ["keyword 'capillary_friction' was removed", "mu |f_n^e + f_n^d|",
                  "eq. 12", "counting it twice", "delete the keyword"]
        good = code != 0 and all(w in error for w in wanted)
        ok = ok and good
        print("capillary_friction %s: %s %s" % (value, error or "(no error)",
                                               "ok" if good else "FAIL"))
    print("friction limit: %s (files in %s)" % ("PASS" if ok else "FAIL", workdir))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
