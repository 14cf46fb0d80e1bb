#!/usr/bin/env python3
"""A pair held in contact by its bridge alone slides at mu F_cap (Richefeu 2007 eq. 12).

tests/liggghts/in.held: a sphere touching a sphere at rest, held by a richefeu bridge and by
nothing else, settles where the contact force balances the bridge (gap -F_cap/k_n); a slow
tangential ramp then makes it slide. Eq. 12's limit mu (f_n - f_n^c), with eq. 1's
f_n = f_n^e + f_n^d + f_n^c, is mu times the contact force alone, here mu F_cap; a limit that
adds the attraction to the contact force (the model's former 'capillary_friction on') gives
2 mu F_cap. F_cap comes from `capbridge force` (the C reference CLI), not from LIGGGHTS.

usage: held.py CAPBRIDGE LIGGGHTS_ENV [--workdir DIR]
"""
import argparse
import os
import subprocess
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import liggghts_common as lc  # noqa: E402

MU, KN = 0.4, 1000.0
TOLERANCE = 0.03   # the ramp's load grows 0.35 % of mu F_cap per 100-step check


def contact_force(cli):
    """F_cap of in.held's bridge at contact, from the reference CLI."""
    result = subprocess.run([cli, "force", "richefeu", "gamma", "0.0728", "--r1", "1e-3",
                             "--r2", "1e-3", "--volume", "1e-11", "--gap", "0"],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            universal_newlines=True)
    lines = result.stdout.split()
    if result.returncode != 0 or len(lines) != 2:
        lc.fail("capbridge force failed: " + result.stderr)
    return float(lines[1].split(",")[1])


def printed(log, key):
    for line in log.splitlines():
        fields = line.split()
        if len(fields) >= 2 and fields[0] == key:
            return [float(v) for v in fields[1::2]]
    lc.fail("in.held printed no %s: %s" % (key, lc.error_line(log) or log[-1500:]))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("capbridge")
    parser.add_argument("env")
    parser.add_argument("--workdir", default="")
    args = parser.parse_args()
    env, workdir = lc.start(args.env, args.workdir, "held")
    fcap = contact_force(os.path.abspath(args.capbridge))
    deck = os.path.join(lc.HERE, "in.held")
    code, log = lc.liggghts(env, deck, [("mu", MU), ("fcap", repr(fcap)), ("extra", "")],
                            workdir, log="log.held")
    if code != 0:
        lc.fail("in.held: " + (lc.error_line(log) or log[-1500:]))
    gap = printed(log, "SETTLED_GAP")[0]
    load, speed = printed(log, "SLIDING_LOAD")
    ok = True
    settled = -fcap / KN
    good = abs(gap - settled) <= 1e-3 * abs(settled)
    ok = ok and good
    print("at rest, held by the bridge: gap %.9e m, -F_cap/k_n %.9e m (F_cap %.9e N from "
          "capbridge force) %s" % (gap, settled, fcap, "ok" if good else "FAIL"))
    good = speed > 5e-5 and abs(load - MU * fcap) <= TOLERANCE * MU * fcap
    ok = ok and good
    print("slides under a tangential load of %.9e N = %.4f mu F_cap (speed %.3g m/s); "
          "eq. 12: mu F_cap = %.9e N, within %g %s" % (
              load, load / (MU * fcap), speed, MU * fcap, TOLERANCE, "ok" if good else "FAIL"))
    print("held by its bridge alone: %s (files in %s)" % ("PASS" if ok else "FAIL", workdir))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
