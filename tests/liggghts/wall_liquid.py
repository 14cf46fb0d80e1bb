#!/usr/bin/env python3
"""Wall bridges under Richefeu 2007's Protocols 2 and 3 in LIGGGHTS (issue 19, point 2): the
wall holds no liquid; the grain's liquid forms the bridge, shared with the grain's other new
bridges of the step, and comes back at rupture; the liquid is conserved on 1, 2, 3 ranks and
across a restart file.

tests/liggghts/in.wall_share, two spheres (radius 1 mm) touching a primitive wall z = 0 and
each other from the first step, sphere 1 with 2e-11 m^3 of free liquid, sphere 2 dry:
  - up 1 (sphere 2 above, both pulled up): sphere 1's two new bridges take half of its liquid
    each (the core's k-way share, cb_protocol_grain_step: the wall's bridge counted with the
    pair's, as LAMMPS's fix capillary/liquid counts it); while the wall's bridge stretches the
    wall's force on the two spheres (fz1 + fz2) is the attraction of `capbridge force willett
    --plane --volume 1e-11` at the run's gap, to 1e-9; none once the gap passes `capbridge
    rupture`; its liquid is then sphere 1's free liquid again;
  - up 0 (sphere 2 beside, pulled away along the wall): the pair's bridge breaks; sphere 1's
    share of it (half: equal radii) goes to its free liquid under Protocol 2 and to its lowest
    bridge, the wall's, under Protocol 3; sphere 2's share forms its own wall bridge (it slides
    on the wall).
Each on 1 and 2 ranks (the two spheres owned by two ranks): every value the same to 1e-12.
tests/liggghts/in.wall_floor, 150 grains falling onto the wall under Protocols 2 and 3:
the total liquid is 150 nl to 1e-12 relative at every step on 1, 2 and 3 ranks, wall bridges
form and break; and stopped at half-way into a restart file, read by a second process: the
same liquid and wall bridges at the restart, the total kept in both halves.
Refusals, by message: a wall whose liquid is not the pair_style's, Protocol 1 at a wall, a
mesh under a protocol, the pair_style's `start bridges` with walls.

usage: wall_liquid.py CAPBRIDGE LIGGGHTS_ENV [--workdir DIR]
"""
import argparse
import math
import os
import subprocess
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import liggghts_common as lc  # noqa: E402

TOLERANCE = 1e-9    # the wall's force against the core's sphere-plane pair
SAME = 1e-12        # liquid totals; one run against another
LIQUID1 = 2e-11     # sphere 1's free liquid [m^3]
R = 1e-3
SHARE = {"liquid1": LIQUID1, "vz": 0.05, "nsteps": 8000, "skin": 6e-4, "up": 1,
         "liquid": "protocol2"}
# the bridge's contact angle: the mean cosine of the spheres' 20 and the wall's 40 degrees
THETA = repr(math.degrees(math.acos(0.5 * (math.cos(math.radians(20.0)) +
                                           math.cos(math.radians(40.0))))))
FLOOR_TOTAL = 150 * 1e-12
FLOOR_STEPS = 3000


def cli(capbridge, command, volume, *extra):
    words = [capbridge, command, "willett", "theta", THETA, "--r1", repr(R), "--plane",
             "--volume", repr(volume)] + list(extra)
    result = subprocess.run(words, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            universal_newlines=True)
    lines = result.stdout.split()
    if result.returncode != 0 or len(lines) != 2:
        lc.fail("%s failed: %s" % (" ".join(words), result.stderr))
    return [float(v) for v in lines[1].split(",")]


def close(a, b, scale):
    return abs(a - b) <= SAME * scale


def share_run(env, workdir, ranks, **changes):
    run = dict(SHARE, **changes)
    name = "share-%s-up%d-%d" % (run["liquid"], run["up"], ranks)
    code, log = lc.liggghts(env, os.path.join(lc.HERE, "in.wall_share"),
                            [(k, v if isinstance(v, str) else repr(v)) for k, v in run.items()],
                            workdir, ranks=ranks, log="log." + name)
    if code != 0:
        lc.fail("in.wall_share (%s): %s" % (name, lc.error_line(log) or log[-1500:]))
    return [[float(v) for v in row] for row in lc.thermo_rows(log) if len(row) == 8]


