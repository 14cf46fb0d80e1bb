#!/usr/bin/env python3
"""The removal asked for between two runs in LIGGGHTS: fix property/global capillaryRemove
vector F S (Richefeu 2007 fig. 7: the half-bonds sample is the all-bonds sample with half
of its bonds removed at the start of shearing, after the consolidation), on remove.py's
scene (tests/liggghts/in.remove: 2000 spheres at rest on a lattice closer than the
diameters, free liquid 1 % of the mean grain mass each, start bridges), Protocols 2 and 3.

The deck runs `steps` steps without removal, defines fix capillaryRemove (0.5, seed 7723)
and runs `steps` steps again:
  - run 1 equals the run without any removal step for step (bridges, formations, liquid);
  - the model's line 'removed N of M bridges' comes after run 1 and before run 2's first
    output, M = the bridges at run 1's end, N within 4 standard deviations of M/2 (a
    binomial draw);
  - run 2's first output has M - N + formed bridges (formed: the formations of that pass),
    less at most a few ruptures; Protocol 2: its free liquid is run 1's last plus the
    removed liquid less what the new bridges took (0 if none formed), to 1e-12;
  - the total liquid is conserved to 1e-12 at every output of both runs;
  - the same N, M and bridges at every output on 1 and 2 ranks;
  - once per simulation: a run read from the restart file written after the removal, the
    request still defined, removes nothing, says so in one line and goes on from run 2's
    last bridges and liquid.
Protocol 2 also:
  - the request defined before the first run removes in the pass the liquid starts, the
    same pairs as keyword remove 0.5 remove_seed 7723 (the same N of M and bridges at every
    step);
  - after the keyword's removal (its restart file), the request removes nothing: the mark
    is set by either way;
  - start free, the request before the first run: run 1's setup has no bridge, says so and
    removes nothing (no mark); run 2's setup removes N of M, M the bridges run 1 formed
    (> 0), N within 4 standard deviations of M/2.

usage: remove_later.py LIGGGHTS_ENV [--workdir DIR] [--ranks 1,2]
"""
import math
import os
import re
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import liggghts_common as lc  # noqa: E402
import remove  # noqa: E402  (the scene, its deck and the model's removal line)

STEPS = 10
TOLERANCE = 1e-12
RUPTURES = 5               # at most this many ruptures in run 2's setup pass (a packing at rest)
REQUEST = "fix             capillaryRemove all property/global capillaryRemove vector 0.5 7723\n"
RUN = "run             ${steps}\n"
DONE = ("fix capillaryRemove asks for a removal, and this simulation has removed bridges "
        "once already")
# the marked output steps of a log, in order: run 1's, then run 2's (split by the thermo rows)
STEP_HEADER = re.compile(r"^\s*Step\b", re.M)


def deck_text():
    with open(os.path.join(remove.lc.HERE, "in.remove")) as f:
        return f.read()


def write_deck(workdir, name, body):
    """in.remove up to its run, then `body`"""
    text = deck_text()
    path = os.path.join(workdir, "in." + name)
    with open(path, "w") as f:
        f.write(text[:text.index(RUN)] + body)
    return path


def write_second(workdir, name, body):
    """a deck reading the restart file: in.remove from its `neighbor` line, up to its run"""
    text = deck_text()
    path = os.path.join(workdir, "in." + name)
    with open(path, "w") as f:
        f.write(remove.SECOND_HEAD + text[text.index("neighbor "):text.index(RUN)] + body)
    return path


def run(env, workdir, name, deck, liquid, free, ranks=1, restart=None, runs=1):
    """the runs' rows [[(step, bridges, bridged, free, total, formed)...] per run] and log"""
    code, log = lc.liggghts(env, deck,
                            [("px", ranks), ("data", os.path.join(workdir, "scene.data")),
                             ("liquid", liquid), ("free", repr(free)), ("steps", STEPS),
                             ("local", name + ".local"),
                             ("restart", restart or name + ".restart")],
                            workdir, ranks=ranks, log="log." + name)
    if code != 0:
        lc.fail("%s: %s" % (name, lc.error_line(log) or log[-2000:]))
    rows = [tuple(float(v) for v in r) for r in lc.thermo_rows(log) if len(r) == 6]
    if len(rows) != runs * (STEPS + 1):
        lc.fail("%s: %d outputs, expected %d" % (name, len(rows), runs * (STEPS + 1)))
    return [rows[k * (STEPS + 1):(k + 1) * (STEPS + 1)] for k in range(runs)], log


