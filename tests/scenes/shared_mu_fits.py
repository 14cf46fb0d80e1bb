#!/usr/bin/python3
"""Checks inputs/split_bottom/shared_mu.py's two fits of tau = mu p + c_V (Gladkyy 2014
eq. 14) on band cells made from known lines, three seeds of dry, 13.6 and 74.2 nl:

  * one slope for every volume (mu 0.13, c 0 / 1.3 / 2 Pa, noise 0.05 Pa): the joint fit and
    the dry-mu fit both give mu within 0.01 and each c within 0.1 Pa, the per-seed error of
    c positive and below the noise of one cell (it is a mean over 60 cells per seed);
  * the wet lines steeper (0.2): the dry-mu intercept is the analytic mean of
    tau - 0.13 p over the cells, c_V + 0.07 <p>, and the joint fit's slope lies between the
    two slopes.

Usage: shared_mu_fits.py"""
import os
import sys

import numpy as np

TOP = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(TOP, "inputs", "split_bottom"))
import shared_mu  # noqa: E402

failures = []


def check(cond, what):
    print(("ok    " if cond else "FAIL  ") + what)
    if not cond:
        failures.append(what)


def make_runs(slope_wet, noise, rng):
    lines = {0.0: (0.13, 0.0), 13.6: (slope_wet, 1.3), 74.2: (slope_wet, 2.0)}
    runs = []
    for seed in range(3):
        for v, (mu, c) in lines.items():
            p = rng.uniform(1.0, 13.0, 60)
            runs.append({"engine": "lammps", "volume": v, "seed": seed, "p": p,
                         "tau": mu * p + c + noise * rng.standard_normal(p.size)})
    return runs


def rows_by_volume(runs):
    header, rows = shared_mu.shared_mu_rows(runs)
    return {float(r[1]): {h: (float(x) if x != "" else None) for h, x in zip(header[1:], r[1:])}
            for r in rows}


def main():
    rng = np.random.default_rng(20141)
    noise = 0.05
    rows = rows_by_volume(make_runs(0.13, noise, rng))
    for v, c in ((0.0, 0.0), (13.6, 1.3), (74.2, 2.0)):
        r = rows[v]
        check(abs(r["mu"] - 0.13) < 0.01 and abs(r["c_Pa"] - c) < 0.1,
              f"joint fit at {v:g} nl: mu {r['mu']:.4f} (0.13), c {r['c_Pa']:.3f} Pa ({c})")
        check(abs(r["mu_dry"] - 0.13) < 0.01 and abs(r["c_at_mu_dry_Pa"] - c) < 0.1,
              f"dry-mu fit at {v:g} nl: mu_dry {r['mu_dry']:.4f}, c {r['c_at_mu_dry_Pa']:.3f} Pa ({c})")
        check(0 < r["c_at_mu_dry_se_seeds_Pa"] < noise,
              f"dry-mu fit at {v:g} nl: per-seed error {r['c_at_mu_dry_se_seeds_Pa']:.4f} Pa, "
              f"in (0, {noise}) Pa")
    runs = make_runs(0.2, 0.0, rng)
    rows = rows_by_volume(runs)
    for v, c in ((13.6, 1.3), (74.2, 2.0)):
        p = np.concatenate([r["p"] for r in runs if r["volume"] == v])
        expected = c + (0.2 - 0.13) * p.mean()
        got = rows[v]["c_at_mu_dry_Pa"]
        check(abs(got - expected) < 1e-3,
              f"steeper wet lines at {v:g} nl: c at mu_dry {got:.4f} Pa = c + 0.07 <p> {expected:.4f}")
    mu = rows[0.0]["mu"]
    check(0.13 < mu < 0.2, f"steeper wet lines: the joint slope {mu:.4f} lies in (0.13, 0.2)")
    if failures:
        sys.exit(f"{len(failures)} check(s) failed")
    print("all checks passed")


if __name__ == "__main__":
    main()
