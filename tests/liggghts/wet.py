#!/usr/bin/env python3
"""A wet granular run under Protocol 2 (tests/liggghts/in.wet) on 1 and 2 ranks.

320 spheres of two sizes, periodic box, 3000 steps. Checks, on every rank count:
  - the total liquid (free + in bridges) equals its initial value to 1e-12 relative at
    every thermo output;
  - bridges formed and some ruptured (free liquid went down and, at least once, up);
and across rank counts: the number of bridges is the same at every output of the first
1500 steps (the initial state is the same; trajectories only differ by round-off).  Between
`run 0` and the run the deck sets the free liquid of type 2 from 1 to 2 nl: the model's
between-run check warns once, with the change, N(type 2) x 1 nl.

usage: wet.py LIGGGHTS_ENV [--workdir DIR] [--ranks 1,2]
"""
import os
import re
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import liggghts_common as lc  # noqa: E402

TOLERANCE = 1e-12
STEPS = 3000
EVERY = 100
COMPARE_UNTIL = 1500


def run(env, ranks, workdir, law):
    code, log = lc.liggghts(env, os.path.join(lc.HERE, "in.wet"),
                            [("px", ranks), ("steps", STEPS), ("every", EVERY), ("law", law)],
                            workdir, ranks=ranks, log="log.wet.%d" % ranks)
    if code != 0:
        lc.fail("wet run on %d rank(s): %s" % (ranks, lc.error_line(log) or log[-2000:]))
    changes = re.findall(r"WARNING: cohesion model capillary: the liquid changed by (\S+)", log)
    type2 = re.search(r"(\d+) settings made for type/fraction", log)
    expected = int(type2.group(1)) * 1e-12 if type2 else float("nan")
    if len(changes) != 1 or not abs(float(changes[0]) - expected) <= 1e-9 * expected:
        lc.fail("wet run on %d rank(s): between-run warnings %s, expected one of %.6e m^3" % (
            ranks, changes, expected))
    print("wet run, %d rank(s): the free liquid set between the runs is reported: %s m^3 "
          "(%d x 1 nl)" % (ranks, changes[0], round(expected / 1e-12)))
    rows = lc.thermo_rows(log)
    # the first block is `run 0`; the second the run itself
    rows = [r for r in rows if len(r) == 5]
    series = {}
    for r in rows:
        series[int(r[0])] = (float(r[1]), float(r[2]), float(r[3]), float(r[4]))
    if len(series) != STEPS // EVERY + 1:
        lc.fail("wet run on %d rank(s): %d outputs, expected %d" % (
            ranks, len(series), STEPS // EVERY + 1))
    return series


def check(series, ranks):
    steps = sorted(series)
    total0 = series[steps[0]][2]
    worst = 0.0
    for s in steps:
        free, bridged, total, _ = series[s]
        worst = max(worst, abs(total - total0) / total0)
    frees = [series[s][0] for s in steps]
    rises = sum(1 for a, b in zip(frees, frees[1:]) if b > a)
    bridges = [series[s][3] for s in steps]
    ok = worst <= TOLERANCE and max(bridges) > 0 and min(frees) < frees[0] and rises > 0
    print("wet run, %d rank(s): total liquid %.6e m^3, largest relative change %.2e "
          "(tolerance %g); bridges at the end %d (max %d); free liquid %.3e -> %.3e, rose "
          "between %d of %d outputs (ruptures) %s" % (
              ranks, total0, worst, TOLERANCE, bridges[-1], max(bridges), frees[0],
              frees[-1], rises, len(frees) - 1, "ok" if ok else "FAIL"))
    return ok


def main():
    parser = lc.argument_parser(__doc__)
    parser.add_argument("--ranks", default="1,2")
    parser.add_argument("--law", default="willett")
    args = parser.parse_args()
    env, workdir = lc.start(args.env, args.workdir, "wet")
    ok = True
    results = {}
    for ranks in [int(r) for r in args.ranks.split(",")]:
        results[ranks] = run(env, ranks, workdir, args.law)
        ok = check(results[ranks], ranks) and ok
    counts = sorted(results)
    for a, b in zip(counts, counts[1:]):
        differ = [s for s in sorted(results[a]) if s <= COMPARE_UNTIL
                  and results[a][s][3] != results[b][s][3]]
        same_all = all(results[a][s][3] == results[b][s][3] for s in results[a])
        print("bridges on %d and %d ranks: %s up to step %d%s" % (
            a, b, "the same" if not differ else "differ at steps %s" % differ[:5],
            COMPARE_UNTIL, " (and to the end, step %d)" % STEPS if same_all else ""))
        ok = ok and not differ
    print("wet run: %s (files in %s)" % ("PASS" if ok else "FAIL", workdir))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
