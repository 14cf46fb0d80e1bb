#!/usr/bin/env python3
"""Protocol 1's distribution in LIGGGHTS against the core's, computed without LIGGGHTS.

tests/liggghts/in.protocol1_reference: 45 spheres at rest, off a lattice, 1 nl each; the
distribution at the setup of `run 0` on 1 and 3 ranks. The reference is the capbridge core's
cb_protocol1_distribute over every pair of the dumped spheres (protocol1_reference.c: it
decides which pairs are eligible). Checked: the same pairs hold bridges, each volume within
1e-12 relative of the reference's; no free liquid left; the bridges hold 45 nl (1e-12).

usage: protocol1_reference.py REFERENCE_PROGRAM LIGGGHTS_ENV [--workdir DIR]
"""
import argparse
import os
import subprocess
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import liggghts_common as lc  # noqa: E402

TOLERANCE = 1e-12
SPHERES, V0 = 45, 1e-12


def dump_rows(path):
    """The rows of a one-snapshot dump after its ITEM: header line."""
    with open(path) as f:
        lines = f.read().splitlines()
    start = next(k for k, line in enumerate(lines) if line.startswith("ITEM: ATOMS") or
                 line.startswith("ITEM: ENTRIES"))
    return [line.split() for line in lines[start + 1:] if line.strip()]


def run(env, workdir, ranks):
    sub = os.path.join(workdir, "ranks%d" % ranks)
    os.makedirs(sub, exist_ok=True)
    code, log = lc.liggghts(env, os.path.join(lc.HERE, "in.protocol1_reference"),
                            [("px", ranks)], sub, ranks=ranks)
    if code != 0:
        lc.fail("%d rank(s): %s" % (ranks, lc.error_line(log) or log[-2000:]))
    bridges = {}
    for r in dump_rows(os.path.join(sub, "pairs.dump")):
        if float(r[3]) != 0.0:
            ids = tuple(sorted((int(float(r[0])), int(float(r[1])))))
            bridges[ids] = float(r[2])
    atoms = dump_rows(os.path.join(sub, "atoms.dump"))
    return bridges, atoms, sub


def reference(program, atoms):
    text = "".join(" ".join(a[:5]) + "\n" for a in atoms)
    result = subprocess.run([program, "richefeu", "0.0728", "0", repr(SPHERES * V0)],
                            input=text, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            universal_newlines=True)
    if result.returncode != 0:
        lc.fail("protocol1_reference: " + result.stderr)
    lines = result.stdout.split("\n")
    alpha = float(lines[0].split()[1])
    volumes = {}
    for line in lines[1:]:
        if line.strip():
            a, b, v = line.split()
            volumes[(int(a), int(b))] = float(v)
    return alpha, volumes


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("program")
    parser.add_argument("env")
    parser.add_argument("--workdir", default="")
    args = parser.parse_args()
    env, workdir = lc.start(args.env, args.workdir, "protocol1_reference")
    ok = True
    for ranks in (1, 3):
        bridges, atoms, sub = run(env, workdir, ranks)
        alpha, expected = reference(os.path.abspath(args.program), atoms)
        same_pairs = set(bridges) == set(expected)
        worst = max([abs(bridges[p] - expected[p]) / expected[p] for p in expected
                     if p in bridges] or [float("inf")])
        free = sum(float(a[5]) for a in atoms)
        held = sum(bridges.values())
        good = (same_pairs and worst <= TOLERANCE and free == 0.0 and
                abs(held - SPHERES * V0) <= TOLERANCE * SPHERES * V0 and len(expected) > 10)
        print("%d rank(s): %d bridges (reference: %d, alpha %.9g), %s pairs; volumes within "
              "%.2e of the reference (tolerance %g); free liquid left %g; in bridges %.15g "
              "m^3 %s" % (ranks, len(bridges), len(expected), alpha,
                          "the same" if same_pairs else "OTHER", worst, TOLERANCE, free, held,
                          "ok" if good else "FAIL"))
        if not same_pairs:
            print("  only in LIGGGHTS: %s; only in the reference: %s" % (
                sorted(set(bridges) - set(expected))[:5],
                sorted(set(expected) - set(bridges))[:5]))
        ok = ok and good
    print("Protocol 1 against the core: %s (files in %s)" % ("PASS" if ok else "FAIL", workdir))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
