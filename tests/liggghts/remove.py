#!/usr/bin/env python3
"""Keyword remove of `cohesion capillary` in LIGGGHTS (Richefeu 2007 fig. 7, fig. 12: half of
the bonds removed, the water content kept): tests/lammps/test_remove.sh's assertions on its
scene (tests/liggghts/in.remove), Protocols 2 and 3, on 1 and 2 ranks.

2000 spheres (radii 0.45..0.55 mm) at rest on a lattice closer than the diameters (most
neighbours in contact), free liquid 1 % of the mean grain mass each, `start bridges`:
  - the run without remove has M bridges at step 0; with remove 0.5 remove_seed 7723 the
    model reports N of M removed, N within 4 standard deviations of M/2 (a binomial draw),
    and M - N bridges remain at step 0;
  - the removed liquid is handed on by the protocol: Protocol 2, every drop of it is free
    liquid at step 0 (to 1e-12 relative); Protocol 3, more liquid stays in bridges than the
    remaining bridges held before (the receivers grew); the total is conserved to 1e-12 at
    every step;
  - a removed pair in contact forms no bridge again while its contact lasts: few formations
    in the next 10 steps (< N / 5: new contacts as the packing relaxes), where without the
    mark every removed pair still in contact would form again from the liquid it released;
  - the same N, M and bridge counts at every step on 1 and 2 ranks;
  - the liquid starts once: a run after read_restart of the run that removed goes on from
    its bridges and free liquid (no distribution, no removal, a warning that says so);
  - the mark goes when the gap opens, within a run: two spheres in contact, their bridge
    removed at the start (remove 1), the second moved out of contact and back by fix move;
    no bridge while the first contact lasts (all liquid free), one from the first step of
    the new contact.

usage: remove.py LIGGGHTS_ENV [--workdir DIR] [--ranks 1,2]
"""
import math
import os
import re
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import liggghts_common as lc  # noqa: E402

LATTICE = (10, 10, 20)
SEED = 12345
SPACING = 0.95e-3          # closer than the diameters (0.9..1.1 mm): most pairs in contact
DENSITY = 2500.0
WATER = 0.01               # liquid mass over grain mass (1 %), liquid density 1000
REMOVE = "remove 0.5 remove_seed 7723"
STEPS = 10
TOLERANCE = 1e-12
# after read_restart: in.remove from its `neighbor` line on (the model, outputs and run)
SECOND_HEAD = """atom_modify     map array
communicate     single vel yes
processors      ${px} 1 1
read_restart    ${restart}
newton          off
"""
REMOVAL = re.compile(r"removed (\d+) of (\d+) bridges .*holding (\S+) of the liquid (\S+),")


def scene_data(path):
    """tests/lammps/lib.sh's scene_data (Park-Miller, the same numbers), at rest; returns
    {id: radius}."""
    nx, ny, nz = LATTICE
    state = [SEED]

    def rnd():
        state[0] = (16807 * state[0]) % 2147483647
        return state[0] / 2147483647

    def wrap(x, length):
        return x - length if x >= length else (x + length if x < 0 else x)

    radii, lines = {}, []
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                atom = len(radii) + 1
                d = 2 * (0.45e-3 + 0.1e-3 * rnd())
                x = wrap((i + 0.5) * SPACING + 0.02e-3 * (2 * rnd() - 1), nx * SPACING)
                y = wrap((j + 0.5) * SPACING + 0.02e-3 * (2 * rnd() - 1), ny * SPACING)
                z = wrap((k + 0.5) * SPACING + 0.02e-3 * (2 * rnd() - 1), nz * SPACING)
                radii[atom] = d / 2
                lines.append("%d 1 %.17g %r %.17g %.17g %.17g" % (atom, d, DENSITY, x, y, z))
    with open(path, "w") as f:
        f.write("capbridge granular scene: %d x %d x %d spheres\n\n" % LATTICE)
        f.write("%d atoms\n1 atom types\n\n" % len(radii))
        for n, axis in zip(LATTICE, "xyz"):
            f.write("0 %.17g %slo %shi\n" % (n * SPACING, axis, axis))
        f.write("\nAtoms\n\n" + "\n".join(lines) + "\n")
    return radii


def free_per_particle(radii):
    """WATER of the mean grain mass, as liquid volume (density 1000)."""
    mass = sum(4.0 / 3.0 * math.pi * r ** 3 * DENSITY for r in radii.values())
    return WATER * mass / 1000.0 / len(radii)


