#!/usr/bin/python3
"""Plot each law's force error against its cost, from `capbridge report --csv`.

usage: plot_report.py REPORT.csv OUT.png
x: nanoseconds per cb_force call; y: relative force error over the reference grid
(RMS and max, inside each law's stated validity where it has one, and over all of it).
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(report_path, png_path):
    with open(report_path, newline="") as f:
        rows = list(csv.DictReader(f))
    fig, ax = plt.subplots(figsize=(8, 5.5))
    for row in rows:
        cost = float(row["ns_per_call"])
        rms_all = 100 * float(row["force_rms_grid"])
        max_all = 100 * float(row["force_max_grid"])
        ax.scatter(cost, rms_all, color="tab:blue", zorder=3)
        ax.scatter(cost, max_all, color="tab:red", marker="^", zorder=3)
        ax.plot([cost, cost], [rms_all, max_all], color="0.7", zorder=1)
        if row["force_rms_grid_valid"] not in ("", "nan"):
            ax.scatter(cost, 100 * float(row["force_rms_grid_valid"]), color="tab:green",
                       marker="s", zorder=3)
        ax.annotate(row["law"], (cost, rms_all), textcoords="offset points", xytext=(6, -3),
                    fontsize=9)
    ax.set_xlim(left=0)
    ax.set_yscale("log")
    ax.set_xlabel("cost per force call [ns] (measured in the same run)")
    ax.set_ylabel("force error against exact Laplace-Young [%]")
    ax.scatter([], [], color="tab:blue", label="RMS, whole grid")
    ax.scatter([], [], color="tab:red", marker="^", label="max, whole grid")
    ax.scatter([], [], color="tab:green", marker="s", label="RMS, inside stated validity")
    ax.legend(loc="best", fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    ax.set_title("capbridge: capillary force laws, error against cost")
    fig.tight_layout()
    fig.savefig(png_path, dpi=120)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
