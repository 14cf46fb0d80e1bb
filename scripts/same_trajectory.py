#!/usr/bin/env python3
"""Run one LAMMPS scene with two builds of the capbridge plugin and compare what they wrote.

Usage: scripts/same_trajectory.py A.so B.so SCENE [-fixed-bins SORT NEIGH] [-size S] [-np N]
                                  [-var NAME VALUE ...]

For a change that must not move a trajectory (a refactoring, a rule moved into the core):
both runs use the current deck (inputs/SCENE/in.lammps through scripts/scene.sh, which must
be readable by both builds), in out/same_trajectory/{A,B}.  Compared, number by number: every
dump the deck writes (files *.dump, snap.*.txt) and the thermo rows of log.lammps.  Prints
the largest difference relative to the largest magnitude of its column and file, per file,
and exits 1 if a file is missing in one run or the row counts differ.  It sets no tolerance:
round-off grows along a chaotic trajectory, so the reader judges the numbers it prints.

-fixed-bins SORT NEIGH: both runs use a copy of the deck with `atom_modify sort 1000 SORT`
and `neigh_modify binsize NEIGH` (lengths in the deck's units) before its first run.  LAMMPS
derives both bin sizes from the neighbor cutoff, and the bins set the order of the atoms and
of their neighbors, hence of every force sum: a change of the cutoff alone (the bridges'
reach) reorders the sums and moves a trajectory by round-off that then grows.  With the bins
fixed, a change that is only that gives identical numbers.
"""
import glob
import os
import subprocess
import sys

TOP = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def fail(message):
    print(f"same_trajectory: {message}", file=sys.stderr)
    sys.exit(2)


def numbers(line):
    """The numbers of a line (None for a line with a word that is not a number)."""
    values = []
    for word in line.split():
        try:
            values.append(float(word))
        except ValueError:
            return None
    return values


def table(path):
    """The rows of numbers of a file: a dump's atom rows, or log.lammps's thermo rows."""
    rows = []
    with open(path) as f:
        lines = f.read().splitlines()
    if os.path.basename(path) == "log.lammps":
        inside = False
        for line in lines:
            if line.split()[:1] == ["Step"]:
                inside = True
            elif line.startswith("Loop time"):
                inside = False
            elif inside and numbers(line) is not None:
                rows.append(numbers(line))
        return rows
    return [values for values in map(numbers, lines) if values]


def largest_difference(a, b):
    """max over columns of max |a - b| / max |a| in that column."""
    worst = 0.0
    for column in range(min(len(a[0]), len(b[0])) if a and b else 0):
        scale = max(abs(row[column]) for row in a if column < len(row)) or 1.0
        diff = max(abs(ra[column] - rb[column]) for ra, rb in zip(a, b)
                   if column < len(ra) and column < len(rb))
        worst = max(worst, diff / scale)
    return worst


def fixed_bins_deck(scene, sort_bin, neigh_bin, out):
    """A copy of the scene's LAMMPS deck with both bin sizes fixed before its first run."""
    for value in (sort_bin, neigh_bin):
        if numbers(value) is None or len(numbers(value)) != 1 or float(value) <= 0.0:
            fail(f"-fixed-bins takes two positive lengths, not '{value}'")
    with open(os.path.join(TOP, "inputs", scene, "in.lammps")) as f:
        lines = f.read().splitlines()
    first_run = next((k for k, line in enumerate(lines) if line.split()[:1] == ["run"]), None)
    if first_run is None:
        fail(f"inputs/{scene}/in.lammps has no run command")
    lines[first_run:first_run] = [f"atom_modify sort 1000 {sort_bin}",
                                  f"neigh_modify binsize {neigh_bin}"]
    os.makedirs(out, exist_ok=True)
    path = os.path.join(out, "in.fixed-bins.lammps")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    return path


def main():
    args = sys.argv[1:]
    if len(args) < 3:
        fail("usage: scripts/same_trajectory.py A.so B.so SCENE [-size S] [-np N] [-var ...]")
    builds, scene, options = args[:2], args[2], args[3:]
    for build in builds:
        if not os.path.isfile(build):
            fail(f"no plugin file '{build}'")
    out = os.path.join(TOP, "out", "same_trajectory")
    deck = {}
    if options[:1] == ["-fixed-bins"]:
        if len(options) < 3:
            fail("-fixed-bins needs two lengths: SORT NEIGH")
        deck = {"CAPBRIDGE_DECK": fixed_bins_deck(scene, options[1], options[2], out)}
        options = options[3:]
    for label, build in zip("AB", builds):
        env = dict(os.environ, CAPBRIDGE_PLUGIN=os.path.realpath(build),
                   CAPBRIDGE_SKIP_CONFIGURE="1", **deck)
        run = subprocess.run([os.path.join(TOP, "scripts", "scene.sh"), "lammps", scene,
                              "-out", os.path.join(out, label)] + options, env=env,
                             stdout=subprocess.DEVNULL)
        if run.returncode != 0:
            fail(f"the run with {label} = {build} failed (log: {out}/{label}/log.lammps)")
    status = 0
    patterns = ("*.dump", "snap.*.txt", "log.lammps")
    names = sorted({os.path.relpath(p, os.path.join(out, "A")) for pattern in patterns
                    for p in glob.glob(os.path.join(out, "A", "**", pattern), recursive=True)})
    for name in names:
        path_b = os.path.join(out, "B", name)
        if not os.path.isfile(path_b):
            print(f"{name}: missing in B")
            status = 1
            continue
        a, b = table(os.path.join(out, "A", name)), table(path_b)
        if len(a) != len(b):
            print(f"{name}: {len(a)} rows in A, {len(b)} in B")
            status = 1
            continue
        print(f"{name}: {len(a)} rows, largest relative difference {largest_difference(a, b):.3g}")
    sys.exit(status)


if __name__ == "__main__":
    main()
