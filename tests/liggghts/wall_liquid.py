#!/usr/bin/env python3
"""Wall bridges under Richefeu 2007's Protocols 1, 2 and 3 in LIGGGHTS (issue 19, point 2):
the wall holds no liquid; the grain's liquid forms the bridge (Protocols 2, 3: shared with the
grain's other new bridges of the step; Protocol 1 and `start bridges`: the distribution gives
it with the pairs'), and comes back at rupture; the liquid is conserved on 1, 2, 3 ranks and
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
  - Protocol 1, up 0 (the wall at the spheres' 20 degrees): the first distribution gives the
    three bridges (the pair's, R = sqrt(r1 r2), and each sphere's with the wall, R = r: the
    core weighs a wall pair as the sphere and its mirror image) a third of the liquid each,
    Richefeu's eq. 13 for three equal R; once sphere 2 has left the pair's rupture distance,
    the distributions every 100 steps give each wall bridge half of it;
  - Protocol 2 with `start bridges`, up 0, the wall made after the liquid was set: the start's
    distribution at the run's setup gives the three bridges a third each (the wall's new
    contact history kept through LIGGGHTS's reset of new per-atom properties there); when
    the pair's bridge breaks, its liquid is the two spheres' free liquid, half each; with
    `remove 1` all three bridges are removed at the start (the report counts the walls'),
    their liquid free, and the wall bridges do not form again while their contacts last (the
    pair's forms again at the step its contact opens to gap 0, as the core's rule has it).
Each on 1 and 2 ranks (the two spheres owned by two ranks): every value the same to 1e-12.
tests/liggghts/in.wall_floor, 150 grains falling onto the wall under Protocols 1, 2 and 3 and
Protocol 2 with `start bridges`: the total liquid is 150 nl to 1e-12 relative at every step
on 1, 2 and 3 ranks, wall bridges form and break; and stopped at half-way into a restart file,
read by a second process: the same liquid and wall bridges at the restart, the total kept in
both halves.
Refusals, by message: a wall whose liquid is not the pair_style's, a mesh under a protocol, a
wall whose law is not the pair's where the liquid distributes (the wall's contact angle apart
from the grains' is refused before, by the pair's own check: the wall's atom type is one of
the pair_style's).

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


def cli(capbridge, command, volume, *extra, theta=THETA, second=("--plane",)):
    """The core's number for the sphere of radius R and a wall (second: the plane), or
    another sphere (second=("--r2", R))."""
    words = [capbridge, command, "willett", "theta", theta, "--r1", repr(R)] + list(second) + \
        ["--volume", repr(volume)] + list(extra)
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
    return [[float(v) for v in row] for row in lc.thermo_rows(log) if len(row) == 9]


def shared_at_start(rows, name):
    """Step 0: sphere 1's liquid in two bridges of half of it each, none free."""
    step, _, _, free1, free2, bridged1, bridged2, walls, _ = rows[0]
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
    for step, z1, fz, free1, _, bridged1, _, walls, _ in rows:
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
    step, _, _, free1, free2, bridged1, bridged2, walls, _ = rows[-1]
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


def same_on_two_ranks(runs, name):
    """Every value of the 2-rank run (one sphere per rank) as on 1 rank, to 1e-12."""
    rows = runs[1]
    same = len(runs[2]) == len(rows) and all(
        close(a, b, max(abs(a), 1e-30)) for r1, r2 in zip(rows, runs[2]) for a, b in zip(r1, r2))
    print("%s on 2 ranks (one sphere each): every value as on 1 rank %s"
          % (name, "ok" if same else "FAIL"))
    return same


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
            ok = same_on_two_ranks(runs, name) and ok
    return ok