def run(env, workdir, name, liquid, free, ranks=1, deck=os.path.join(lc.HERE, "in.remove"),
        restart=None):
    """rows {step: (bridges, bridged, free, total, formed)} and the log; the run writes
    NAME.restart, and reads `restart` if given with its deck"""
    code, log = lc.liggghts(env, deck,
                            [("px", ranks), ("data", os.path.join(workdir, "scene.data")),
                             ("liquid", liquid), ("free", repr(free)), ("steps", STEPS),
                             ("local", name + ".local"),
                             ("restart", restart or name + ".restart")],
                            workdir, ranks=ranks, log="log." + name)
    if code != 0:
        lc.fail("%s: %s" % (name, lc.error_line(log) or log[-2000:]))
    rows = [r for r in lc.thermo_rows(log) if len(r) == 6]
    if len(rows) != STEPS + 1:
        lc.fail("%s: %d outputs, expected %d" % (name, len(rows), STEPS + 1))
    return {int(r[0]): tuple(float(v) for v in r[1:]) for r in rows}, log


def removal(log, name):
    """(N, M, removed liquid, total liquid) of the model's line"""
    found = REMOVAL.search(log)
    if not found:
        lc.fail("%s: no line 'removed N of M bridges ...' in the log" % name)
    return int(found.group(1)), int(found.group(2)), float(found.group(3)), float(found.group(4))


def check(label, rows, line, all_rows, protocol):
    """the assertions of test_remove.sh; returns the failures"""
    n, m_seen, removed, total = line
    m, bridged_all = all_rows[0][0], all_rows[0][1]
    bridges0, bridged0, free0 = rows[0][0], rows[0][1], rows[0][2]
    formed = sum(rows[s][4] for s in rows if s > 0)
    worst = max(abs(rows[s][3] - total) for s in rows) / total
    bad = []
    if m_seen != m:
        bad.append("the model saw %d bridges, the run without remove %d" % (m_seen, m))
    if abs(n - m / 2) > 4 * math.sqrt(m / 4):
        bad.append("removed %d of %d" % (n, m))
    if bridges0 != m - n:
        bad.append("%d bridges at step 0, expected %d - %d" % (bridges0, m, n))
    if protocol == "protocol2" and abs(free0 - removed) > TOLERANCE * removed:
        bad.append("free liquid %.17g at step 0, removed %.17g" % (free0, removed))
    if protocol == "protocol3" and not bridged0 > bridged_all - removed * (1 + TOLERANCE):
        bad.append("%.17g in bridges, no receiver grew (%.17g - %.17g)" % (
            bridged0, bridged_all, removed))
    if worst > TOLERANCE:
        bad.append("total liquid off by %.3g of it" % worst)
    if not formed < n / 5:
        bad.append("%d bridges formed in the %d steps after removing %d" % (formed, STEPS, n))
    print("%s: removed %d of %d bridges (%d at step 0), %d formed in the next %d steps, "
          "liquid within %.2e %s" % (label, n, m, bridges0, formed, STEPS, worst,
                                     "ok" if not bad else "FAIL: " + "; ".join(bad)))
    return bad


def check_restart(env, workdir, name, liquid, free, first):
    """a second run from the restart file of run `name`: it starts as `first` ended"""
    with open(os.path.join(lc.HERE, "in.remove")) as f:
        text = f.read()
    deck = os.path.join(workdir, "in.remove_second")
    with open(deck, "w") as f:
        f.write(SECOND_HEAD + text[text.index("neighbor "):])
    rows, log = run(env, workdir, name + "-second", liquid, free, deck=deck,
                    restart=name + ".restart")
    end, start = first[STEPS], rows[min(rows)]  # (the step goes on from the file)
    bad = []
    if REMOVAL.search(log):
        bad.append("bridges removed again")
    if "it has started (a restart file or an earlier pair_style): no bridge is removed" \
            not in " ".join(log.split()):
        bad.append("no warning that no bridge is removed")
    if start[0] != end[0] or abs(start[2] - end[2]) > TOLERANCE * end[3]:
        bad.append("%d bridges and free liquid %.17g, the first run ended with %d and %.17g"
                   % (start[0], start[2], end[0], end[2]))
    if abs(start[3] - end[3]) > TOLERANCE * end[3]:
        bad.append("total %.17g, before %.17g" % (start[3], end[3]))
    print("%s after read_restart: %d bridges, free liquid %.6g as the first run ended, "
          "nothing removed %s" % (name, start[0], start[2],
                                  "ok" if not bad else "FAIL: " + "; ".join(bad)))
    return bad