def shared_at_start(rows, name):
    """Step 0: sphere 1's liquid in two bridges of half of it each, none free."""
    step, _, _, free1, free2, bridged1, bridged2, walls = rows[0]
    half = 0.5 * LIQUID1
    ok = step == 0 and free1 == 0.0 and free2 == 0.0 and walls == 1.0 and \
        close(bridged1, half + 0.5 * half, LIQUID1) and close(bridged2, 0.5 * half, LIQUID1)
    print("%s: at the first step sphere 1's liquid in its wall bridge and its pair bridge, "
          "half each (bridged %.6g and %.6g m^3, free %g, %g; %d wall bridge) %s"
          % (name, bridged1, bridged2, free1, free2, walls, "ok" if ok else "FAIL"))
    return ok


def conserved(rows, total, name):
    worst = max(abs(r[3] + r[4] + r[5] + r[6] - total) for r in rows) / total
    ok = worst <= SAME
    print("%s: free + bridged liquid %.6g m^3 at every step within %.1e (tolerance %g) %s"
          % (name, total, worst, SAME, "ok" if ok else "FAIL"))
    return ok


def pulled_up(capbridge, rows, name):
    """The wall's bridge of half of sphere 1's liquid stretched to its rupture."""
    volume = 0.5 * LIQUID1
    rupture = cli(capbridge, "rupture", volume)[0]
    worst, checked, after, last_gap, returned = 0.0, 0, 0, 0.0, True
    for step, z1, fz, free1, _, bridged1, _, walls in rows:
        gap = z1 - R
        if gap <= 0.0:
            continue
        if gap > rupture:
            after += 1
            returned = returned and abs(fz) <= 1e-15 and walls == 0.0 and \
                close(free1, volume, LIQUID1) and close(bridged1, 0.5 * volume, LIQUID1)
            continue
        last_gap = max(last_gap, gap)
        if int(step) % 10:
            continue
        force = cli(capbridge, "force", volume, "--gap", repr(gap))[1]
        worst = max(worst, abs(fz + force) / force)
        checked += 1
    ok = checked >= 300 and after >= 50 and worst <= TOLERANCE and returned and \
        rupture - last_gap < SHARE["vz"] * 1e-6 * 1.01
    print("%s: the wall's force within %.1e of the core's for its %.3g m^3 bridge (%d gaps, "
          "tolerance %g); held to gap %.6g m, broken beyond the rupture distance %.6g m, its "
          "liquid sphere 1's free liquid again (%d steps) %s"
          % (name, worst, volume, checked, TOLERANCE, last_gap, rupture, after,
             "ok" if ok and returned else "FAIL"))
    return ok


def pulled_apart(rows, protocol, name):
    """The pair's bridge broken: sphere 1's half of it free (Protocol 2) or in its wall
    bridge (Protocol 3); sphere 2's half in its own new wall bridge."""
    quarter = 0.25 * LIQUID1
    step, _, _, free1, free2, bridged1, bridged2, walls = rows[-1]
    if protocol == "protocol2":
        expected = (quarter, 0.0, 0.5 * LIQUID1, quarter)
    else:
        expected = (0.0, 0.0, 0.5 * LIQUID1 + quarter, quarter)
    ok = walls == 2.0 and all(close(a, b, LIQUID1) for a, b in
                              zip((free1, free2, bridged1, bridged2), expected))
    print("%s: the pair's bridge broken by step %d: sphere 1 free %.6g, bridged %.6g m^3 (%s), "
          "sphere 2's share in its own wall bridge (bridged %.6g m^3), %d wall bridges %s"
          % (name, step, free1, bridged1,
             "its share free" if protocol == "protocol2" else "its share in its wall bridge",
             bridged2, walls, "ok" if ok else "FAIL"))
    return ok


def share(capbridge, env, workdir):
    ok = True
    for protocol in ("protocol2", "protocol3"):
        for up in (1, 0):
            runs = {ranks: share_run(env, workdir, ranks, liquid=protocol, up=up)
                    for ranks in (1, 2)}
            name = "%s, %s" % (protocol, "pulled up" if up else "pulled apart")
            rows = runs[1]
            ok = shared_at_start(rows, name) and ok
            ok = conserved(rows, LIQUID1, name) and ok
            ok = (pulled_up(capbridge, rows, name) if up else
                  pulled_apart(rows, protocol, name)) and ok
            same = len(runs[2]) == len(rows) and all(
                close(a, b, max(abs(a), 1e-30)) for r1, r2 in zip(rows, runs[2])
                for a, b in zip(r1, r2))
            print("%s on 2 ranks (one sphere each): every value as on 1 rank %s"
                  % (name, "ok" if same else "FAIL"))
            ok = same and ok
    return ok