def distributed(capbridge, env, workdir):
    """Protocol 1: the liquid in thirds, then in halves once the pair is out of reach."""
    runs = {ranks: share_run(env, workdir, ranks, liquid="protocol1", up=0, theta_wall=20.0,
                             pair_keyword="every", pair_value=100)
            for ranks in (1, 2)}
    rows, name = runs[1], "protocol1, pulled apart"
    third, half = LIQUID1 / 3.0, 0.5 * LIQUID1
    # the liquid is set after a `run 0`, whose setup made the first distribution (of none):
    # the next is at step 100 (every 100)
    before = all(r[7] == 0.0 and r[3] == LIQUID1 for r in rows if r[0] < 100)
    first = next(r for r in rows if r[0] == 100)
    last = rows[-1]
    ok = before and first[3] == 0.0 and first[4] == 0.0 and first[7] == 2.0 and \
        close(first[8], 2.0 * third, LIQUID1) and close(first[5], half, LIQUID1) and \
        close(first[6], half, LIQUID1)
    print("%s: the liquid free until the distribution at step 100, which gives the pair's bridge "
          "and the two wall bridges a third of it each (wall bridges %d holding %.6g m^3, "
          "bridged %.6g and %.6g, free %g, %g) %s"
          % (name, first[7], first[8], first[5], first[6], first[3], first[4],
             "ok" if ok else "FAIL"))
    # sphere 2 moved by vz t along x from the gap -1e-7 + 1e-7 (its start): beyond the pair's
    # rupture distance for the half it would receive, so the pair is no candidate at the end
    gap = SHARE["vz"] * 1e-6 * last[0] - 1e-7
    rupture = cli(capbridge, "rupture", half, theta="20", second=("--r2", repr(R)))[0]
    halves = last[7] == 2.0 and close(last[8], LIQUID1, LIQUID1) and \
        close(last[5], half, LIQUID1) and close(last[6], half, LIQUID1) and \
        last[3] == 0.0 and last[4] == 0.0 and gap > rupture
    print("%s: at the end (the pair's gap %.6g m, beyond the rupture distance %.6g m of the half) "
          "the two wall bridges hold half of the liquid each (%.6g m^3 in all; bridged %.6g and "
          "%.6g, free %g, %g) %s" % (name, gap, rupture, last[8], last[5], last[6], last[3],
                                     last[4], "ok" if halves else "FAIL"))
    ok = halves and conserved(rows, LIQUID1, name) and ok
    return same_on_two_ranks(runs, name) and ok


def started(env, workdir):
    """Protocol 2 with start bridges: thirds at the setup of the run (the wall made just before
    it), then the pair's bridge broken and its liquid free, half to each sphere."""
    runs = {ranks: share_run(env, workdir, ranks, up=0, theta_wall=20.0, start="bridges")
            for ranks in (1, 2)}
    rows, name = runs[1], "protocol2 start bridges, pulled apart"
    third = LIQUID1 / 3.0
    first, last = rows[0], rows[-1]
    ok = first[0] == 0 and first[3] == 0.0 and first[4] == 0.0 and first[7] == 2.0 and \
        close(first[8], 2.0 * third, LIQUID1) and close(first[5], 0.5 * LIQUID1, LIQUID1) and \
        close(first[6], 0.5 * LIQUID1, LIQUID1)
    print("%s: at the first step (the setup of the wall's first run) the pair's bridge and the "
          "two wall bridges a third of the liquid each (wall bridges %d holding %.6g m^3, "
          "bridged %.6g and %.6g, free %g, %g) %s"
          % (name, first[7], first[8], first[5], first[6], first[3], first[4],
             "ok" if ok else "FAIL"))
    broken = last[7] == 2.0 and close(last[8], 2.0 * third, LIQUID1) and \
        all(close(v, 0.5 * third, LIQUID1) for v in (last[3], last[4])) and \
        all(close(v, third, LIQUID1) for v in (last[5], last[6]))
    print("%s: at the end the pair's bridge broken, half of its liquid free on each sphere "
          "(free %.6g and %.6g m^3), the wall bridges kept (%.6g m^3) %s"
          % (name, last[3], last[4], last[8], "ok" if broken else "FAIL"))
    ok = broken and conserved(rows, LIQUID1, name) and ok
    return same_on_two_ranks(runs, name) and ok


