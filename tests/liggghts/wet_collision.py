#!/usr/bin/env python3
"""A wet head-on collision in LIGGGHTS (`cohesion capillary ... viscous on`): its restitution
against the Stokes number, asserted against the lubrication impulse (issue 19, point 1).

tests/liggghts/in.wet_collision: equal glass spheres of radius 1 mm, v0 1 m/s, bridge volume
1e-11 m^3, viscousMinGap 1 um, k_n 1e4 N/m, gamman 2 alpha_n sqrt(k_n / m*) with alpha_n 0.1
(the damping of tests/lammps/in.wet_collision's dashpot both), over nine viscosities.  The bridge
forms at contact, so the viscous force acts while the spheres separate: its impulse over
m* v0 takes L / St off the restitution without viscosity, St = m* v0 / (6 pi eta R*^2),
L = chi(min_gap) + the integral of chi(s)/s ds from min_gap to the rupture distance, chi Pitois'
volume factor (computed here by Simpson's rule, independently of the core).  The published
trend (Barnocky & Davis 1988, Gollwitzer et al. 2012): no rebound below a critical St of order
10, the dry value approached above.  Asserted, as tests/lammps/test_viscous.sh does for LAMMPS:
stuck (bridge kept, e within 0.02 of 0) below St 6, a rebound with the bridge broken above; e
rising with St; e within 1 % of the run without viscosity at St > 1000; (e_dry - e) St within
5 % of L for 10 < St < 200; and the run without viscosity within 2 % below the linear
spring-dashpot's exp(-pi alpha / sqrt(1 - alpha^2)) (the bridge's attraction takes a little).

usage: wet_collision.py LIGGGHTS_ENV [--workdir DIR]
"""
import math
import os
import re
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import liggghts_common as lc  # noqa: E402

# the collision's parameters and the lubrication impulse: the wet-collision study's, one home
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__)))), "inputs", "wet_collision"))
from study import (ALPHA, DENSITY, KN, MIN_GAP, MSTAR, RADIUS, RSTAR, V0,  # noqa: E402,F401
                   VOLUME, impulse_integral)

VISCOSITIES = (0.0, 1e-3, 1e-2, 3e-2, 0.06, 0.1, 0.15, 0.2, 0.3)


def collide(env, workdir, eta):
    gamman = 2.0 * ALPHA * math.sqrt(KN / MSTAR)
    variables = [("v0", V0), ("kn", KN), ("gamman", repr(gamman)), ("volume", VOLUME),
                 ("eta", eta), ("min_gap", MIN_GAP), ("nsteps", 20000)]
    code, log = lc.liggghts(env, os.path.join(lc.HERE, "in.wet_collision"), variables, workdir,
                            log="log.eta%g" % eta)
    found = re.search(r"^RESTITUTION (\S+) BRIDGES (\S+) GAP", log, re.M)
    if code != 0 or not found:
        lc.fail("in.wet_collision (eta %g): %s" % (eta, lc.error_line(log) or log[-1500:]))
    return float(found.group(1)), float(found.group(2))


def main():
    args = lc.argument_parser(__doc__).parse_args()
    env, workdir = lc.start(args.env, args.workdir, "wet_collision")
    runs = [collide(env, workdir, eta) for eta in VISCOSITIES]
    L = impulse_integral()
    e_dry = runs[0][0]
    e_spring = math.exp(-math.pi * ALPHA / math.sqrt(1.0 - ALPHA * ALPHA))
    bad = []
    if not (0.98 * e_spring <= e_dry < e_spring):
        bad.append("without viscosity e %.4f not within 2 %% below the spring-dashpot's %.4f"
                   % (e_dry, e_spring))
    print("wet collision: L = %.4g; without viscosity e %.4f (spring-dashpot alone %.4f)"
          % (L, e_dry, e_spring))
    previous = None
    for eta, (e, bridges) in zip(VISCOSITIES[1:], runs[1:]):
        st = MSTAR * V0 / (6.0 * math.pi * eta * RSTAR ** 2)
        print("wet collision: St %7.1f  e %.4f  bridges %g" % (st, e, bridges))
        if st < 6.0:
            if not (bridges == 1 and abs(e) < 0.02):
                bad.append("St %.1f: not stuck (e %.4f, bridges %g)" % (st, e, bridges))
        elif not (bridges == 0 and e > 0.0):
            bad.append("St %.1f: no rebound (e %.4f, bridges %g)" % (st, e, bridges))
        if previous is not None and st >= 6.0 and not e < previous:
            bad.append("St %.1f: e %.4f not below %.4f at the larger St" % (st, e, previous))
        if st > 1000 and abs(e - e_dry) > 0.01 * e_dry:
            bad.append("St %.1f: e %.4f not within 1 %% of %.4f" % (st, e, e_dry))
        if 10 < st < 200 and abs((e_dry - e) * st - L) > 0.05 * L:
            bad.append("St %.1f: (e_dry - e) St = %.4g, L = %.4g" % (st, (e_dry - e) * st, L))
        previous = e
    for line in bad:
        print("FAIL: " + line)
    print("wet collision: %s (files in %s)" % ("FAIL" if bad else "PASS", workdir))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
