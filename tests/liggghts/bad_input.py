#!/usr/bin/env python3
"""Bad input for `cohesion capillary`: each case must stop LIGGGHTS with an ERROR line
that names the problem; plus a fix wall/gran with `cohesion capillary` and no law (its
bridges need one: refused, naming the fix; tests/liggghts/wall.py has the wet walls); and a bridge too small for LIGGGHTS's reach test, whose
error must give a volume and a contact distance factor that work (both are run); and
Protocol 1 with two atom types: refused when their contact angles differ (one law, one
alpha: Richefeu eqs. 13-14), run when they are equal; fix capillaryRemove (the removal
request) with a bad value defined between two runs: refused at the second run's init.

usage: bad_input.py LIGGGHTS_ENV [--workdir DIR]
"""
import os
import re
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import liggghts_common as lc  # noqa: E402

# The box and the contact properties every deck shares; {zlo}, {newton}, {props} filled in.
HEADER = """units           si
atom_style      granular
atom_modify     map array
boundary        {boundary}
newton          {newton}
communicate     single vel yes
region          box block {xlo} {xhi} -0.01 0.01 {zlo} 0.01 units box
create_box      1 box
neighbor        5e-4 bin
neigh_modify    delay 0
fix m1 all property/global kn peratomtypepair 1 1000
fix m2 all property/global kt peratomtypepair 1 1000
fix m3 all property/global gamman peratomtypepair 1 0
fix m4 all property/global gammat peratomtypepair 1 0
fix m5 all property/global coefficientFriction peratomtypepair 1 0.5
{props}
"""

# Two touching spheres; {pair} is filled in per case.
DECK = """pair_style      gran model hooke/stiffness tangential history cohesion {pair}
pair_coeff      * *
timestep        1e-6
create_atoms    1 single 0 0 0 units box
create_atoms    1 single 2e-3 0 0 units box
set             atom * diameter 2e-3 density 2500
fix             integrate all nve/sphere
run             10
"""
GAMMA = "fix m6 all property/global surfaceTension scalar 0.0728"
THETA = "fix m7 all property/global contactAngle peratomtype 10"
VOLUME = "fix m8 all property/global bridgeVolume peratomtypepair 1 1e-11"
FREE = "fix freeLiquid all property/atom freeLiquid scalar yes yes no 1e-11"
ALL = "\n".join([GAMMA, THETA, VOLUME])
REQUEST = "fix remove all property/global capillaryRemove vector %s"

