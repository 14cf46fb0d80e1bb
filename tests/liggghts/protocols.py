#!/usr/bin/env python3
"""Richefeu 2007's Protocols 1, 2 and 3 in LIGGGHTS (tests/liggghts/in.protocols) on 1, 2
and 3 ranks.

320 spheres of two sizes thrown at each other in a periodic box, 1 nl of free liquid each,
3000 steps, the liquid at every step. Checks, for each protocol and rank count:
  - the total liquid (free + in bridges) equals its initial value, 320 nl, to 1e-12
    relative at every step;
  - bridges formed and ruptured: the number of bridges rose and fell between steps;
  - Protocol 1 put all liquid in bridges at the start (no free liquid at step 0), and a
    broken bridge's liquid became free liquid until the next distribution (free liquid > 0
    at some step);
and across rank counts: the same number of bridges at every step of the first 1500 (the
initial state is the same; the trajectories differ only by round-off).

usage: protocols.py LIGGGHTS_ENV [--workdir DIR] [--ranks 1,2,3]
"""
import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import liggghts_common as lc  # noqa: E402

TOLERANCE = 1e-12
STEPS = 3000
COMPARE_UNTIL = 1500
TOTAL = 320 * 1e-12       # 320 particles of 1 nl
VMAX = 1e-11              # the reach for Protocol 1's first alpha (a few pairs within reach)


def run(env, workdir, liquid, ranks):
    code, log = lc.liggghts(env, os.path.join(lc.HERE, "in.protocols"),
                            [("px", ranks), ("steps", STEPS), ("every", 1), ("liquid", lc.liquid_words(liquid)),
                             ("vmax", VMAX)],
                            workdir, ranks=ranks, log="log.%s.%d" % (liquid, ranks))
    if code != 0:
        lc.fail("%s on %d rank(s): %s" % (liquid, ranks, lc.error_line(log) or log[-2000:]))
    rows = [r for r in lc.thermo_rows(log) if len(r) == 5]
    if len(rows) != STEPS + 1:
        lc.fail("%s on %d rank(s): %d outputs, expected %d" % (liquid, ranks, len(rows),
                                                              STEPS + 1))
    # step: (free, bridged, total, bridges)
    return {int(r[0]): tuple(float(v) for v in r[1:]) for r in rows}


def check(series, liquid, ranks):
    steps = sorted(series)
    worst = max(abs(series[s][2] - TOTAL) for s in steps) / TOTAL
    bridges = [series[s][3] for s in steps]
    rose = sum(1 for a, b in zip(bridges, bridges[1:]) if b > a)
    fell = sum(1 for a, b in zip(bridges, bridges[1:]) if b < a)
    ok = worst <= TOLERANCE and rose > 0 and fell > 0
    extra = ""
    if liquid == "protocol1":
        free_at_start = series[0][0]
        free_later = max(series[s][0] for s in steps)
        ok = ok and free_at_start == 0.0 and free_later > 0.0
        extra = "; free liquid at step 0 %g, at most %.3g later" % (free_at_start, free_later)
    print("%s, %d rank(s): total liquid within %.2e of 320 nl (tolerance %g) at all %d "
          "steps; bridges %d at the start, %d at the end, rose at %d steps, fell at %d%s %s" % (
              liquid, ranks, worst, TOLERANCE, len(steps), bridges[0], bridges[-1], rose, fell,
              extra, "ok" if ok else "FAIL"))
    return ok


def main():
    parser = lc.argument_parser(__doc__)
    parser.add_argument("--ranks", default="1,2,3")
    args = parser.parse_args()
    env, workdir = lc.start(args.env, args.workdir, "protocols")
    ok = True
    for liquid in ("protocol1", "protocol2", "protocol3"):
        results = {}
        for ranks in [int(r) for r in args.ranks.split(",")]:
            results[ranks] = run(env, workdir, liquid, ranks)
            ok = check(results[ranks], liquid, ranks) and ok
        counts = sorted(results)
        for a, b in zip(counts, counts[1:]):
            differ = [s for s in sorted(results[a]) if s <= COMPARE_UNTIL and
                      results[a][s][3] != results[b][s][3]]
            print("%s, bridges on %d and %d ranks: %s up to step %d %s" % (
                liquid, a, b, "the same" if not differ else "differ at steps %s" % differ[:5],
                COMPARE_UNTIL, "ok" if not differ else "FAIL"))
            ok = ok and not differ
    print("protocols: %s (files in %s)" % ("PASS" if ok else "FAIL", workdir))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
