#!/usr/bin/env python3
"""A stretched bridge and its liquid survive a restart file (Protocol 2).

Two spheres of radius 1 mm in contact, 1 nl of free liquid each: the bridge that forms takes
all of it (2e-12 m^3), so no particle has free liquid left.  They then separate at 1 m/s
each.  At step 30 the bridge is stretched to a gap of ~48 um, beyond the neighbor skin
(20 um), and a restart file is written; a second LIGGGHTS process reads it and goes on to
step 130, past the rupture distance.  The reach of the second run must cover the bridge
that exists, although no free liquid is on offer (the contact distance factor of a new
process starts from 1): before, the pair fell out of the neighbor list at the restart and
the bridge's liquid was gone, without a word.

Checked:
  - the restarted run is the continuous run, step for step (positions and free liquid
    equal to 1e-12 relative: the bridge's force acted after the restart);
  - the liquid is released to the particles at rupture: free liquid 2e-12 m^3 at the end;
  - rupture between the two outputs that bracket Lian's rupture distance V^(1/3) at
    theta = 0 (the law's own, analytic), in both runs.
With --ranks 2 each sphere is on a rank of its own (the bridge in both ranks' histories).

usage: restart.py LIGGGHTS_ENV [--workdir DIR] [--ranks 1|2]
"""
import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import liggghts_common as lc  # noqa: E402

R, FREE, SKIN = 1e-3, 1e-12, 2e-5
VOLUME = 2 * FREE
MODEL = """fix m1 all property/global kn peratomtypepair 1 100
fix m2 all property/global kt peratomtypepair 1 100
fix m3 all property/global gamman peratomtypepair 1 0
fix m4 all property/global gammat peratomtypepair 1 0
fix m5 all property/global coefficientFriction peratomtypepair 1 0.3
fix m6 all property/global surfaceTension scalar 0.0728
fix m7 all property/global contactAngle peratomtype 0
pair_style      gran model hooke/stiffness tangential history cohesion capillary &
                law richefeu liquid protocol2 start free
pair_coeff      * *
timestep        1e-6
fix             integrate all nve/sphere
compute         free all reduce sum f_freeLiquid
variable        x1 equal x[1]
variable        x2 equal x[2]
thermo_style    custom step v_x1 v_x2 c_free
thermo_modify   format float %.17g norm no
thermo          10
"""
FIRST = """units           si
atom_style      granular
atom_modify     map array
boundary        f f f
newton          off
communicate     single vel yes
processors      {ranks} 1 1
region          box block -0.01 0.01 -0.01 0.01 -0.01 0.01 units box
create_box      1 box
create_atoms    1 single -0.000999 0 0 units box
create_atoms    1 single 0.000999 0 0 units box
set             type 1 diameter {diameter!r} density 2500
neighbor        {skin!r} bin
neigh_modify    delay 0
fix freeLiquid all property/atom freeLiquid scalar yes yes no {free!r}
{model}run             5
velocity        all set NULL 0 0
set             atom 1 vx -1.0
set             atom 2 vx 1.0
run             25
{end}"""
SECOND = """atom_modify     map array
communicate     single vel yes
processors      {ranks} 1 1
read_restart    two.restart
newton          off
neighbor        {skin!r} bin
neigh_modify    delay 0
fix freeLiquid all property/atom freeLiquid scalar yes yes no 0
{model}run             100
"""


def series(workdir, env, name, text, ranks):
    deck = os.path.join(workdir, "in." + name)
    with open(deck, "w") as f:
        f.write(text)
    code, log = lc.liggghts(env, deck, [], workdir, ranks=ranks, log="log." + name)
    if code != 0:
        lc.fail("%s: %s" % (name, lc.error_line(log) or log[-1500:]))
    return {int(row[0]): [float(v) for v in row[1:4]] for row in lc.thermo_rows(log)}


def rupture_step(rows):
    """The first output with free liquid back, and the gap at the output before it."""
    steps = sorted(s for s in rows if s >= 30)
    for before, step in zip(steps, steps[1:]):
        if rows[step][2] > 0.0:
            return step, gap(rows[before]), gap(rows[step])
    return None, None, None


def gap(row):
    return (row[1] - row[0]) - 2 * R


def main():
    parser = lc.argument_parser(__doc__)
    parser.add_argument("--ranks", type=int, choices=(1, 2), default=1)
    args = parser.parse_args()
    env, workdir = lc.start(args.env, args.workdir, "restart")
    ranks = args.ranks
    settings = dict(diameter=2 * R, skin=SKIN, free=FREE, model=MODEL, ranks=ranks)
    continuous = series(workdir, env, "continuous",
                        FIRST.format(end="run             100\n", **settings), ranks)
    series(workdir, env, "first", FIRST.format(end="write_restart   two.restart\n", **settings),
           ranks)
    restarted = series(workdir, env, "second", SECOND.format(**settings), ranks)

    ok = True

    def check(good, text):
        nonlocal ok
        ok = ok and good
        print("%s %s" % (text, "ok" if good else "FAIL"))

    at_restart = continuous.get(30)
    check(at_restart is not None and at_restart[2] == 0.0 and gap(at_restart) > SKIN,
          "step 30: all liquid in the bridge, gap %.3g m beyond the skin %.3g m" % (
              gap(at_restart) if at_restart else float("nan"), SKIN))
    steps = sorted(s for s in continuous if s >= 30)
    check(sorted(restarted) == steps, "restarted run: outputs at steps %s" % steps)
    for step in steps:
        if step not in restarted:
            continue
        same = all(abs(a - b) <= 1e-12 * max(abs(a), 1e-30)
                   for a, b in zip(continuous[step], restarted[step]))
        if not same:
            check(False, "step %d: restarted %s, continuous %s" % (
                step, restarted[step], continuous[step]))
    rupture = VOLUME ** (1.0 / 3.0)    # Lian et al.'s (1 + theta/2) V^(1/3), theta = 0
    for name, rows in (("continuous", continuous), ("restarted", restarted)):
        final = rows[max(rows)][2]
        check(abs(final - VOLUME) <= 1e-12 * VOLUME,
              "%s: free liquid at the end %.17g m^3 (the bridge's %.3g)" % (name, final, VOLUME))
        step, below, above = rupture_step(rows)
        check(step is not None and below < rupture <= above,
              "%s: liquid released at step %s, gap between %s and %s m around V^(1/3) = %.6g m"
              % (name, step, below, above, rupture))
    print("restart on %d rank(s): %s (files in %s)" % (ranks, "PASS" if ok else "FAIL", workdir))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