# (name, properties, pair_style words after `cohesion`, newton, words the ERROR must hold)
CASES = [
    ("missing surfaceTension", "\n".join([THETA, VOLUME]), "capillary law willett", "off",
     ["surfaceTension"]),
    ("missing contactAngle", "\n".join([GAMMA, VOLUME]), "capillary law willett", "off",
     ["contactAngle"]),
    ("missing bridgeVolume", "\n".join([GAMMA, THETA]), "capillary law willett", "off",
     ["bridgeVolume"]),
    ("unknown law", ALL, "capillary law foo", "off",
     ["law 'foo'", "richefeu", "willett/reduced", "table"]),
    ("no law given", ALL, "capillary", "off", ["law NAME", "richefeu"]),
    # the last word of the command: what follows in LIGGGHTS's argument array is an earlier
    # command's, not a value
    ("a keyword without its value", ALL, "capillary law", "off", ["keyword 'law' needs a value"]),
    # on/off keywords as the last word: LIGGGHTS's own on/off reader aborted (SIGABRT)
    ("tally as the last word", ALL, "capillary law willett tally", "off",
     ["keyword 'tally' needs a value", "allowed: on, off"]),
    # removed (it counted the attraction twice in the Coulomb limit): refused also without a
    # value (friction.py: with each value)
    ("capillary_friction as the last word", ALL, "capillary law willett capillary_friction",
     "off", ["keyword 'capillary_friction' was removed", "delete the keyword"]),
    ("tally with another word", ALL, "capillary law willett tally yes", "off",
     ["tally 'yes'", "allowed: on, off"]),
    ("a keyword given twice", ALL, "capillary law willett law richefeu", "off",
     ["keyword 'law' is given twice"]),
    ("unknown rupture rule", ALL, "capillary law willett rupture bar", "off",
     ["rupture 'bar'", "lian"]),
    ("unknown liquid protocol", ALL, "capillary law willett liquid protocol7", "off",
     ["liquid 'protocol7'", "protocol2"]),
    ("rupture exact for a closed-form law", ALL, "capillary law willett rupture exact", "off",
     ["rupture 'exact'", "allowed lian, willett, willett/unequal, default"]),
    ("richefeu_c for another law", ALL, "capillary law willett richefeu_c 0.8", "off",
     ["'c'", "richefeu only"]),
    # a law's own keyword, registered from the core's rows as law + "_" + keyword: refused
    # for another law by the name the user gave, and its value read by the core's row
    ("a law keyword of another law, by its name", ALL, "capillary law table richefeu_c 0.8",
     "off", ["keyword 'richefeu_c'", "applies to law richefeu only, not to table"]),
    ("richefeu_c not > 0", ALL, "capillary law richefeu richefeu_c 0", "off",
     ["keyword 'richefeu_c'", "c '0'", "> 0"]),
    ("contact angle of 95 degrees",
     "\n".join([GAMMA, "fix m7 all property/global contactAngle peratomtype 95", VOLUME]),
     "capillary law willett", "off", ["contactAngle", "95", "90"]),
    ("negative surface tension",
     "\n".join(["fix m6 all property/global surfaceTension scalar -0.07", THETA, VOLUME]),
     "capillary law willett", "off", ["surfaceTension", "-0.07"]),
    ("negative bridgeVolume",
     "\n".join([GAMMA, THETA, "fix m8 all property/global bridgeVolume peratomtypepair 1 -1e-11"]),
     "capillary law willett", "off", ["bridgeVolume", "-1e-11"]),
    ("protocol2 without freeLiquid", ALL, "capillary law willett liquid protocol2", "off",
     ["freeLiquid"]),
    ("freeLiquid not sent to ghosts",
     ALL + "\nfix freeLiquid all property/atom freeLiquid scalar yes no no 1e-11",
     "capillary law willett liquid protocol2", "off", ["freeLiquid", "ghost"]),
    ("periodic box narrower than twice the cutoff", ALL, "capillary law willett", "off",
     ["periodic box is 0.005 wide along x", "twice the neighbor cutoff"]),
    ("vmax with liquid fixed", ALL, "capillary law willett vmax 1e-11", "off",
     ["keyword 'vmax' applies to 'liquid protocol1', 'protocol2' and 'protocol3' only",
      "bridgeVolume"]),
    ("every with liquid protocol2", ALL + "\n" + FREE,
     "capillary law willett liquid protocol2 every 10", "off",
     ["keyword 'every' applies to 'liquid protocol1' only"]),
    ("vmax not a volume", ALL + "\n" + FREE, "capillary law willett liquid protocol3 vmax -1",
     "off", ["vmax '-1'", "a volume > 0"]),
    ("every not a whole number", ALL + "\n" + FREE,
     "capillary law willett liquid protocol1 every 2.5", "off",
     ["every '2.5'", "whole number >= 0"]),
    # the two spheres' 2e-11 m^3 in one bridge, above the volume the reach is built for
    ("Protocol 1 beyond vmax", ALL + "\n" + FREE,
     "capillary law willett liquid protocol1 vmax 1e-11", "off",
     ["Protocol 1 gives alpha", "give a larger 'vmax' (at least 2e-11)"]),
    # start, remove, remove_seed: the refusals of LAMMPS's fix capillary/liquid
    ("remove with liquid protocol1", ALL + "\n" + FREE,
     "capillary law willett liquid protocol1 remove 0.5 remove_seed 7", "off",
     ["keyword 'remove' applies to 'liquid protocol2' and 'protocol3' only",
      "Protocol 1 gives every eligible pair a bridge again"]),
    ("remove with liquid fixed", ALL, "capillary law willett remove 0.5 remove_seed 7", "off",
     ["keyword 'remove' applies to 'liquid protocol2' and 'protocol3' only",
      "fixed volumes keep no water content"]),
    ("remove with start free", ALL + "\n" + FREE,
     "capillary law willett liquid protocol2 start free remove 0.5 remove_seed 7", "off",
     ["keyword 'remove' needs 'start bridges'", "no bridge exists when the liquid starts"]),
    ("remove above 1", ALL + "\n" + FREE,
     "capillary law willett liquid protocol3 remove 1.5 remove_seed 7", "off",
     ["remove '1.5'", "must be > 0 and <= 1"]),
    ("remove 0", ALL + "\n" + FREE,
     "capillary law willett liquid protocol2 remove 0 remove_seed 7", "off",
     ["remove '0'", "must be > 0 and <= 1"]),
    ("remove_seed 0", ALL + "\n" + FREE,
     "capillary law willett liquid protocol2 remove 0.5 remove_seed 0", "off",
     ["remove_seed '0'", "whole number >= 1"]),
    ("remove without remove_seed", ALL + "\n" + FREE,
     "capillary law willett liquid protocol2 remove 0.5", "off",
     ["keyword 'remove' needs 'remove_seed S'"]),
    ("remove_seed without remove", ALL + "\n" + FREE,
     "capillary law willett liquid protocol2 remove_seed 7", "off",
     ["keyword 'remove_seed' applies with 'remove F' only"]),
    ("start with liquid protocol1", ALL + "\n" + FREE,
     "capillary law willett liquid protocol1 start bridges", "off",
     ["keyword 'start' applies to 'liquid protocol2' and 'protocol3' only"]),
    ("unknown start", ALL + "\n" + FREE, "capillary law willett liquid protocol2 start all",
     "off", ["start 'all'", "allowed: bridges, free"]),
    # fix capillaryRemove, the removal asked for between runs (checked at each run's init):
    # the keyword's refusals, and the removal given once
    ("removal request with liquid protocol1", ALL + "\n" + FREE + "\n" + REQUEST % "0.5 7",
     "capillary law willett liquid protocol1", "off",
     ["fix property/global capillaryRemove", "applies to 'liquid protocol2' and 'protocol3' "
      "only", "Protocol 1 gives every eligible pair a bridge again"]),
    ("removal request with liquid fixed", ALL + "\n" + REQUEST % "0.5 7",
     "capillary law willett", "off",
     ["fix property/global capillaryRemove", "applies to 'liquid protocol2' and 'protocol3' "
      "only", "fixed volumes keep no water content"]),
    ("removal request F above 1", ALL + "\n" + FREE + "\n" + REQUEST % "1.5 7",
     "capillary law willett liquid protocol2", "off",
     ["capillaryRemove", "F = 1.5", "must be > 0 and <= 1"]),
    ("removal request F 0", ALL + "\n" + FREE + "\n" + REQUEST % "0 7",
     "capillary law willett liquid protocol3", "off",
     ["capillaryRemove", "F = 0", "must be > 0 and <= 1"]),
    ("removal request seed 2.5", ALL + "\n" + FREE + "\n" + REQUEST % "0.5 2.5",
     "capillary law willett liquid protocol2", "off",
     ["capillaryRemove", "S = 2.5", "whole number >= 1"]),
    ("removal request seed 0", ALL + "\n" + FREE + "\n" + REQUEST % "0.5 0",
     "capillary law willett liquid protocol2 start free", "off",
     ["capillaryRemove", "S = 0", "whole number >= 1"]),
    ("removal request of one value", ALL + "\n" + FREE + "\n" + REQUEST % "0.5",
     "capillary law willett liquid protocol2", "off",
     ["capillaryRemove", "must be a vector of 2 values, F S"]),
    ("removal request and keyword remove", ALL + "\n" + FREE + "\n" + REQUEST % "0.5 7",
     "capillary law willett liquid protocol2 remove 0.5 remove_seed 7", "off",
     ["capillaryRemove", "keyword 'remove' are both given", "give the removal once"]),
    # viscous on: its two properties, checked like the others
    ("viscous on without liquidViscosity", ALL, "capillary law willett viscous on", "off",
     ["liquidViscosity"]),
    ("negative liquidViscosity",
     ALL + "\nfix m9 all property/global liquidViscosity peratomtypepair 1 -0.1"
     "\nfix m10 all property/global viscousMinGap peratomtypepair 1 1e-7",
     "capillary law willett viscous on", "off", ["liquidViscosity", "-0.1", ">= 0"]),
    ("viscousMinGap 0 with a viscosity",
     ALL + "\nfix m9 all property/global liquidViscosity peratomtypepair 1 0.5"
     "\nfix m10 all property/global viscousMinGap peratomtypepair 1 0",
     "capillary law willett viscous on", "off", ["viscousMinGap", "> 0", "0.5 Pa s"]),
    ("viscous with another word", ALL, "capillary law willett viscous yes", "off",
     ["viscous 'yes'", "allowed: on, off"]),
    ("viscous as the last word", ALL, "capillary law willett viscous", "off",
     ["keyword 'viscous' needs a value", "allowed: on, off"]),
    ("volume outside the validity, validity strict",
     "\n".join([GAMMA, THETA, "fix m8 all property/global bridgeVolume peratomtypepair 1 1e-8"]),
     "capillary law willett validity strict", "off",
     ["bridgeVolume", "willett", "validity strict"]),
]

