#!/usr/bin/python3
"""Where the dry tau(p) line of the split bottom misses the origin: the stress ratio tau/p of
the band cells by pressure and by inertial number, and the line tau = mu p + c over the band
cells below a height (issue 18: the dry intercept).

Usage: inputs/split_bottom/stress_ratio.py D RHO POSTDIR [RUN ...]
D: the grain diameter [m] and RHO their density [kg/m^3] (params.in: 4.762e-3 and 150, as
Gladkyy section 4.1, at every size); POSTDIR: post.py's output
directory, whose <run>_stress.csv give p, tau and the shear rate per (r, z) cell and whether it
is in the band; RUN: the runs to read (default: every <run>_stress.csv there).  Prints, over the
band cells of all runs, tau/p per pressure bin and per bin of I = shear rate d / sqrt(p / rho)
(the inertial number of GDR MiDi 2004, as post.py's), and per run
the least-squares line through the band cells at z <= zmax for a few zmax (mu +- s.e., c +-
s.e.).
"""
import glob
import os
import sys

import numpy as np


def band_cells(path):
    a = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    return a[a[:, 5] == 1]


def line(p, tau):
    """tau = mu p + c by least squares: mu, its s.e., c, its s.e."""
    a = np.vstack([p, np.ones_like(p)]).T
    coef = np.linalg.lstsq(a, tau, rcond=None)[0]
    s2 = np.sum((tau - a @ coef) ** 2) / (len(p) - 2)
    cov = s2 * np.linalg.inv(a.T @ a)
    return coef[0], np.sqrt(cov[0, 0]), coef[1], np.sqrt(cov[1, 1])


def main(argv):
    if len(argv) < 4:
        sys.exit(__doc__)
    d, rho, post = float(argv[1]), float(argv[2]), argv[3]
    paths = ([os.path.join(post, run + "_stress.csv") for run in argv[4:]] or
             sorted(glob.glob(os.path.join(post, "*_stress.csv"))))
    cells = {os.path.basename(p)[:-len("_stress.csv")]: band_cells(p) for p in paths}
    allc = np.vstack(list(cells.values()))
    z, p, tau, rate = allc[:, 1], allc[:, 2], allc[:, 3], allc[:, 4]
    ratio, inertial = tau / p, rate * d / np.sqrt(p / rho)
    print("| p [Pa] | cells | tau/p (mean +- s.e.) | I (median) | z/d (median) |")
    print("|---|---|---|---|---|")
    for lo, hi in ((0, 5), (5, 10), (10, 15), (15, 20), (20, 1e9)):
        s = (p >= lo) & (p < hi)
        if s.sum() > 1:
            print("| %s | %d | %.3f +- %.3f | %.4f | %.1f |"
                  % ("%g-%g" % (lo, hi) if hi < 1e9 else "> %g" % lo, s.sum(), ratio[s].mean(),
                     ratio[s].std(ddof=1) / np.sqrt(s.sum()), np.median(inertial[s]),
                     np.median(z[s]) / d))
    print()
    print("| I | cells | tau/p (mean +- s.e.) | p [Pa] (median) |")
    print("|---|---|---|---|")
    for lo, hi in ((0, 0.0025), (0.0025, 0.005), (0.005, 0.01), (0.01, 1e9)):
        s = (inertial >= lo) & (inertial < hi)
        if s.sum() > 1:
            print("| %s | %d | %.3f +- %.3f | %.1f |"
                  % ("%g-%g" % (lo, hi) if hi < 1e9 else "> %g" % lo, s.sum(), ratio[s].mean(),
                     ratio[s].std(ddof=1) / np.sqrt(s.sum()), np.median(p[s])))
    print()
    top = max(c[:, 1].max() for c in cells.values()) / d
    print("| band cells at z <= | " + " | ".join(cells) + " |")
    print("|---|" + "---|" * len(cells))
    for zmax in (top, top - 2, top - 3, top - 4):
        fits = []
        for c in cells.values():
            s = c[:, 1] <= zmax * d + 1e-12
            fits.append("n %d: mu %.3f +- %.3f, c %.2f +- %.2f Pa"
                        % ((s.sum(),) + line(c[s, 2], c[s, 3])) if s.sum() > 3 else "-")
        print("| %.1f d | %s |" % (zmax, " | ".join(fits)))


if __name__ == "__main__":
    main(sys.argv)
