#!/usr/bin/env python3
"""Bridges between a grain and a wall in LIGGGHTS (`cohesion capillary` in fix wall/gran)
against the core's sphere-plane pair (issue 19, point 2), and through a restart file.

tests/liggghts/in.wall pulls one sphere (radius 1 mm) off the plane z = 0 at 5 cm/s, from
contact past its bridge's rupture: a primitive wall, and a mesh of two triangles whose shared
edge runs under the sphere (one bridge, not two).  At every 10th step apart and within the
rupture distance the force on the sphere must be the attraction of `capbridge force LAW
--plane` (the C reference CLI) at the run's gap, to 1e-9, with the contact angle of the mean
cosine of the sphere's and the wall's (20 and 40 degrees here: acos((cos 20 + cos 40) / 2));
none once the gap passes `capbridge rupture LAW --plane`.  Each pull again in two processes,
a restart file written at step 2000 with the bridge stretched: every step after it as the
continuous run's, to 1e-12 (the bridge kept in the wall's history, per grain or per triangle).
Both pulls again on 2 ranks: the sphere starts on the boundary of the two ranks' domains (x = 0)
and each mesh triangle is owned by one of them.  The pair_style's tally on counts the wall bridge (all its liquid, one end).  The table law at the
primitive wall against the exact Laplace-Young sphere-plane bridge
(`capbridge exact --plane`) to 2e-3.  Errors, asserted by message: a
primitive wall whose neighbor skin is shorter than its bridges' rupture distance (its grain
list is built with the skin alone), and a wall under a liquid protocol beside the pair's liquid
fixed (the protocols at walls: wall_liquid.py).

usage: wall.py CAPBRIDGE LIGGGHTS_ENV [--workdir DIR]
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
EXACT_TOLERANCE = 2e-3  # the table law against the exact bridge, as tests/lammps/test_wall.sh
RUN = {"law": "willett", "volume": 1e-11, "r": 1e-3, "vz": 0.05, "dt": 1e-6, "nsteps": 8000,
       "skin": 3e-4, "theta1": 20.0, "theta2": 40.0, "liquid": "liquid fixed", "resume": 0,
       "save": 0}
SAVE_STEP = 2000  # the restart file: gap 1e-4 m, the bridge stretched, 36 % of its rupture
THETA = math.degrees(math.acos(0.5 * (math.cos(math.radians(RUN["theta1"])) +
                                      math.cos(math.radians(RUN["theta2"])))))


def cli(capbridge, command, *extra, law=RUN["law"]):
    words = [capbridge, command, law, "theta", repr(THETA), "--r1", repr(RUN["r"]),
             "--plane", "--volume", repr(RUN["volume"])] + list(extra)
    result = subprocess.run(words, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            universal_newlines=True)
    lines = result.stdout.split()
    if result.returncode != 0 or len(lines) != 2:
        lc.fail("%s failed: %s" % (" ".join(words), result.stderr))
    return [float(v) for v in lines[1].split(",")]


def deck_variables(workdir, mesh, **changes):
    run = dict(RUN, **changes)
    return [("mesh", mesh), ("stl", os.path.join(workdir, "plane.stl")),
            ("restart", os.path.join(workdir, "wall%d.restart" % mesh))] + \
        [(k, v if isinstance(v, str) else repr(v)) for k, v in run.items()]


def pull(capbridge, env, workdir, mesh, rupture, ranks=1):
    name = ("mesh" if mesh else "primitive") + " wall" + ("" if ranks == 1 else ", %d ranks" % ranks)
    tag = name.replace(", ", "-").replace(" ", "")
    code, log = lc.liggghts(env, os.path.join(lc.HERE, "in.wall"),
                            deck_variables(workdir, mesh), workdir, ranks=ranks,
                            log="log." + tag, screen="screen." + tag)
    if code != 0:
        lc.fail("in.wall (%s): %s" % (name, lc.error_line(log) or log[-1500:]))
    rows = [[float(v) for v in row] for row in lc.thermo_rows(log)]
    worst, checked, after, last_gap = 0.0, 0, 0, 0.0
    for step, z, fz in rows:
        gap = z - RUN["r"]
        if gap <= 0.0:
            continue
        if gap > rupture:
            after += 1
            if fz != 0.0:
                lc.fail("%s: force %g N at gap %g m, beyond the rupture distance %g m"
                        % (name, fz, gap, rupture))
            continue
        last_gap = max(last_gap, gap)
        if int(step) % 10:
            continue
        force = cli(capbridge, "force", "--gap", repr(gap))[1]
        worst = max(worst, abs(fz + force) / force)
        checked += 1
    ok = checked >= 300 and after >= 50 and worst <= TOLERANCE and \
        rupture - last_gap < RUN["vz"] * RUN["dt"] * 1.01
    print("%s: %d steps checked, force within %.1e of the core's (tolerance %g); held to "
          "gap %.6g m, none beyond the rupture distance %.6g m (%d steps) %s"
          % (name, checked, worst, TOLERANCE, last_gap, rupture, after, "ok" if ok else "FAIL"))
    return ok and (ranks > 1 or restarted(env, workdir, mesh, name, rows))


def exact_force(capbridge, gap):
    """The exact Laplace-Young sphere-plane bridge at the mean-cosine angle."""
    words = [capbridge, "exact", "--r1", repr(RUN["r"]), "--plane", "--volume",
             repr(RUN["volume"]), "--theta", repr(THETA), "--gap", repr(gap)]
    result = subprocess.run(words, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            universal_newlines=True)
    lines = result.stdout.split()
    if result.returncode != 0 or len(lines) != 2:
        lc.fail("%s failed: %s" % (" ".join(words), result.stderr))
    return float(lines[1].split(",")[1])


def table_against_exact(capbridge, env, workdir):
    """The table law at a primitive wall against the exact sphere-plane bridge (the table
    interpolates it: within EXACT_TOLERANCE), every 100th step in contact with it."""
    rupture = cli(capbridge, "rupture", law="table")[0]
    code, log = lc.liggghts(env, os.path.join(lc.HERE, "in.wall"),
                            deck_variables(workdir, 0, law="table"), workdir, log="log.table")
    if code != 0:
        lc.fail("in.wall (table): %s" % (lc.error_line(log) or log[-1500:]))
    worst, checked, beyond = 0.0, 0, 0
    for step, z, fz in [[float(v) for v in row] for row in lc.thermo_rows(log)]:
        gap = z - RUN["r"]
        if gap > rupture:
            beyond += fz != 0.0
        elif gap > 0.0 and int(step) % 100 == 0:
            exact = exact_force(capbridge, gap)
            worst = max(worst, abs(-fz - exact) / exact)
            checked += 1
    ok = checked >= 40 and worst <= EXACT_TOLERANCE and beyond == 0
    print("table law at a primitive wall: %d gaps, largest error against the exact bridge %.3g "
          "(tolerance %g), no force beyond its rupture distance %.6g m %s"
          % (checked, worst, EXACT_TOLERANCE, rupture, "ok" if ok else "FAIL"))
    return ok


def restarted(env, workdir, mesh, name, continuous):
    """The pull written to a restart file at SAVE_STEP and read by a second process: every
    step after it as the continuous run's (the bridge kept in the wall's history)."""
    runs = []
    for part, changes in (("first", dict(nsteps=SAVE_STEP, save=1)),
                          ("second", dict(nsteps=RUN["nsteps"] - SAVE_STEP, resume=1))):
        code, log = lc.liggghts(env, os.path.join(lc.HERE, "in.wall"),
                                deck_variables(workdir, mesh, **changes), workdir,
                                log="log.%s.%s" % (name.replace(" ", "-"), part),
                                screen="screen." + name.replace(" ", "-"))
        if code != 0:
            lc.fail("in.wall (%s, %s part): %s" % (name, part, lc.error_line(log) or log[-1500:]))
        runs.append(log)
    after = {int(row[0]): row[1:] for row in lc.thermo_rows(runs[1])}
    expected = {int(r[0]): r[1:] for r in continuous if r[0] >= SAVE_STEP}
    differ = [s for s in expected if s not in after or
              any(abs(a - float(b)) > 1e-12 * max(abs(a), 1e-30)
                  for a, b in zip(expected[s], after[s]))]
    bridged = expected[SAVE_STEP][1] != 0.0
    ok = bridged and sorted(after) == sorted(expected) and not differ
    print("%s, restarted at step %d (force %.6g N): %d steps as the continuous run's%s %s"
          % (name, SAVE_STEP, expected[SAVE_STEP][1], len(expected) - len(differ),
             "" if not differ else ", first difference at step %d" % min(differ),
             "ok" if ok else "FAIL"))
    return ok


def tallied(env, workdir, mesh):
    """The pair_style's tally on counts the wall's bridge, its grain's: all of its liquid in
    bridgedLiquid and one end in bridgeCount while it holds, nothing once it has broken."""
    name = ("mesh" if mesh else "primitive") + " wall, tally"
    code, log = lc.liggghts(env, os.path.join(lc.HERE, "in.wall"),
                            deck_variables(workdir, mesh, tally=1), workdir,
                            log="log." + name.replace(", ", "-").replace(" ", ""),
                            screen="screen." + name.replace(", ", "-").replace(" ", ""))
    if code != 0:
        lc.fail("in.wall (%s): %s" % (name, lc.error_line(log) or log[-1500:]))
    rows = [[float(v) for v in row] for row in lc.thermo_rows(log) if len(row) == 5]
    held = [r for r in rows if r[2] != 0.0]
    gone = [r for r in rows if r[2] == 0.0 and r[1] > RUN["r"]]
    ok = len(held) > 100 and len(gone) > 100 and \
        all(r[3] == RUN["volume"] and r[4] == 1.0 for r in held) and \
        all(r[3] == 0.0 and r[4] == 0.0 for r in gone)
    print("%s: bridgedLiquid %g m^3 and bridgeCount 1 at the %d steps with a force, 0 at the %d "
          "after %s" % (name, RUN["volume"], len(held), len(gone), "ok" if ok else "FAIL"))
    return ok


def refused(env, workdir, name, expected, **changes):
    code, log = lc.liggghts(env, os.path.join(lc.HERE, "in.wall"),
                            deck_variables(workdir, 0, nsteps=10, **changes), workdir,
                            log="log." + name.replace(" ", "-"))
    ok = code != 0 and expected in log
    print("%s: %s %s" % (name, "refused" if ok else "NOT refused as expected",
                         "ok" if ok else "FAIL: " + (lc.error_line(log) or log[-800:])))
    return ok


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("capbridge")
    parser.add_argument("env")
    parser.add_argument("--workdir", default="")
    args = parser.parse_args()
    env, workdir = lc.start(args.env, args.workdir, "wall")
    capbridge = os.path.abspath(args.capbridge)
    lc.write_plane_stl(os.path.join(workdir, "plane.stl"))
    rupture = cli(capbridge, "rupture")[0]
    ok = pull(capbridge, env, workdir, 0, rupture)
    ok = pull(capbridge, env, workdir, 1, rupture) and ok
    ok = pull(capbridge, env, workdir, 0, rupture, ranks=2) and ok
    ok = pull(capbridge, env, workdir, 1, rupture, ranks=2) and ok
    ok = table_against_exact(capbridge, env, workdir) and ok
    ok = tallied(env, workdir, 0) and ok
    ok = tallied(env, workdir, 1) and ok
    ok = refused(env, workdir, "primitive wall with a short skin",
                 "beyond the skin 0.0001 m: a bridged grain would leave the list", skin=1e-4) and ok
    ok = refused(env, workdir, "wall with liquid protocol2 beside the pair's liquid fixed",
                 "'liquid protocol2' must be the pair_style's liquid, 'liquid fixed'",
                 liquid="liquid protocol2") and ok
    print("wall bridges: %s (files in %s)" % ("PASS" if ok else "FAIL", workdir))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