# One sphere on a wall whose `cohesion capillary` has no law.
WALL_DECK = """pair_style      gran model hooke/stiffness tangential history cohesion capillary law willett
pair_coeff      * *
fix             floor all wall/gran model hooke/stiffness tangential history &
                cohesion capillary primitive type 1 zplane 0.0
timestep        1e-6
# one sphere of radius 1 mm overlapping the floor by 1 micrometre
create_atoms    1 single 0 0 0.999e-3 units box
set             atom * diameter 2e-3 density 2500
fix             integrate all nve/sphere
variable        fz equal fz[1]
thermo_style    custom step v_fz
thermo_modify   format float %.17g
thermo          1
run             1
"""


# Two spheres overlapping by 1 um, Protocol 2 with {free} m^3 of free liquid each: the bridge
# forms in the setup pass and is checked against the reach (contact distance factor)
TINY_DECK = """fix freeLiquid all property/atom freeLiquid scalar yes yes no {free!r}
pair_style      gran model hooke/stiffness tangential history cohesion capillary &
                law willett liquid protocol2 start free tally on
pair_coeff      * *
{neigh}
timestep        1e-6
create_atoms    1 single 0 0 0 units box
create_atoms    1 single 1.999e-3 0 0 units box
set             atom * diameter 2e-3 density 2500
fix             integrate all nve/sphere
compute         bridged all reduce sum f_bridgedLiquid
thermo_style    custom step c_bridged
thermo_modify   format float %.17g norm no
run             0
"""


