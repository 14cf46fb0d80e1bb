#!/usr/bin/python3
"""The loading-rate sweep of issue 18 item 5: is the uniaxial strength independent of the wall
speed at the speed the default size uses?

Usage: inputs/uniaxial/rate_sweep.py OUTDIR RUNDIR [RUNDIR ...]
Each RUNDIR is one finished run of inputs/uniaxial/in.lammps (scripts/scene.sh ... -var vwall V
-var seed S); runs are grouped by their summary's vwall.  Writes OUTDIR/rate_sweep.csv (one row
per run: vwall, seed, sigma_rupt, z at the start, inertial number) and prints per speed the mean
strength +- its standard error over the packings, and each speed's difference from the default
size's 0.01 m/s over their combined standard error.
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from post import mean_and_error, read_curve, read_summary, strength  # noqa: E402  (the page's definitions)

DEFAULT_SPEED = 0.01   # m/s, the default size's vwall (in.lammps)


def main(argv):
    if len(argv) < 3:
        sys.exit(__doc__)
    out, runs = argv[1], argv[2:]
    rows = []
    for run in runs:
        summary, curve = read_summary(run), read_curve(run)
        rows.append((float(summary["vwall"]), summary.get("seed", "?"), strength(curve[:, 3]),
                     float(curve[0, 5]), float(summary["inertial_capillary_scale"])))
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "rate_sweep.csv"), "w") as f:
        f.write("vwall_m_per_s,seed,sigma_rupt_Pa,z_start,inertial_number\n")
        for row in sorted(rows):
            f.write("%g,%s,%.6g,%.4g,%.4g\n" % row)
    speeds = sorted({row[0] for row in rows})
    stats = {v: mean_and_error([r[2] for r in rows if r[0] == v]) for v in speeds}
    print("| vwall [m/s] | packings | sigma_rupt [Pa] (mean +- s.e.) | "
          "difference from 0.01 m/s / combined s.e. |")
    print("|---|---|---|---|")
    for v in speeds:
        mean, err = stats[v]
        count = sum(1 for r in rows if r[0] == v)
        if v != DEFAULT_SPEED and DEFAULT_SPEED in stats:
            ref, ref_err = stats[DEFAULT_SPEED]
            ratio = "%.2f" % ((mean - ref) / math.hypot(err, ref_err))
        else:
            ratio = "-"
        print(f"| {v:g} | {count} | {mean:.1f} +- {err:.1f} | {ratio} |")


if __name__ == "__main__":
    main(sys.argv)
