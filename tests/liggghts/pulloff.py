#!/usr/bin/env python3
"""LIGGGHTS pull-off against `capbridge pulloff`, for the 13 cases of Gladkyy Table 1.

For every case, `capbridge pulloff` (the standalone reference, src_c/cli/cmd_pulloff.c)
and LIGGGHTS with `cohesion capillary` (tests/liggghts/in.pulloff) integrate the same two
spheres with the same time step, velocity, k_n and density; every step of the LIGGGHTS run
is compared with the reference: x1, v1, x2, the gap, the net force on sphere 1 (capillary
minus contact) and the bridge flag. The cases cycle through every law and a few of the
options; the relative difference must stay below 1e-9 at every step.

usage: pulloff.py CAPBRIDGE LIGGGHTS_ENV [--ranks N] [--cases W11,R2,...] [--workdir DIR]
"""
import argparse
import os
import subprocess
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import liggghts_common as lc  # noqa: E402

TOLERANCE = 1e-9
# law and options per case: (law, [(keyword, value)]); keywords as the CLI spells them
# (LIGGGHTS spells Richefeu's constant `richefeu_c`). Every law appears at least once.
PLAN = [
    ("W11", "willett", []),
    ("W12", "richefeu", [("c", "0.8")]),
    ("W13", "willett/reduced", []),
    ("W21", "rabinovich", []),
    ("W22", "rabinovich/uncorrected", [("overlap", "none")]),
    ("W23", "weigert", []),
    ("W24", "soulie", []),
    ("W31", "willett", [("rupture", "lian")]),
    ("W32", "richefeu", []),
    ("W33", "table", []),
    ("R1", "willett", []),
    ("R2", "rabinovich", [("rupture", "lian")]),
    ("R3", "soulie", [("rupture", "willett")]),
]
# Contact: in the pull-offs above sphere 1 never catches up with sphere 2. A light sphere 1
# pulled slowly does, and bounces in contact (linear spring) while the bridge holds; these
# runs stop after a fixed number of steps without rupture (capbridge then exits 1).
CONTACT_PLAN = [
    ("W21", "willett", [], "100", "0.02", 3000),
    ("W21", "richefeu", [("overlap", "none")], "50", "0.02", 3000),
]
LIGGGHTS_KEYWORD = {"c": "richefeu_c"}


def velocity_of(case):
    # fast enough for the bridge to break (sphere 1 is attracted and follows sphere 2)
    return "0.05" if float(case["r1"]) > 1e-4 else "0.5"


def reference(cli, case, law, options, run, workdir):
    command = [cli, "pulloff", law, "gamma", case["gamma"], "theta", case["theta"]]
    for keyword, value in options:
        command += [keyword, value]
    command += ["--r1", case["r1"], "--r2", case["r2"], "--volume", case["volume"],
                "--velocity", run["velocity"], "--density", run["density"], "--kn", "1000"]
    if run["max_steps"]:
        command += ["--max-steps", str(run["max_steps"])]
    result = subprocess.run(command, cwd=workdir, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, universal_newlines=True)
    held = run["max_steps"] and result.returncode == 1 and "did not rupture" in result.stderr
    if result.returncode != 0 and not held:
        lc.fail("%s: capbridge pulloff failed: %s" % (case["name"], result.stderr.strip()))
    dt = None
    rows = []
    for line in result.stdout.splitlines():
        if line.startswith("# dt = "):
            dt = line.split()[3]
        elif line and line[0].isdigit():
            rows.append(line.split(","))
    if dt is None or not rows:
        lc.fail("%s: unexpected capbridge pulloff output" % case["name"])
    return dt, rows


def relative(a, b, floor):
    scale = max(abs(a), abs(b), floor)
    return 0.0 if scale == 0.0 else abs(a - b) / scale