MARK_PERIOD, MARK_STEPS, OVERLAP, AMPLITUDE = 40, 30, 1e-6, 2e-6
MARK_DECK = """pair_style      gran model hooke/stiffness tangential history cohesion capillary &
                law richefeu liquid protocol2 vmax 1e-10 remove 1 remove_seed 1 tally on
pair_coeff      * *
timestep        1e-6
create_atoms    1 single 0 0 0 units box
create_atoms    1 single {x!r} 0 0 units box
set             atom * diameter 2e-3 density 2500
group           mover id 2
variable        dx equal {amplitude!r}*sin(2*PI*elapsed/{period})
fix             out_and_back mover move variable v_dx NULL NULL NULL NULL NULL
compute         ends all reduce sum f_bridgeCount
compute         free all reduce sum f_freeLiquid
thermo_style    custom step c_ends c_free
thermo_modify   format float %.17g norm no
thermo          1
run             {steps}
"""


def check_mark_goes(env, workdir):
    """the removed pair's mark, cleared when its gap opens in a pass of the run"""
    deck = os.path.join(workdir, "in.mark")
    with open(deck, "w") as f:
        f.write(lc.free_liquid_header(1, (-0.01, 0.01), 5e-4, 100, 0.5, 1e-11) +
                MARK_DECK.format(x=2e-3 - OVERLAP, amplitude=AMPLITUDE, period=MARK_PERIOD,
                                 steps=MARK_STEPS))
    code, log = lc.liggghts(env, deck, [], workdir, log="log.mark")
    if code != 0:
        lc.fail("mark: %s" % (lc.error_line(log) or log[-2000:]))
    ends = {int(r[0]): float(r[1]) for r in lc.thermo_rows(log) if len(r) == 3}
    gap = {n: -OVERLAP + AMPLITUDE * math.sin(2 * math.pi * n / MARK_PERIOD) for n in ends}
    opened = min(n for n in gap if gap[n] > 0)
    again = min(n for n in gap if n > opened and gap[n] <= 0)
    bad = []
    if not REMOVAL.search(log) or REMOVAL.search(log).group(1) != "1":
        bad.append("the bridge was not removed at the start")
    if any(ends[n] != 0 for n in ends if n < again):
        bad.append("a bridge before the new contact: %s" % [n for n in ends if ends[n]])
    if any(ends[n] != 2 for n in ends if n >= again):
        bad.append("no bridge at the new contact (steps %d on): %s" % (
            again, [ends[n] for n in sorted(ends) if n >= again]))
    print("mark: the removed pair dry in its contact (steps 0-%d) and apart (%d-%d), a "
          "bridge from the new contact at step %d on %s" % (
              opened - 1, opened, again - 1, again, "ok" if not bad else
              "FAIL: " + "; ".join(bad)))
    return bad


def main():
    parser = lc.argument_parser(__doc__)
    parser.add_argument("--ranks", default="1,2")
    args = parser.parse_args()
    env, workdir = lc.start(args.env, args.workdir, "remove")
    free = free_per_particle(scene_data(os.path.join(workdir, "scene.data")))
    failures = check_mark_goes(env, workdir)
    for protocol in ("protocol2", "protocol3"):
        all_rows, _ = run(env, workdir, protocol + "-all", protocol, free)
        counts = {}
        for ranks in [int(r) for r in args.ranks.split(",")]:
            name = "%s-np%d" % (protocol, ranks)
            rows, log = run(env, workdir, name, protocol + " " + REMOVE, free, ranks)
            line = removal(log, name)
            failures += check("%s np %d" % (protocol, ranks), rows, line, all_rows, protocol)
            counts[ranks] = (line[:2], [rows[s][0] for s in sorted(rows)])
            if ranks == 1:
                failures += check_restart(env, workdir, name, protocol + " " + REMOVE, free,
                                          rows)
        for a, b in zip(sorted(counts), sorted(counts)[1:]):
            same = counts[a] == counts[b]
            print("%s: N, M and the bridges at every step on %d and %d ranks %s" % (
                protocol, a, b, "the same ok" if same else "differ FAIL: %s, %s" % (
                    counts[a], counts[b])))
            if not same:
                failures.append("%s ranks %d, %d" % (protocol, a, b))
    print("remove: %s (files in %s)" % ("PASS" if not failures else "FAIL", workdir))
    return 0 if not failures else 1


if __name__ == "__main__":
    sys.exit(main())
