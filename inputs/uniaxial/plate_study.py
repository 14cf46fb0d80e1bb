#!/usr/bin/python3
"""The wet bottom plate variant (issue 19 point 3): does a wet plate change the strength?

Usage: inputs/uniaxial/plate_study.py OUT.csv NOTE RUNDIR [RUNDIR ...]
Each RUNDIR is one finished run of inputs/uniaxial/in.lammps or in.liggghts with -var plate
wet or dry (scripts/scene.sh ... -var seed S -var plate P); runs of one seed with both plates
are a pair.  Writes OUT.csv (NOTE as its first line, a comment: the size, engine, protocol and
code revision) with one row per run, and prints per plate the mean peak stress +- its standard
error over the packings and the paired difference wet - dry.
Peak sigma: the largest sigma at dh/<D> > 0.1 (after the lid's first-contact transient);
drift: the largest |relative liquid change| during the compression; bridges_end: the bridges at
the end (the plate's included).
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from post import mean_and_error, read_curve, read_summary  # noqa: E402  (the page's definitions)


def row(run):
    summary, curve = read_summary(run), read_curve(run)
    after = curve[curve[:, 2] > 0.1]
    return {"seed": summary["seed"], "plate": summary.get("plate", "dry"),
            "peak": float(after[:, 3].max()), "drift": float(abs(curve[:, 6]).max()),
            "plate_bridges": int(float(summary.get("plate_bridges", 0))),
            "phi": float(summary["phi"]), "bridges_end": int(curve[-1, 4])}


def main(argv):
    if len(argv) < 4:
        sys.exit(__doc__)
    out, note, rows = argv[1], argv[2], [row(run) for run in argv[3:]]
    with open(out, "w") as f:
        f.write("# %s; peak_sigma: largest sigma at dh/<D> > 0.1; drift: largest |relative "
                "liquid change| during the compression; bridges_end: at the end (plate bridges "
                "included)\n" % note)
        f.write("seed,plate,peak_sigma_Pa,liquid_drift,plate_bridges,phi,bridges_end\n")
        for r in rows:
            f.write("%s,%s,%.1f,%.2g,%d,%.4f,%d\n" % (r["seed"], r["plate"], r["peak"],
                                                      r["drift"], r["plate_bridges"], r["phi"],
                                                      r["bridges_end"]))
    print("| plate | peak sigma, mean +- s.e. (n) | plate bridges | liquid drift (worst) |")
    print("|---|---|---|---|")
    for plate in ("wet", "dry"):
        mine = [r for r in rows if r["plate"] == plate]
        if not mine:
            continue
        mean, error = mean_and_error([r["peak"] for r in mine])
        bridges = [r["plate_bridges"] for r in mine]
        print("| %s | %.0f +- %.0f Pa (%d) | %d-%d | %.2g |"
              % (plate, mean, error, len(mine), min(bridges), max(bridges),
                 max(r["drift"] for r in mine)))
    by_seed = {}
    for r in rows:
        by_seed.setdefault(r["seed"], {})[r["plate"]] = r["peak"]
    pairs = [p["wet"] - p["dry"] for p in by_seed.values() if "wet" in p and "dry" in p]
    if pairs:
        mean, error = mean_and_error(pairs)
        print("| paired difference wet - dry | %+.1f +- %.1f Pa (%d pairs) | | |"
              % (mean, error, len(pairs)))


if __name__ == "__main__":
    main(sys.argv)
