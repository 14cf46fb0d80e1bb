#!/usr/bin/env python3
"""Protocol 2's liquid that leaves without the model's doing is reported, with its amount.

1. pair_style issued again: three spheres of radius 1 mm with V = 10 nl of free liquid each,
   spheres 1 and 2 overlapping (their bridge takes 2V in the setup pass), sphere 3 apart.
   After a first run the same pair_style is issued again: its new contact history has no
   bridge, so the second run starts with V of the 3V.  Expected: one warning, the liquid
   changed by -2V, naming pair_style; and none without the second pair_style (control).
2. atoms lost in a run (thermo_modify lost ignore): six spheres, V = 1 nl each, in a box
   with fixed walls; spheres 1, 2, 3 rest, sphere 4 and the overlapping pair 5-6 (a bridge
   of 2V) move at 2 m/s out of the box side by side, so they leave at the same
   re-neighboring.  Expected: one warning in the run, 3 particles and 3V of liquid (the free
   liquid of 4 and the bridge of 5-6), on 1 and on 2 ranks; the liquid that stays (read with
   compute reduce) is 3V; and a following run warns no more (the loss was reported).
The change at setup is printed with 17 digits (tolerance 1e-9), the liquid lost with 6
(tolerance 1e-5).

usage: liquid_account.py LIGGGHTS_ENV [--workdir DIR]
"""
import os
import re
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import liggghts_common as lc  # noqa: E402

def header(ranks, free):
    """The deck's start: k_n = k_t = 1000 N/m, friction 0.5, `free` m^3 per atom."""
    return lc.free_liquid_header(ranks, ("-0.01", "0.01"), "5e-4", "1000", "0.5", free)

PAIR = """pair_style      gran model hooke/stiffness tangential history cohesion capillary &
                law richefeu liquid protocol2 start free tally on
pair_coeff      * *
"""
OUTPUT = """timestep        1e-6
fix             integrate all nve/sphere
compute         free all reduce sum f_freeLiquid
compute         bridged all reduce sum f_bridgedLiquid
variable        total equal c_free+c_bridged
thermo_style    custom step atoms v_total
thermo_modify   format float %.17g norm no lost ignore
"""
REISSUE = """create_atoms    1 single -0.0005 0 0 units box
create_atoms    1 single 0.000999 0 0 units box
create_atoms    1 single 0 0.005 0 units box
set             atom * diameter 2e-3 density 2500
""" + OUTPUT + """run             10
{again}run             10
"""
LOST = """create_atoms    1 single -0.005 0 0 units box
create_atoms    1 single -0.005 0.005 0 units box
create_atoms    1 single -0.005 -0.005 0 units box
create_atoms    1 single 0.006 0.005 0 units box
create_atoms    1 single 0.006 -0.005 0 units box
create_atoms    1 single 0.006 -0.003001 0 units box
set             atom * diameter 2e-3 density 2500
group           moving id 4 5 6
velocity        moving set 2 0 0 units box
""" + OUTPUT + """thermo          500
run             3000
run             10
"""
CHANGED = r"WARNING: cohesion model capillary: the liquid changed by (\S+) .*"
LEFT = (r"WARNING: cohesion model capillary: (\d+) particles left the run by step (\d+) .* "
        r"with them (\S+) m\^3 of liquid")


def close(a, b, tolerance=1e-9):
    return abs(a - b) <= tolerance * abs(b)


def deck(workdir, name, text):
    path = os.path.join(workdir, "in." + name)
    with open(path, "w") as f:
        f.write(text)
    return path


def reissued(env, workdir):
    free = 1e-11
    ok = True
    for again in (True, False):
        name = "reissue" if again else "reissue_control"
        path = deck(workdir, name, header(1, free) + PAIR +
                    REISSUE.format(again=PAIR if again else ""))
        code, log = lc.liggghts(env, path, [], workdir, log="log." + name)
        if code != 0:
            lc.fail("%s: %s" % (name, lc.error_line(log) or log[-1500:]))
        warnings = re.findall(CHANGED, log)
        lines = [m.group(0) for m in re.finditer(CHANGED, log)]
        if again:
            good = (len(warnings) == 1 and close(float(warnings[0]), -2 * free)
                    and "pair_style was issued again" in lines[0])
            detail = lines[0] if lines else "no warning"
        else:
            good = not warnings
            detail = "no warning" if good else lines[0]
        ok = ok and good
        print("%s: %s (expected %s)\n    %s" % (
            "pair_style issued again" if again else "control, one pair_style",
            "ok" if good else "FAIL", "-2V = %g m^3" % (-2 * free) if again else "none",
            detail))
    return ok


def lost(env, workdir, ranks):
    free = 1e-12
    name = "lost.%d" % ranks
    path = deck(workdir, name, header(ranks, free) + PAIR + LOST)
    code, log = lc.liggghts(env, path, [], workdir, ranks=ranks, log="log." + name)
    if code != 0:
        lc.fail("%s: %s" % (name, lc.error_line(log) or log[-1500:]))
    left = re.findall(LEFT, log)
    rows = lc.thermo_rows(log)
    atoms, total = int(rows[-1][1]), float(rows[-1][2])
    good = (len(left) == 1 and int(left[0][0]) == 3 and close(float(left[0][2]), 3 * free, 1e-5)
            and atoms == 3 and close(total, 3 * free) and not re.findall(CHANGED, log))
    print("atoms lost, %d rank(s): %s (expected 3 particles, 3V = %g m^3; %d atoms and "
          "%.6g m^3 stay)\n    %s" % (
              ranks, "ok" if good else "FAIL", 3 * free, atoms, total,
              "; ".join("%s particles by step %s with %s m^3" % w for w in left) or
              "no warning"))
    return good


def main():
    parser = lc.argument_parser(__doc__)
    args = parser.parse_args()
    env, workdir = lc.start(args.env, args.workdir, "liquid-account")
    ok = reissued(env, workdir)
    for ranks in (1, 2):
        ok = lost(env, workdir, ranks) and ok
    print("liquid account: %s (files in %s)" % ("PASS" if ok else "FAIL", workdir))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