def request_between_runs(env, workdir):
    """fix capillaryRemove defined after a first run (liquid fixed, F 2): refused at the
    init of the second run, after the first ran (its thermo output)"""
    deck = os.path.join(workdir, "in.request_between_runs")
    with open(deck, "w") as f:
        f.write(HEADER.format(boundary="f f f", xlo=-0.01, xhi=0.01, zlo=-0.01, newton="off",
                              props=ALL + "\n" + FREE) +
                DECK.format(pair="capillary law willett liquid protocol2") +
                REQUEST % "2 7" + "\nrun             10\n")
    code, log = lc.liggghts(env, deck, [], workdir, log="log.request_between_runs")
    line = lc.error_line(log)
    good = (code != 0 and line is not None and "F = 2" in line and
            "capillaryRemove" in line and log.count("Loop time") == 1)
    print("%-45s %s\n    %s" % ("removal request F 2, defined between runs",
                                "ok" if good else "FAIL (exit %d)" % code,
                                line or "no ERROR line"))
    return good


def tiny_volume(env, workdir):
    """A bridge far too small for the reach test (1e-300 m^3 per particle): the error must
    name a smallest volume and a factor that work, not the factor in use.  Both are run:
    with that volume (half per particle), and with 1e-300 and that factor, the bridge forms
    (its liquid, read back, is what the particles gave) and the run ends normally."""
    def run(name, free, neigh):
        deck = os.path.join(workdir, "in." + name)
        with open(deck, "w") as f:
            f.write(HEADER.format(boundary="f f f", xlo=-0.01, xhi=0.01, zlo=-0.01,
                                  newton="off", props="\n".join([GAMMA, THETA])) +
                    TINY_DECK.format(free=free, neigh=neigh))
        return lc.liggghts(env, deck, [], workdir, log="log." + name)

    code, log = run("tiny", 1e-300, "")
    line = lc.error_line(log) or ""
    volume = re.search(r"Give at least (\S+) m\^3 per bridge", line)
    factor = re.search(r"'neigh_modify contact_distance_factor (\S+)'", line)
    good = (code != 0 and "too small" in line and volume is not None and factor is not None
            and float(factor.group(1)) > 1.0)
    print("%-45s %s\n    %s" % ("bridge too small for the reach test",
                                "ok" if good else "FAIL (exit %d)" % code,
                                line or "no ERROR line"))
    if not good:
        return False
    ok = True
    smallest = float(volume.group(1))
    for name, free, neigh, bridge in [
            ("tiny_smallest", smallest / 2, "", smallest),
            ("tiny_factor", 1e-300, "neigh_modify contact_distance_factor " + factor.group(1),
             2e-300)]:
        code, log = run(name, free, neigh)
        rows = lc.thermo_rows(log)
        held = float(rows[0][1]) if code == 0 and len(rows) == 1 else float("nan")
        good = abs(held - bridge) <= 1e-12 * bridge
        ok = ok and good
        print("%-45s %s\n    %s" % (
            "  followed: freeLiquid %g, %s" % (free, neigh or "default factor"),
            "ok" if good else "FAIL (exit %d)" % code,
            "bridge of %.6g m^3 formed (expected %.6g)" % (held, bridge) if code == 0
            else lc.error_line(log) or "exit %d" % code))
    return ok