def same_rows(first, second):
    """bridges and formations equal, liquid to TOLERANCE"""
    for a, b in zip(first, second):
        if a[0] != b[0] or a[1] != b[1] or a[5] != b[5]:
            return False
        if any(abs(x - y) > TOLERANCE * a[4] for x, y in zip(a[2:5], b[2:5])):
            return False
    return len(first) == len(second)


def check_later(label, runs, log, reference, protocol):
    """the assertions on the two runs (the request before run 2); returns the failures and
    (N, M, the bridges at every output)"""
    first, second = runs
    bad = []
    if not same_rows(first, reference):
        bad.append("run 1 differs from the run without removal")
    found = [m for m in remove.REMOVAL.finditer(log)]
    headers = [m.start() for m in STEP_HEADER.finditer(log)]
    if len(found) != 1 or len(headers) < 2:
        lc.fail("%s: %d removal lines, %d thermo blocks" % (label, len(found), len(headers)))
    line = found[0]
    n, m_seen = int(line.group(1)), int(line.group(2))
    removed, total = float(line.group(3)), float(line.group(4))
    end_of_first = log.index("Loop time", headers[0])
    if not end_of_first < line.start() < headers[1]:
        bad.append("the removal line is not between run 1 and run 2's first output")
    if "asked for by fix capillaryRemove" not in line.group(0) + log[line.end():line.end() + 200]:
        bad.append("the line does not say the request removed")
    m = first[-1][1]
    if m_seen != m:
        bad.append("the model saw %d bridges, run 1 ended with %d" % (m_seen, m))
    if abs(n - m / 2) > 4 * math.sqrt(m / 4):
        bad.append("removed %d of %d" % (n, m))
    start = second[0]
    formed0 = start[5]
    ruptured = m - n + formed0 - start[1]
    if not 0 <= ruptured <= RUPTURES:
        bad.append("%d bridges at run 2's start, expected %d - %d + %d formed (less at most "
                   "%d ruptures)" % (start[1], m, n, formed0, RUPTURES))
    expected_free = first[-1][3] + removed
    if protocol == "protocol2" and formed0 == 0 and \
            abs(start[3] - expected_free) > TOLERANCE * total:
        bad.append("free liquid %.17g at run 2's start, expected %.17g + %.17g" % (
            start[3], first[-1][3], removed))
    worst = max(abs(r[4] - total) for r in first + second) / total
    if worst > TOLERANCE:
        bad.append("total liquid off by %.3g of it" % worst)
    print("%s: run 1 as without removal; removed %d of %d bridges after it (%d at run 2's "
          "start, %d formed, %d ruptured), liquid within %.2e %s" % (
              label, n, m, start[1], formed0, ruptured, worst,
              "ok" if not bad else "FAIL: " + "; ".join(bad)))
    return bad, (n, m, [r[1] for r in first + second])


def check_restart(env, workdir, name, liquid, free, end, what):
    """a run read from `name`'s restart file with the request defined removes nothing, says
    so once, and goes on from `end`, that file's last output"""
    deck = write_second(workdir, name + "-second", REQUEST + RUN)
    runs, log = run(env, workdir, name + "-second", deck, liquid, free,
                    restart=name + ".restart")
    start = runs[0][0]
    text = " ".join(log.split())
    bad = []
    if remove.REMOVAL.search(log):
        bad.append("bridges removed again")
    if text.count(DONE) != 1:
        bad.append("%d lines saying the removal was done (expected 1)" % text.count(DONE))
    if start[1] != end[1] or abs(start[3] - end[3]) > TOLERANCE * end[4] or \
            abs(start[4] - end[4]) > TOLERANCE * end[4]:
        bad.append("%d bridges, free liquid %.17g, total %.17g; the file's run ended with %d, "
                   "%.17g, %.17g" % (start[1], start[3], start[4], end[1], end[3], end[4]))
    print("%s: read_restart after %s, request defined: nothing removed, said once, %d bridges "
          "as before %s" % (name, what, start[1], "ok" if not bad else
                            "FAIL: " + "; ".join(bad)))
    return bad