def compare(case, law, options, run, cli, env, ranks, workdir):
    name = case["name"]
    dt, ref = reference(cli, case, law, options, run, workdir)
    steps = int(ref[-1][0])
    x2 = ref[0][4]
    r1, r2 = float(case["r1"]), float(case["r2"])
    radsum = r1 + r2
    cohesion = "capillary law %s" % law
    for keyword, value in options:
        cohesion += " %s %s" % (LIGGGHTS_KEYWORD.get(keyword, keyword), value)
    cohesion += " tally on"
    variables = [
        ("cohesion", cohesion), ("r1", case["r1"]), ("r2", case["r2"]),
        ("d1", repr(2.0 * r1)), ("d2", repr(2.0 * r2)), ("x2", x2),
        ("gamma", case["gamma"]), ("theta", case["theta"]), ("volume", case["volume"]),
        ("content", "0"), ("density", run["density"]), ("kn", "1000"),
        ("velocity", run["velocity"]), ("dt", dt), ("steps", steps), ("px", ranks),
        ("box", repr(10.0 * radsum)), ("bridges", "f_bridgeCount[1]")]
    code, log = lc.liggghts(env, os.path.join(lc.HERE, "in.pulloff"), variables, workdir,
                            ranks=ranks, log="log.%s.%s" % (name, run["tag"]))
    if code != 0:
        lc.fail("%s: LIGGGHTS failed: %s" % (name, lc.error_line(log) or log[-2000:]))
    lig = lc.thermo_rows(log)
    if len(lig) != len(ref):
        lc.fail("%s: LIGGGHTS printed %d rows, capbridge %d" % (name, len(lig), len(ref)))

    # column scales: a value that passes through zero is compared relative to 1e-12 of
    # the largest magnitude of its column
    ref_cols = {"x1": [float(r[2]) for r in ref], "v1": [float(r[3]) for r in ref],
                "x2": [float(r[4]) for r in ref], "gap": [float(r[5]) for r in ref],
                "f1": [float(r[6]) - float(r[7]) for r in ref]}
    lig_cols = {"x1": [float(r[1]) for r in lig], "v1": [float(r[2]) for r in lig],
                "x2": [float(r[3]) for r in lig],
                "gap": [(float(r[3]) - float(r[1])) - radsum for r in lig],
                "f1": [float(r[4]) for r in lig]}
    worst = {}
    for column in ref_cols:
        floor = 1e-12 * max(abs(v) for v in ref_cols[column])
        worst[column] = (0.0, 0)
        for n, (a, b) in enumerate(zip(ref_cols[column], lig_cols[column])):
            d = relative(a, b, floor)
            if d > worst[column][0]:
                worst[column] = (d, n)
    bridge_mismatch = [int(r[0]) for r, l in zip(ref, lig)
                       if int(r[8]) != int(round(float(l[5])))]
    rupture_step = next((int(r[0]) for r in ref if r[8] == "0"), -1)
    contact_steps = sum(1 for r in ref if float(r[7]) > 0.0)
    ok = all(w[0] <= TOLERANCE for w in worst.values()) and not bridge_mismatch
    for r, l in zip(ref, lig):
        if int(r[0]) != int(l[0]):
            lc.fail("%s: step %s against %s" % (name, l[0], r[0]))
    label = law + "".join(" %s %s" % o for o in options)
    print("%-4s %-36s %d rank(s) %5d steps, rupture at %5d, %4d in contact | max rel. diff "
          "x1 %.1e v1 %.1e x2 %.1e gap %.1e f1 %.1e | bridge flag %s %s" % (
              name, label, ranks, steps, rupture_step, contact_steps, worst["x1"][0],
              worst["v1"][0],
              worst["x2"][0], worst["gap"][0], worst["f1"][0],
              "same" if not bridge_mismatch else "differs at steps %s" % bridge_mismatch[:5],
              "ok" if ok else "FAIL"))
    if not ok:
        for column, (d, n) in worst.items():
            if d > TOLERANCE:
                print("    %s step %d: capbridge %.17g, LIGGGHTS %.17g" % (
                    column, n, ref_cols[column][n], lig_cols[column][n]))
    return ok


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("capbridge")
    parser.add_argument("env")
    parser.add_argument("--ranks", type=int, default=1)
    parser.add_argument("--cases", default="")
    parser.add_argument("--workdir", default="")
    args = parser.parse_args()
    args.capbridge = os.path.abspath(args.capbridge)
    env, workdir = lc.start(args.env, args.workdir, "pulloff")
    cases = lc.gladkyy_cases()
    if len(cases) != 13:
        lc.fail("reference_data/cases.csv holds %d cases, not 13" % len(cases))
    by_name = dict((c["name"], c) for c in cases)
    runs = []
    for name, law, options in PLAN:
        runs.append((name, law, options, {"velocity": velocity_of(by_name[name]),
                                          "density": "2500", "max_steps": 0,
                                          "tag": "pull"}))
    for k, (name, law, options, density, velocity, steps) in enumerate(CONTACT_PLAN):
        runs.append((name, law, options, {"velocity": velocity, "density": density,
                                          "max_steps": steps, "tag": "contact%d" % k}))
    if args.cases:
        wanted = args.cases.split(",")
        runs = [r for r in runs if r[0] in wanted]
    ok = True
    for name, law, options, run in runs:
        ok = compare(by_name[name], law, options, run, args.capbridge, env, args.ranks,
                     workdir) and ok
    print("pull-off, %d run(s) on %d rank(s): %s (tolerance %g relative; files in %s)" % (
        len(runs), args.ranks, "PASS" if ok else "FAIL", TOLERANCE, workdir))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
