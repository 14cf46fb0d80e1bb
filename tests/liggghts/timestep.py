#!/usr/bin/env python3
"""The time-step check against the capillary stiffness (the LAMMPS binding's rule).

Two spheres of radius R = 1 mm (density 2500), law richefeu, theta = 0, a bridge of
V = 1e-11 m^3: with liquid fixed (bridgeVolume, spheres apart), and under Protocol 2
(5e-12 m^3 of free liquid each, spheres overlapping by 1 um: the bridge forms in the setup
pass).  Richefeu's force F = 2 pi gamma R exp(-gap/lambda), lambda = c sqrt(V/R) at equal
radii (eqs. 4-11, c = 0.9), is steepest at contact: k = 2 pi gamma R / lambda, so the limit
is 0.1 pi sqrt(m/k) with m = 4/3 pi R^3 rho.  A time step 1 % above the limit must warn
once, naming the limit, m and k (6 digits, tolerance 1e-5); 1 % below it must not.

usage: timestep.py LIGGGHTS_ENV [--workdir DIR]
"""
import math
import os
import re
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import liggghts_common as lc  # noqa: E402

R, RHO, GAMMA, VOLUME, C = 1e-3, 2500.0, 0.0728, 1e-11, 0.9
WARNING = (r"WARNING: cohesion model capillary: time step (\S+) s exceeds the limit (\S+) s "
           r"= 10% of pi sqrt\(m/k\) for types 1 1 \(smallest mass m = (\S+), k = (\S+):")
RUN = """fix             integrate all nve/sphere
run             0
run             0
"""


def expected():
    mass = 4.0 / 3.0 * math.pi * R ** 3 * RHO
    stiffness = 2 * math.pi * GAMMA * R / (C * math.sqrt(VOLUME / R))
    return 0.1 * math.pi * math.sqrt(mass / stiffness), mass, stiffness


def deck(workdir, name, liquid, dt):
    base = lc.two_spheres_deck(100.0, 0.5, GAMMA, "law richefeu" + (
        " liquid protocol2 start free" if liquid == "protocol2" else ""),
        2 * R - 1e-6 if liquid == "protocol2" else 3 * R, 2 * R)
    if liquid == "protocol2":
        base = base.replace("pair_style", "fix freeLiquid all property/atom freeLiquid scalar "
                            "yes yes no %r\npair_style" % (VOLUME / 2), 1)
    base = base.replace("timestep        1e-6", "timestep        %r" % dt)
    path = os.path.join(workdir, "in." + name)
    with open(path, "w") as f:
        f.write(base + RUN)
    return path


def close(a, b):
    return abs(a - b) <= 1e-5 * abs(b)


def main():
    parser = lc.argument_parser(__doc__)
    args = parser.parse_args()
    env, workdir = lc.start(args.env, args.workdir, "timestep")
    limit, mass, stiffness = expected()
    ok = True
    for liquid in ("fixed", "protocol2"):
        for factor in (1.01, 0.99):
            name = "%s.%s" % (liquid, "above" if factor > 1 else "below")
            path = deck(workdir, name, liquid, factor * limit)
            code, log = lc.liggghts(env, path, [], workdir, log="log." + name)
            if code != 0:
                lc.fail("%s: %s" % (name, lc.error_line(log) or log[-1500:]))
            found = re.findall(WARNING, log)
            if factor > 1:
                good = len(found) == 1 and all(close(float(a), b) for a, b in zip(
                    found[0], (factor * limit, limit, mass, stiffness)))
            else:
                good = not found
            ok = ok and good
            print("liquid %s, dt = %.2f x limit: %s (limit %.6g s, m %.6g kg, k %.6g N/m)\n"
                  "    %s" % (liquid, factor, "ok" if good else "FAIL", limit, mass,
                             stiffness, "; ".join(", ".join(w) for w in found) or
                             "no warning"))
    print("time step: %s (files in %s)" % ("PASS" if ok else "FAIL", workdir))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