def floor_run(env, workdir, protocol, ranks, part, restart=""):
    name = "floor-%s-%d-part%d" % (protocol, ranks, part)
    code, log = lc.liggghts(env, os.path.join(lc.HERE, "in.wall_floor"),
                            [("px", ranks), ("liquid", protocol), ("nsteps", FLOOR_STEPS),
                             ("part", part), ("restart", restart or "none")],
                            workdir, ranks=ranks, log="log." + name)
    if code != 0:
        lc.fail("in.wall_floor (%s): %s" % (name, lc.error_line(log) or log[-1500:]))
    return [[float(v) for v in row] for row in lc.thermo_rows(log) if len(row) == 5]


def floor_conserved(rows, name, steps):
    worst = max(abs(r[3] - FLOOR_TOTAL) for r in rows) / FLOOR_TOTAL
    walls = [r[4] for r in rows]
    broke = any(b < a for a, b in zip(walls, walls[1:]))
    ok = len(rows) == steps + 1 and worst <= SAME and max(walls) > 0 and broke
    print("%s: total liquid within %.1e of 150 nl at %d steps (tolerance %g); wall bridges "
          "up to %d, some broken %s" % (name, worst, len(rows), SAME, max(walls),
                                         "ok" if ok else "FAIL"))
    return ok


def floor(env, workdir):
    ok = True
    for protocol in ("protocol2", "protocol3"):
        for ranks in (1, 2, 3):
            ok = floor_conserved(floor_run(env, workdir, protocol, ranks, 0),
                                 "floor, %s, %d rank(s)" % (protocol, ranks), FLOOR_STEPS) and ok
        for ranks in (1, 2):
            restart = os.path.join(workdir, "floor-%s-%d.restart" % (protocol, ranks))
            first = floor_run(env, workdir, protocol, ranks, 1, restart)
            second = floor_run(env, workdir, protocol, ranks, 2, restart)
            name = "floor, %s, %d rank(s), restarted" % (protocol, ranks)
            kept = close(first[-1][1], second[0][1], FLOOR_TOTAL) and \
                close(first[-1][2], second[0][2], FLOOR_TOTAL) and first[-1][4] == second[0][4]
            print("%s: the second process starts with the liquid and the %d wall bridges the "
                  "first ended with %s" % (name, second[0][4], "ok" if kept else "FAIL"))
            ok = kept and floor_conserved(first + second[1:], name, FLOOR_STEPS) and ok
    return ok


def refused(env, workdir, name, expected, **changes):
    run = dict(SHARE, nsteps=10, **changes)
    code, log = lc.liggghts(env, os.path.join(lc.HERE, "in.wall_share"),
                            [(k, v if isinstance(v, str) else repr(v)) for k, v in run.items()],
                            workdir, log="log." + name.replace(" ", "-"),
                            screen="screen." + name.replace(" ", "-"))
    ok = code != 0 and expected in log
    print("%s: %s %s" % (name, "refused" if ok else "NOT refused as expected",
                         "ok" if ok else "FAIL: " + (lc.error_line(log) or log[-800:])))
    return ok


def refusals(env, workdir):
    stl = os.path.join(workdir, "plane.stl")
    lc.write_plane_stl(stl)
    ok = refused(env, workdir, "wall liquid fixed beside the pair's protocol2",
                 "'liquid fixed' must be the pair_style's liquid, 'liquid protocol2'",
                 wall_liquid="fixed")
    ok = refused(env, workdir, "wall protocol1", "not 'liquid protocol1'",
                 liquid="protocol1", wall_liquid="protocol1") and ok
    ok = refused(env, workdir, "mesh wall under protocol2", "takes primitive walls only",
                 mesh=1, stl=stl) and ok
    ok = refused(env, workdir, "walls with start bridges", "give the pair_style 'start free'",
                 start="bridges", theta_wall=20.0) and ok
    ok = refused(env, workdir, "wall with vmax", "are the pair_style's",
                 wall_liquid="protocol2 vmax 1e-11") and ok
    return ok


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("capbridge")
    parser.add_argument("env")
    parser.add_argument("--workdir", default="")
    args = parser.parse_args()
    env, workdir = lc.start(args.env, args.workdir, "wall_liquid")
    capbridge = os.path.abspath(args.capbridge)
    ok = share(capbridge, env, workdir)
    ok = floor(env, workdir) and ok
    ok = refusals(env, workdir) and ok
    print("wall bridges under the protocols: %s (files in %s)"
          % ("PASS" if ok else "FAIL", workdir))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