def check_same_pass(env, workdir, free):
    """Protocol 2: the request before the first run acts in the pass the liquid starts, as
    keyword remove does; then the keyword's restart file with the request removes nothing"""
    keyword, klog = run(env, workdir, "keyword", os.path.join(lc.HERE, "in.remove"),
                        "protocol2 " + remove.REMOVE, free)
    deck = write_deck(workdir, "first", REQUEST + RUN + "write_restart   ${restart}\n")
    asked, alog = run(env, workdir, "first", deck, "protocol2", free)
    k, a = remove.removal(klog, "keyword"), remove.removal(alog, "first")
    bad = []
    if k[:2] != a[:2] or [r[1] for r in keyword[0]] != [r[1] for r in asked[0]]:
        bad.append("keyword: %d of %d, request: %d of %d, or other bridges" % (
            k[0], k[1], a[0], a[1]))
    print("protocol2: the request before the first run removes as keyword remove does, "
          "%d of %d, the same bridges at every step %s" % (
              a[0], a[1], "ok" if not bad else "FAIL: " + "; ".join(bad)))
    return bad + check_restart(env, workdir, "keyword", "protocol2", free, keyword[0][-1],
                               "keyword remove's removal")


WAITS = "fix capillaryRemove: no bridge exists at this run's setup: nothing removed"


def check_start_free(env, workdir, free):
    """Protocol 2, start free: the request before the first run waits for a run with
    bridges (the first run's setup has none; the second's has those the first formed)"""
    deck = write_deck(workdir, "free", REQUEST + RUN + RUN)
    runs, log = run(env, workdir, "free", deck, "protocol2 start free", free, runs=2)
    bad = []
    waits = log.find(WAITS)
    headers = [m.start() for m in STEP_HEADER.finditer(log)]
    if not 0 <= waits < headers[0]:
        bad.append("no 'no bridge exists' line before run 1's first output")
    n, m = remove.removal(log, "free")[:2]
    end = runs[0][-1][1]
    if m != end or not m > 0 or abs(n - m / 2.0) > 4.0 * math.sqrt(m / 4.0):
        bad.append("run 2 removed %d of %d, run 1 ended with %d bridges" % (n, m, end))
    print("protocol2 start free: the request waits at run 1 (no bridge), removes %d of %d at "
          "run 2 %s" % (n, m, "ok" if not bad else "FAIL: " + "; ".join(bad)))
    return bad


def main():
    parser = lc.argument_parser(__doc__)
    parser.add_argument("--ranks", default="1,2")
    args = parser.parse_args()
    env, workdir = lc.start(args.env, args.workdir, "remove_later")
    free = remove.free_per_particle(remove.scene_data(os.path.join(workdir, "scene.data")))
    later = write_deck(workdir, "later", RUN + REQUEST + RUN + "write_restart   ${restart}\n")
    failures = check_same_pass(env, workdir, free) + check_start_free(env, workdir, free)
    for protocol in ("protocol2", "protocol3"):
        reference, _ = run(env, workdir, protocol + "-none", os.path.join(lc.HERE, "in.remove"),
                           protocol, free)
        counts = {}
        for ranks in [int(r) for r in args.ranks.split(",")]:
            name = "%s-np%d" % (protocol, ranks)
            runs, log = run(env, workdir, name, later, protocol, free, ranks, runs=2)
            bad, counts[ranks] = check_later("%s np %d" % (protocol, ranks), runs, log,
                                             reference[0], protocol)
            failures += bad
            if ranks == 1:
                failures += check_restart(env, workdir, name, protocol, free, runs[1][-1],
                                          "the request's removal")
        for a, b in zip(sorted(counts), sorted(counts)[1:]):
            same = counts[a] == counts[b]
            print("%s: N, M and the bridges at every output on %d and %d ranks %s" % (
                protocol, a, b, "the same ok" if same else "differ FAIL: %s, %s" % (
                    counts[a][:2], counts[b][:2])))
            if not same:
                failures.append("%s ranks %d, %d" % (protocol, a, b))
    print("remove_later: %s (files in %s)" % ("PASS" if not failures else "FAIL", workdir))
    return 0 if not failures else 1


if __name__ == "__main__":
    sys.exit(main())
