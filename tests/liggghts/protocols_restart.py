#!/usr/bin/env python3
"""Protocols 1, 2, 3 across write_restart / read_restart (tests/liggghts/in.protocols).

The wet run of liggghts_protocols (320 spheres, 1 nl each) for 1500 steps, a restart file,
and a second LIGGGHTS process that reads it and runs 1500 steps more (its deck sets the
time step again: LIGGGHTS 3.8's read_restart does not restore it), on 1 and 2 ranks.
Checked, for each protocol:
  - the total liquid (free + bridges) is 320 nl to 1e-12 relative at every step of both
    runs: the bridges come back from the contact history, the free liquid from fix
    property/atom freeLiquid (the same fix ID);
  - Protocols 2, 3: the second run starts with the bridges and the free liquid the first
    ended with (the same numbers); Protocol 1 distributes the liquid again at the first run
    after read_restart (LIGGGHTS keeps no state of a contact model in restart files), which
    puts all free liquid in bridges at that step;
  - bridges still form and rupture in the second run.

usage: protocols_restart.py LIGGGHTS_ENV [--workdir DIR] [--ranks 1,2]
"""
import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import liggghts_common as lc  # noqa: E402

TOLERANCE = 1e-12
HALF = 1500
TOTAL = 320 * 1e-12
VMAX = 1e-11
# the deck's model, outputs and run (from its `neighbor` line on), after read_restart
SECOND_HEAD = """atom_modify     map array
communicate     single vel yes
processors      ${px} 1 1
read_restart    protocols.restart
newton          off
"""


def decks(workdir):
    with open(os.path.join(lc.HERE, "in.protocols")) as f:
        text = f.read()
    model = text[text.index("neighbor "):]
    first = os.path.join(workdir, "in.first")
    with open(first, "w") as f:
        f.write(text + "write_restart   protocols.restart\n")
    second = os.path.join(workdir, "in.second")
    with open(second, "w") as f:
        # the per-atom free liquid comes back to the fix of the same ID; its default is unused
        f.write(SECOND_HEAD + model)
    return first, second


def run(env, deck, sub, liquid, ranks, name):
    code, log = lc.liggghts(env, deck, [("px", ranks), ("steps", HALF), ("every", 1),
                                        ("liquid", lc.liquid_words(liquid)), ("vmax", VMAX)],
                            sub, ranks=ranks, log="log." + name)
    if code != 0:
        lc.fail("%s %s on %d rank(s): %s" % (liquid, name, ranks,
                                             lc.error_line(log) or log[-2000:]))
    rows = [r for r in lc.thermo_rows(log) if len(r) == 5]
    if len(rows) != HALF + 1:
        lc.fail("%s %s on %d rank(s): %d outputs, expected %d" % (liquid, name, ranks,
                                                                 len(rows), HALF + 1))
    return {int(r[0]): tuple(float(v) for v in r[1:]) for r in rows}


def check(first, second, liquid, ranks):
    worst = max(abs(row[2] - TOTAL) for rows in (first, second) for row in rows.values())
    worst /= TOTAL
    steps = sorted(second)
    bridges = [second[s][3] for s in steps]
    rose = sum(1 for a, b in zip(bridges, bridges[1:]) if b > a)
    fell = sum(1 for a, b in zip(bridges, bridges[1:]) if b < a)
    end, start = first[HALF], second[HALF]
    if liquid == "protocol1":
        resumed = start[0] == 0.0
        what = "distributed again at the restart (free liquid %g -> %g)" % (end[0], start[0])
    else:
        # (the sums over the atoms may round otherwise: the atoms are in another order)
        resumed = start[3] == end[3] and all(abs(a - b) <= TOLERANCE * TOTAL
                                             for a, b in zip(start[:3], end[:3]))
        what = "resumed with the same bridges (%d) and free liquid (%.17g, before %.17g)" % (
            start[3], start[0], end[0])
    ok = worst <= TOLERANCE and resumed and rose > 0 and fell > 0 and steps[0] == HALF
    print("%s, %d rank(s): liquid within %.2e of 320 nl at every step of both runs "
          "(tolerance %g); %s; second run: bridges rose at %d steps, fell at %d %s" % (
              liquid, ranks, worst, TOLERANCE, what, rose, fell, "ok" if ok else "FAIL"))
    return ok


def main():
    parser = lc.argument_parser(__doc__)
    parser.add_argument("--ranks", default="1,2")
    args = parser.parse_args()
    env, workdir = lc.start(args.env, args.workdir, "protocols_restart")
    ok = True
    for liquid in ("protocol1", "protocol2", "protocol3"):
        for ranks in [int(r) for r in args.ranks.split(",")]:
            sub = os.path.join(workdir, "%s.%d" % (liquid, ranks))
            os.makedirs(sub, exist_ok=True)
            first_deck, second_deck = decks(sub)
            first = run(env, first_deck, sub, liquid, ranks, "first")
            second = run(env, second_deck, sub, liquid, ranks, "second")
            ok = check(first, second, liquid, ranks) and ok
    print("protocols across a restart: %s (files in %s)" % ("PASS" if ok else "FAIL",
                                                            workdir))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
