#!/usr/bin/python3
"""tau = mu p + c_V with one mu shared by all runs of an engine, as Gladkyy & Schwarze 2014
fit their Fig. 7 (eq. 14: mu = 0.13 for every liquid content, c_1 = 1.3 Pa for 13.6 nl,
c_2 = 2 Pa for 74.2 nl).

Usage: /usr/bin/python3 inputs/split_bottom/shared_mu.py POST_DIR
  POST_DIR is post.py's --out (summary.csv and RUN_stress.csv); writes POST_DIR/shared_mu.csv
  and prints it as a markdown table.  post.py writes the same file itself.

The fit: per engine, least squares of tau over the band cells of every run (dry and every
volume, every seed, every law) on the columns p and one indicator per volume, so one slope mu
and one intercept c_V per volume (the dry one included: it must come out near 0).  Two
standard errors are given:
  * residual: s^2 (X^T X)^-1 of the pooled fit.  It treats every band cell as independent,
    which neighbouring cells of one run are not, so it is a lower bound;
  * seeds: the same fit done per seed (that seed's runs of every volume), and the standard
    error of the mean over the seeds (sd / sqrt(n)).  This one holds the packing-to-packing
    scatter; it is the one to compare with the paper.
Each wet row also gives c_V - c_dry (its error from the per-seed differences).

The paper's sentence ("the correlations fit ... tau = mu p + c with mu = 0.13 for the
particular granular material. Here, the parameter c ... depends significantly on the liquid
content") reads two ways, so both fits are written: the joint one above, and the dry
material's mu held for every volume (mu_dry: the slope of the dry runs alone; c at mu_dry:
the mean of tau - mu_dry p over the band cells of a volume, which is its least-squares
intercept at that slope), with errors across the seeds as above.
"""
import csv
import math
import os
import sys

import numpy as np


def joint_fit(runs):
    """mu and one c per volume over `runs` (dicts with volume, p, tau of the band cells).
    Returns mu, {volume: c}, the covariance of (mu, c...) from the residuals, the volumes."""
    volumes = sorted({r["volume"] for r in runs})
    p = np.concatenate([r["p"] for r in runs])
    tau = np.concatenate([r["tau"] for r in runs])
    X = np.zeros((len(p), 1 + len(volumes)))
    X[:, 0] = p
    row = 0
    for r in runs:
        X[row:row + len(r["p"]), 1 + volumes.index(r["volume"])] = 1.0
        row += len(r["p"])
    coef, _, rank, _ = np.linalg.lstsq(X, tau, rcond=None)
    if rank < X.shape[1]:
        raise ValueError("shared_mu: the band cells do not determine mu and every c "
                         "(a volume without band cells, or all cells at one p)")
    dof = len(tau) - X.shape[1]
    resid = tau - X @ coef
    s2 = float(resid @ resid) / dof if dof > 0 else float("nan")
    cov = s2 * np.linalg.inv(X.T @ X)
    return coef[0], dict(zip(volumes, coef[1:])), cov, volumes


def dry_mu_fit(runs):
    """The dry runs' slope mu_dry (their own tau = mu p + c) and, at that slope, one intercept
    per volume: the mean of tau - mu_dry p over its band cells.  None without dry runs."""
    dry = [r for r in runs if r["volume"] == 0.0]
    if not dry:
        return None
    mu_dry = np.polyfit(np.concatenate([r["p"] for r in dry]),
                        np.concatenate([r["tau"] for r in dry]), 1)[0]
    c = {}
    for v in sorted({r["volume"] for r in runs}):
        of_v = [r for r in runs if r["volume"] == v]
        c[v] = float(np.mean(np.concatenate([r["tau"] - mu_dry * r["p"] for r in of_v])))
    return float(mu_dry), c


def mean_se(values):
    v = np.array(values, dtype=float)
    return float(v.mean()), (float(v.std(ddof=1) / math.sqrt(len(v))) if len(v) > 1
                             else float("nan"))