# Two atom types, one sphere of each, touching; contact angles {angles}, Protocol 1
TWO_TYPES_DECK = """units           si
atom_style      granular
atom_modify     map array
boundary        f f f
newton          off
communicate     single vel yes
region          box block -0.01 0.01 -0.01 0.01 -0.01 0.01 units box
create_box      2 box
neighbor        5e-4 bin
neigh_modify    delay 0
fix m1 all property/global kn peratomtypepair 2 1000 1000 1000 1000
fix m2 all property/global kt peratomtypepair 2 1000 1000 1000 1000
fix m3 all property/global gamman peratomtypepair 2 0 0 0 0
fix m4 all property/global gammat peratomtypepair 2 0 0 0 0
fix m5 all property/global coefficientFriction peratomtypepair 2 0.5 0.5 0.5 0.5
{gamma}
fix m7 all property/global contactAngle peratomtype {angles}
{free}
pair_style      gran model hooke/stiffness tangential history cohesion capillary &
                law willett liquid {liquid} tally on
pair_coeff      * *
timestep        1e-6
create_atoms    1 single 0 0 0 units box
create_atoms    2 single 1.999e-3 0 0 units box
set             atom * diameter 2e-3 density 2500
compute         bridged all reduce sum f_bridgedLiquid
thermo_style    custom step c_bridged
thermo_modify   format float %.17g norm no
run             0
"""


