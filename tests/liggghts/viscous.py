#!/usr/bin/env python3
"""The bridge's viscous force in LIGGGHTS (`cohesion capillary ... viscous on`) against the core.

tests/liggghts/in.viscous drives two spheres of atom types 1 and 2 apart along x and past
each other along y, both spinning about z, from an overlap through the gaps of the lubrication
clamp (viscousMinGap) to fifty times it. At every step with the pair apart and its bridge
held, the force and torque on sphere 1 must be the capillary force plus the viscous one, with
the capillary force and both damping coefficients from `capbridge force ... viscosity ETA
min_gap S` (the C reference CLI): F_1 = -F_cap e_n - c_n (v_r . e_n) e_n - c_t v_t, with
e_n = (x_1 - x_2)/|x_1 - x_2|, v_r = v_1 - v_2, v_t = v_r - (v_r . e_n) e_n
+ e_n x (r_1 w_1 + r_2 w_2), and the torque -r_1 e_n x (-c_t v_t). Relative tolerance 1e-9;
1 rank and one sphere per rank. With liquidViscosity 0 the same run has the capillary force
alone. The time-step warning of the viscous force (10 % of pi m/c) is given for types 1 2
with the viscosity and not without.

usage: viscous.py CAPBRIDGE LIGGGHTS_ENV [--workdir DIR]
"""
import argparse
import math
import os
import subprocess
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import liggghts_common as lc  # noqa: E402

TOLERANCE = 1e-9
GAMMA = "0.0728"
RUN = {"r1": 0.5e-3, "r2": 0.8e-3, "volume": 2e-11, "min_gap": 2e-7, "vx": 0.05,
       "vy": 0.02, "w1": 60.0, "w2": -10.0, "dt": 2e-6, "nsteps": 200}
WARNING = "of the bridges' viscous force for types 1 2"


def reference(cli, viscosity, gap):
    """(F_cap, c_n, c_t) of the type pair 1 2's law at this gap, from the reference CLI."""
    command = [cli, "force", "richefeu", "gamma", GAMMA]
    if viscosity > 0.0:
        command += ["viscosity", repr(viscosity), "min_gap", repr(RUN["min_gap"])]
    command += ["--r1", repr(RUN["r1"]), "--r2", repr(RUN["r2"]),
                "--volume", repr(RUN["volume"]), "--gap", repr(gap)]
    result = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            universal_newlines=True)
    lines = result.stdout.split()
    if result.returncode != 0 or len(lines) != 2:
        lc.fail("%s failed: %s" % (" ".join(command), result.stderr))
    values = [float(v) for v in lines[1].split(",")]
    return values[1], (values[4] if viscosity > 0.0 else 0.0), \
        (values[5] if viscosity > 0.0 else 0.0)


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def expected(cli, viscosity, x1, y1, x2, y2, w1, w2):
    """(gap, fx, fy, torque_z) on sphere 1 from the core's F_cap, c_n and c_t."""
    d = [x1 - x2, y1 - y2, 0.0]
    r = math.sqrt(d[0] ** 2 + d[1] ** 2)
    gap = r - RUN["r1"] - RUN["r2"]
    en = [d[0] / r, d[1] / r, 0.0]
    vr = [-RUN["vx"], -RUN["vy"], 0.0]  # sphere 1 held, sphere 2 driven
    rate = vr[0] * en[0] + vr[1] * en[1]
    spin = cross(en, [0.0, 0.0, RUN["r1"] * w1 + RUN["r2"] * w2])
    vt = [vr[k] - rate * en[k] + spin[k] for k in range(3)]
    fcap, c_n, c_t = reference(cli, viscosity, gap)
    ft = [-c_t * v for v in vt]
    force = [-fcap * en[k] - c_n * rate * en[k] + ft[k] for k in range(3)]
    torque = -RUN["r1"] * cross(en, ft)[2]
    scale = abs(fcap) + abs(c_n * rate) + c_t * math.sqrt(sum(v * v for v in vt))
    return gap, force[0], force[1], torque, scale


def check_run(cli, env, workdir, viscosity, ranks):
    variables = [(k, repr(v)) for k, v in RUN.items()] + [("viscosity", repr(viscosity)),
                                                         ("px", ranks)]
    tag = "eta%g.np%d" % (viscosity, ranks)
    code, log = lc.liggghts(env, os.path.join(lc.HERE, "in.viscous"), variables, workdir,
                            ranks=ranks, log="log." + tag)
    if code != 0:
        lc.fail("in.viscous (%s): %s" % (tag, lc.error_line(log) or log[-1500:]))
    rows = [[float(v) for v in row] for row in lc.thermo_rows(log)]
    worst, checked, gaps, fx = 0.0, 0, [], {}
    spins_ok = True
    for step, x1, y1, x2, y2, fx1, fy1, tz1, wz1, wz2, nb in rows:
        spins_ok = spins_ok and wz1 == RUN["w1"] and wz2 == RUN["w2"]
        gap, ex, ey, etz, scale = expected(cli, viscosity, x1, y1, x2, y2, wz1, wz2)
        if step == 0 or gap <= 0.0 or nb != 1.0:
            continue
        checked += 1
        gaps.append(gap)
        fx[int(step)] = fx1
        # the torque is a force times r_1: its scale is scale * r_1
        for got, want, unit in ((fx1, ex, 1.0), (fy1, ey, 1.0), (tz1, etz, RUN["r1"])):
            worst = max(worst, abs(got - want) / (scale * unit))
    warned = WARNING in log
    ok = (spins_ok and checked >= 150 and min(gaps) < RUN["min_gap"]
          and max(gaps) > 50 * RUN["min_gap"] and worst <= TOLERANCE
          and warned == (viscosity > 0.0))
    print("liquidViscosity %g Pa s, %d rank(s): %d steps apart with a bridge, gaps %.3g to "
          "%.3g m (viscousMinGap %g m), spins %s; force and torque on sphere 1 within %.1e of "
          "the core's (tolerance %g); time-step warning for types 1 2 %s %s" % (
              viscosity, ranks, checked, min(gaps) if gaps else 0.0,
              max(gaps) if gaps else 0.0, RUN["min_gap"],
              "constant" if spins_ok else "CHANGED", worst, TOLERANCE,
              "given" if warned else "not given", "ok" if ok else "FAIL"))
    return ok, fx


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("capbridge")
    parser.add_argument("env")
    parser.add_argument("--workdir", default="")
    args = parser.parse_args()
    env, workdir = lc.start(args.env, args.workdir, "viscous")
    cli = os.path.abspath(args.capbridge)
    ok = True
    fx = {}
    for ranks in (1, 2):
        for viscosity in (0.5, 0.0):
            good, fx[(ranks, viscosity)] = check_run(cli, env, workdir, viscosity, ranks)
            ok = ok and good
    # the viscous force is not negligible here: it changes f_x by more than 5 % at every
    # step compared (it resists the separation and the sliding)
    steps = sorted(set(fx[(1, 0.5)]) & set(fx[(1, 0.0)]))
    smallest = min(abs(fx[(1, 0.5)][s] - fx[(1, 0.0)][s]) / abs(fx[(1, 0.0)][s])
                   for s in steps) if steps else 0.0
    good = bool(steps) and smallest > 0.05
    ok = ok and good
    print("the viscous force changes f_x on sphere 1 by at least %.1f %% over %d steps %s" % (
        100.0 * smallest, len(steps), "ok" if good else "FAIL"))
    print("viscous force: %s (files in %s)" % ("PASS" if ok else "FAIL", workdir))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