def removed(env, workdir):
    """start bridges with remove 1: the three bridges removed at the start, their liquid the
    spheres' free liquid; the wall bridges, in contact, do not form again."""
    ok = True
    for ranks in (1, 2):
        name = "protocol2 start bridges remove 1, %d rank(s)" % ranks
        run = dict(SHARE, up=0, theta_wall=20.0, start="bridges", remove_key="remove",
                   remove_value=1, seed_key="remove_seed", seed_value=7723)
        code, log = lc.liggghts(env, os.path.join(lc.HERE, "in.wall_share"),
                                [(k, v if isinstance(v, str) else repr(v))
                                 for k, v in run.items()],
                                workdir, ranks=ranks, log="log.removed-%d" % ranks)
        if code != 0:
            lc.fail("in.wall_share (%s): %s" % (name, lc.error_line(log) or log[-1500:]))
        rows = [[float(v) for v in row] for row in lc.thermo_rows(log) if len(row) == 9]
        report = "removed 3 of 3 bridges" in log
        first = rows[0]
        free = first[5] == 0.0 and first[6] == 0.0 and close(first[3], 0.5 * LIQUID1, LIQUID1) \
            and close(first[4], 0.5 * LIQUID1, LIQUID1)
        walls = all(r[7] == 0.0 and r[8] == 0.0 for r in rows)
        this = report and free and walls and len(rows) == SHARE["nsteps"] + 1
        print("%s: the report says 3 of 3 bridges removed (the two wall bridges with the "
              "pair's); at step 0 no bridge, half of the liquid free on each sphere; no wall "
              "bridge at any step (their contacts last) %s"
              % (name, "ok" if this else "FAIL: " + (lc.error_line(log) or "")))
        ok = conserved(rows, LIQUID1, name) and this and ok
    return ok


# the floor's liquid words: each protocol, and Protocol 2 starting with a distribution
FLOOR_CASES = (("protocol1", "every", "0", 0.0), ("protocol2", "start", "free", 30.0),
               ("protocol3", "start", "free", 30.0), ("protocol2", "start", "bridges", 0.0))


def floor_run(env, workdir, case, ranks, part, restart=""):
    protocol, keyword, value, theta_wall = case
    name = "floor-%s-%s-%d-part%d" % (protocol, value, ranks, part)
    code, log = lc.liggghts(env, os.path.join(lc.HERE, "in.wall_floor"),
                            [("px", ranks), ("liquid", protocol), ("pair_keyword", keyword),
                             ("pair_value", value),
                             ("theta_wall", theta_wall), ("nsteps", FLOOR_STEPS),
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
    for case in FLOOR_CASES:
        words = "%s %s %s" % case[:3]
        for ranks in (1, 2, 3):
            ok = floor_conserved(floor_run(env, workdir, case, ranks, 0),
                                 "floor, %s, %d rank(s)" % (words, ranks), FLOOR_STEPS) and ok
        for ranks in (1, 2):
            restart = os.path.join(workdir, "floor-%s-%s-%d.restart"
                                   % (case[0], case[2], ranks))
            first = floor_run(env, workdir, case, ranks, 1, restart)
            second = floor_run(env, workdir, case, ranks, 2, restart)
            name = "floor, %s, %d rank(s), restarted" % (words, ranks)
            if case[0] == "protocol1":
                # the first run after read_restart distributes (all liquid into bridges)
                kept = close(first[-1][3], second[0][3], FLOOR_TOTAL) and second[0][1] == 0.0
                print("%s: the second process starts with the first's liquid, distributed at "
                      "its setup (free %g, %d wall bridges) %s"
                      % (name, second[0][1], second[0][4], "ok" if kept else "FAIL"))
            else:
                kept = close(first[-1][1], second[0][1], FLOOR_TOTAL) and \
                    close(first[-1][2], second[0][2], FLOOR_TOTAL) and \
                    first[-1][4] == second[0][4]
                print("%s: the second process starts with the liquid and the %d wall bridges "
                      "the first ended with %s" % (name, second[0][4], "ok" if kept else "FAIL"))
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
    ok = refused(env, workdir, "mesh wall under protocol2", "takes primitive walls only",
                 mesh=1, stl=stl) and ok
    ok = refused(env, workdir, "protocol1, the wall with another law",
                 "the wall's bridges with atom type 1 have another law",
                 liquid="protocol1", pair_keyword="every", pair_value=0, theta_wall=20.0,
                 wall_liquid="protocol1 overlap none") and ok
    ok = refused(env, workdir, "start bridges, the wall with another law",
                 "the wall's bridges with atom type 1 have another law", start="bridges",
                 theta_wall=20.0, wall_liquid="protocol2 overlap none") and ok
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
    ok = distributed(capbridge, env, workdir) and ok
    ok = started(env, workdir) and ok
    ok = removed(env, workdir) and ok
    ok = floor(env, workdir) and ok
    ok = refusals(env, workdir) and ok
    print("wall bridges under the protocols: %s (files in %s)"
          % ("PASS" if ok else "FAIL", workdir))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