def protocol1_two_angles(env, workdir):
    """Protocol 1 distributes with one law (one alpha over all pairs, Richefeu eqs. 13-14):
    types of contact angles 10 and 20 degrees (pairs of 10, 15 and 20) are refused with the
    angles named and what is allowed; types of 10 and 10 run (the bridge holds both
    spheres' 2e-11 m^3).  So is Protocol 2's start bridges (Protocol 1 once), not its start
    free (a law per pair)."""
    ok = True
    for liquid, angles, refused in (("protocol1", "10 20", "liquid protocol1"),
                                    ("protocol1", "10 10", None),
                                    ("protocol2", "10 20",
                                     "liquid protocol2 with 'start bridges'"),
                                    ("protocol2 start free", "10 20", None)):
        name = "%s_angles_%s" % (liquid.replace(" ", "_"), angles.replace(" ", "_"))
        deck = os.path.join(workdir, "in." + name)
        with open(deck, "w") as f:
            f.write(TWO_TYPES_DECK.format(gamma=GAMMA, angles=angles, free=FREE,
                                          liquid=liquid))
        code, log = lc.liggghts(env, deck, [], workdir, log="log." + name)
        line = lc.error_line(log)
        if refused:
            words = [refused + " needs one contact angle", "10, 15, 20 degrees",
                     "the same contactAngle", "liquid protocol2 or protocol3"]
            good = code != 0 and line is not None and all(w in line for w in words)
            detail = line or "no ERROR line"
        else:
            rows = lc.thermo_rows(log)
            held = float(rows[0][1]) if code == 0 and len(rows) == 1 else float("nan")
            good = abs(held - 2e-11) <= 1e-12 * 2e-11
            detail = ("bridge of %.6g m^3 (expected 2e-11)" % held if code == 0
                      else line or "exit %d" % code)
        ok = ok and good
        print("%-45s %s\n    %s" % (liquid + ", contact angles " + angles,
                                    "ok" if good else "FAIL (exit %d)" % code, detail))
    return ok


def main():
    parser = lc.argument_parser(__doc__)
    args = parser.parse_args()
    env, workdir = lc.start(args.env, args.workdir, "bad")
    ok = True
    for k, (name, props, pair, newton, words) in enumerate(CASES):
        deck = os.path.join(workdir, "in.bad%02d" % k)
        narrow = name.startswith("periodic box")    # 5 mm along x, periodic
        with open(deck, "w") as f:
            f.write(HEADER.format(boundary="p f f" if narrow else "f f f",
                                  xlo=-0.0025 if narrow else -0.01,
                                  xhi=0.0025 if narrow else 0.01, zlo=-0.01, newton=newton,
                                  props=props) + DECK.format(pair=pair))
        code, log = lc.liggghts(env, deck, [], workdir, log="log.bad%02d" % k)
        line = lc.error_line(log)
        good = code != 0 and line is not None and all(w in line for w in words)
        ok = ok and good
        print("%-45s %s\n    %s" % (name, "ok" if good else "FAIL (exit %d)" % code,
                                    line or "no ERROR line"))

    # a wall's bridges need a law, as a pair's: refused, naming fix wall/gran
    deck = os.path.join(workdir, "in.wall")
    with open(deck, "w") as f:
        f.write(HEADER.format(boundary="f f f", xlo=-0.01, xhi=0.01, zlo=-0.001, newton="off",
                              props=ALL) + WALL_DECK)
    code, log = lc.liggghts(env, deck, [], workdir, log="log.wall")
    line = lc.error_line(log)
    good = code != 0 and line is not None and \
        all(w in line for w in ("needs 'law NAME'", "in fix wall/gran"))
    ok = ok and good
    print("%-45s %s\n    %s" % ("wall without a law", "ok" if good else "FAIL (exit %d)" % code,
                                line or "no ERROR line"))
    ok = request_between_runs(env, workdir) and ok
    ok = tiny_volume(env, workdir) and ok
    ok = protocol1_two_angles(env, workdir) and ok
    print("bad input: %s (files in %s)" % ("PASS" if ok else "FAIL", workdir))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