def shared_mu_rows(runs):
    """One row per engine and volume: mu (shared), c_V, both standard errors, runs, cells."""
    rows = []
    for engine in sorted({r["engine"] for r in runs}):
        mine = [r for r in runs if r["engine"] == engine]
        mu, c, cov, volumes = joint_fit(mine)
        seeds = sorted({r["seed"] for r in mine})
        per_seed, dry_per_seed = [], []
        for s in seeds:
            of_seed = [r for r in mine if r["seed"] == s]
            if {r["volume"] for r in of_seed} == set(volumes):
                per_seed.append(joint_fit(of_seed)[:2])
                dry_per_seed.append(dry_mu_fit(of_seed))
        mu_s = mean_se([f[0] for f in per_seed])
        at_dry = dry_mu_fit(mine)
        dry = volumes[0] if volumes[0] == 0.0 else None
        for k, v in enumerate(volumes):
            c_s = mean_se([f[1][v] for f in per_seed])
            of_v = [r for r in mine if r["volume"] == v]
            row = [engine, f"{v:g}", len(of_v), sum(len(r["p"]) for r in of_v),
                   len(per_seed), f"{mu:.4f}", f"{math.sqrt(cov[0, 0]):.4f}",
                   f"{mu_s[1]:.4f}", f"{c[v]:.4f}",
                   f"{math.sqrt(cov[1 + k, 1 + k]):.4f}", f"{c_s[1]:.4f}"]
            if dry is None or v == dry:
                row += ["", ""]
            else:  # the wet intercept over the dry one, its error from the per-seed differences
                shift = mean_se([f[1][v] - f[1][dry] for f in per_seed])
                row += [f"{c[v] - c[dry]:.4f}", f"{shift[1]:.4f}"]
            if at_dry is None:
                row += ["", "", "", ""]
            else:
                mu_dry_s = mean_se([f[0] for f in dry_per_seed])
                c_dry_s = mean_se([f[1][v] for f in dry_per_seed])
                row += [f"{at_dry[0]:.4f}", f"{mu_dry_s[1]:.4f}", f"{at_dry[1][v]:.4f}",
                        f"{c_dry_s[1]:.4f}"]
            rows.append(row)
    header = ["engine", "volume_nl", "runs", "band_cells", "seeds", "mu", "mu_se_residual",
              "mu_se_seeds", "c_Pa", "c_se_residual_Pa", "c_se_seeds_Pa", "c_minus_dry_Pa",
              "c_minus_dry_se_seeds_Pa", "mu_dry", "mu_dry_se_seeds", "c_at_mu_dry_Pa",
              "c_at_mu_dry_se_seeds_Pa"]
    return header, rows


def write_shared_mu(path, runs):
    header, rows = shared_mu_rows(runs)
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(header)
        w.writerows(rows)
    return header, rows


def load_post_dir(post):
    """The band cells of every run of post.py's summary.csv, from its RUN_stress.csv."""
    runs = []
    with open(os.path.join(post, "summary.csv")) as f:
        for s in csv.DictReader(f):
            with open(os.path.join(post, s["run"] + "_stress.csv")) as g:
                cells = [c for c in csv.DictReader(g) if int(c["in_band"]) == 1]
            runs.append({"engine": s["engine"], "volume": float(s["volume_nl"]),
                         "seed": int(s["seed"]),
                         "p": np.array([float(c["p_Pa"]) for c in cells]),
                         "tau": np.array([float(c["tau_Pa"]) for c in cells])})
    return runs


def main(argv):
    if len(argv) != 1:
        sys.exit(__doc__.split("\n\n")[1])
    header, rows = write_shared_mu(os.path.join(argv[0], "shared_mu.csv"),
                                   load_post_dir(argv[0]))
    print("| " + " | ".join(header) + " |")
    print("|" + " --- |" * len(header))
    for r in rows:
        print("| " + " | ".join(str(x) for x in r) + " |")


if __name__ == "__main__":
    main(sys.argv[1:])
