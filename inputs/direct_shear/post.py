#!/usr/bin/python3
"""Post-processing of the direct shear runs (Richefeu 2007 section 3.2, Figs. 5-7).

Usage: /usr/bin/python3 inputs/direct_shear/post.py RUN_DIR [RUN_DIR ...] --out DIR

Every RUN_DIR (or any directory below it) holding a shear.txt written by in.lammps or in.liggghts
is one run; its first line gives the parameters (engine, size, sigma, w, protocol, bonds, law).
Writes into DIR:
  runs.csv          one line per run: the shear strength (the plateau mean of tau, see below),
                    the peak of tau, the normal stress on the shear plane, bonds, liquid check,
                    the seed; where the deck writes the wall forces (in.lammps since 2026-12-03),
                    the plateau mean of each wall part's x force over pi R^2 (see WALL_PARTS),
                    and the stresses across the split over the common section of the two parts
                    (tau_common, sigma_n_common; common_fraction, its plateau mean share of
                    pi R^2: see strength())
  mohr_coulomb.csv  per engine, protocol, bonds and w with at least two stresses: the fit
                    tau = sigma_n tan(phi) + c (least squares over every run: all sigmas and
                    seeds), the standard errors of tan(phi) and c from the residuals (with four
                    runs or more) and from the seeds (the same fit per seed, the standard error
                    of the mean over the seeds, with two seeds or more), and c_dry_phi, the
                    cohesion with the friction of the dry fit (the paper's lines are parallel);
                    the same fit across the split (plane) and over the common section (common)
  curves_*.png      tau against dx/<D> (Fig. 5), one file per engine and protocol
  yield_loci.png    tau against sigma_n with the fitted lines (Fig. 6a)
  cohesion.png      c against w (Fig. 6b), with the paper's saturation c_m = 120 Pa (simulation)
                    and 150 Pa (experiment, 1 mm glass beads)
  half_bonds.png    tau and the bond coordination against dx/<D> for bonds all / half at the
                    same sigma and w (Fig. 7), when such runs are present
Shear strength: the paper finds no peak (Fig. 5: the residual state is reached after about one
<D>), so the strength is the mean of tau over the plateau, dx >= min(1, dx_max/2) <D>; the peak
(the largest tau) is reported next to it.
Steady state (issue 18 item 3: a residual strength only where the curve is steady): the plateau
is split into its two halves; each half's mean has a standard error from 4 block means (the
blocks, each a quarter of a half, are long against tau's fluctuations, which single outputs are
not); the plateau is steady when the two means agree within 2 combined standard errors
(runs.csv: tau_half1_Pa, tau_half2_Pa, their se, steady yes/no).
"""
import argparse
import csv
import math
import os
import sys

import numpy as np

COLUMNS = ["step", "dx_m", "dx_over_D", "tau_Pa", "sigma_plate_Pa", "sigma_n_Pa", "phi",
           "bridges", "z_bond", "liquid_m3", "liquid_rel_change", "ke_J"]
# the x force of each wall part on the grains above / below the split, and the plate's (the
# plate takes it from the grains; it acts on them with the opposite sign), in shear.txt of
# in.lammps: tau = (ring_above + ring_below - plate) / (pi R^2).  The force across the split
# is the x balance of the grains above it: tau_plane = (ring_above + lowring_above - plate) /
# (pi R^2) (without the rings' edges pushing the grains on the other side of the split), on
# the normal stress sigma_n - fz_rims_above / (pi R^2) (the lower ring's rim carries part of
# the grains above the split)
WALL_PARTS = ["fx_ring_above_N", "fx_ring_below_N", "fx_lowring_above_N", "fx_lowring_below_N",
              "fx_plate_N", "fz_rims_above_N"]
PAPER_CM_SIM = 120.0   # Pa, Richefeu 2007 section 3.2.2 (simulations, saturation)
PAPER_CM_EXP = 150.0   # Pa, Richefeu 2007 Table I / Fig. 4 (experiment, 1 mm glass beads)


def fail(message):
    sys.exit(f"post.py: {message}")


def read_run(path):
    with open(path) as f:
        lines = f.readlines()
    if not lines or not lines[0].startswith("# engine"):
        fail(f"{path}: the first line should be the parameter line '# engine ...'")
    words = lines[0][1:].split()
    params = dict(zip(words[0::2], words[1::2]))
    for key in ("engine", "size", "sigma", "w", "protocol", "bonds", "law", "Dmean"):
        if key not in params:
            fail(f"{path}: no '{key}' in the parameter line")
    if float(params["w"]) == 0:
        params["protocol"] = "dry"   # no liquid: the protocol does not matter
    # the column names: the title line '# step ...' (runs before 2026-12-03 have COLUMNS only)
    names = next((line[1:].split() for line in lines if line.startswith("# step ")), COLUMNS)
    if names[:len(COLUMNS)] != COLUMNS:
        fail(f"{path}: the columns should start with {' '.join(COLUMNS)}, not {' '.join(names)}")
    rows = [line.split() for line in lines if line.strip() and not line.startswith("#")]
    if len(rows) < 3:
        fail(f"{path}: fewer than 3 output lines (did the run finish?)")
    for k, row in enumerate(rows):
        if len(row) != len(names):
            fail(f"{path}: output line {k + 1} has {len(row)} values, expected {len(names)} "
                 "(a truncated or damaged file)")
    try:
        data = np.array([[float(v) for v in row] for row in rows])
    except ValueError as e:
        fail(f"{path}: {e}")
    d = {name: data[:, i] for i, name in enumerate(names)}
    # a run that stopped early would give the plateau of a part of the shear (nD: the planned
    # shear, in the parameter line since 2026-12-02)
    if "nD" in params and d["dx_over_D"][-1] < 0.95 * float(params["nD"]):
        fail(f"{path}: the shear stopped at {d['dx_over_D'][-1]:.3g} <D> of "
             f"{params['nD']} (did the run finish?)")
    return params, d


def halves_agree(tau, blocks=4):
    """The two halves of a plateau: their means, the standard errors of these from `blocks`
    block means each, and whether they agree within 2 combined standard errors."""
    half = len(tau) // 2
    out = []
    for part in (tau[:half], tau[half:2 * half]):
        block_means = [float(b.mean()) for b in np.array_split(part, blocks)]
        out.append((float(part.mean()), float(np.std(block_means, ddof=1) / math.sqrt(blocks))))
    (m1, e1), (m2, e2) = out
    return m1, e1, m2, e2, abs(m1 - m2) <= 2 * math.hypot(e1, e2)


def common_fraction(dx, radius):
    """The common section of the two parts of the cell (Richefeu 3.1.1: the sample is sheared
    "along the common section of the two parts"), two circles of radius R offset by dx, over
    the cell's section pi R^2: (2/pi)(acos(u) - u sqrt(1 - u^2)), u = dx / 2R."""
    u = np.clip(np.asarray(dx) / (2.0 * radius), 0.0, 1.0)
    return (2.0 / math.pi) * (np.arccos(u) - u * np.sqrt(1.0 - u * u))


def strength(d, area):
    """Plateau mean and standard deviation of tau, peak of tau, mean sigma_n on the plateau;
    the plateau mean of each wall part's x force over the section `area` (when written), and
    the stresses across the split over the common section (tau_common, sigma_n_common)."""
    x = d["dx_over_D"]
    start = min(1.0, x[-1] / 2)
    on = x >= start
    s = dict(plateau_from=start, tau=float(d["tau_Pa"][on].mean()),
             tau_std=float(d["tau_Pa"][on].std()), tau_peak=float(d["tau_Pa"].max()),
             sigma_n=float(d["sigma_n_Pa"][on].mean()),
             sigma_plate=float(d["sigma_plate_Pa"][on].mean()))
    s["tau_half1"], s["tau_half1_se"], s["tau_half2"], s["tau_half2_se"], steady = \
        halves_agree(d["tau_Pa"][on])
    s["steady"] = "yes" if steady else "no"
    for name in WALL_PARTS:
        s["tau_" + name[:-2] + "_Pa"] = (float(d[name][on].mean()) / area if name in d
                                          else float("nan"))
    s["tau_plane_Pa"] = (s["tau_fx_ring_above_Pa"] + s["tau_fx_lowring_above_Pa"]
                         - s["tau_fx_plate_Pa"])
    s["sigma_n_plane_Pa"] = s["sigma_n"] - s["tau_fz_rims_above_Pa"]
    # the paper's tau = T/S and sigma = N/S + rho g h are over the lid's area S, the cell's
    # section; across the split the grains touch only on the common section, which shrinks as
    # the upper part moves (0.91 of the section at 1 <D>, 0.73 at 3 <D> in the default cell of
    # 23.6 mm, 0.95 and 0.86 in the paper's 46 mm cell): the same forces over it, row by row
    fraction = common_fraction(d["dx_m"], math.sqrt(area / math.pi))
    s["common_fraction"] = float(fraction[on].mean())
    if all(name in d for name in WALL_PARTS):
        force = d["fx_ring_above_N"] + d["fx_lowring_above_N"] - d["fx_plate_N"]
        normal = d["sigma_n_Pa"] * area - d["fz_rims_above_N"]
        s["tau_common_Pa"] = float((force / (fraction * area))[on].mean())
        s["sigma_n_common_Pa"] = float((normal / (fraction * area))[on].mean())
    else:
        s["tau_common_Pa"] = s["sigma_n_common_Pa"] = float("nan")
    return s


def find_runs(roots):
    runs = []
    for root in roots:
        if not os.path.isdir(root):
            fail(f"no directory {root}")
        for here, _, files in os.walk(root):
            if "shear.txt" in files:
                path = os.path.join(here, "shear.txt")
                params, data = read_run(path)
                runs.append((path, params, data))
    if not runs:
        fail(f"no shear.txt under {' '.join(roots)}")
    return runs


def key_of(p):
    return (p["engine"], p["protocol"], p["bonds"])


def write_runs(runs, out):
    rows = []
    for path, p, d in runs:
        s = strength(d, math.pi * float(p["R"]) ** 2)
        rows.append(dict(engine=p["engine"], size=p["size"], protocol=p["protocol"], bonds=p["bonds"],
                         law=p["law"], seed=p.get("seed", "deck"), sigma_Pa=float(p["sigma"]),
                         w_percent=float(p["w"]),
                         vshear_m_s=p.get("vshear", ""),   # runs before -var vshear: the size's
                         sigma_n_Pa=s["sigma_n"], sigma_plate_Pa=s["sigma_plate"],
                         tau_plateau_Pa=s["tau"], tau_plateau_std_Pa=s["tau_std"],
                         tau_peak_Pa=s["tau_peak"], plateau_from_D=s["plateau_from"],
                         tau_half1_Pa=s["tau_half1"], tau_half1_se_Pa=s["tau_half1_se"],
                         tau_half2_Pa=s["tau_half2"], tau_half2_se_Pa=s["tau_half2_se"],
                         steady=s["steady"],
                         dx_end_D=float(d["dx_over_D"][-1]), phi_end=float(d["phi"][-1]),
                         z_bond_start=float(d["z_bond"][0]), z_bond_end=float(d["z_bond"][-1]),
                         liquid_max_abs_rel_change=float(np.abs(d["liquid_rel_change"]).max()),
                         **{k: v for k, v in s.items() if k.startswith(("tau_f", "tau_plane"))},
                         sigma_n_plane_Pa=s["sigma_n_plane_Pa"],
                         common_fraction=s["common_fraction"], tau_common_Pa=s["tau_common_Pa"],
                         sigma_n_common_Pa=s["sigma_n_common_Pa"],
                         run=os.path.basename(os.path.dirname(path))))
    rows.sort(key=lambda r: (r["engine"], r["protocol"], r["bonds"], r["w_percent"], r["sigma_Pa"],
                             r["seed"]))
    with open(os.path.join(out, "runs.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        for r in rows:
            writer.writerow({k: (f"{v:.6g}" if isinstance(v, float) else v) for k, v in r.items()})
    return rows


def line_fit(rs, tau="tau_plateau_Pa", sigma="sigma_n_Pa"):
    """tau = tan(phi) sigma_n + c over the runs `rs` by least squares: slope, intercept and
    their standard errors from the residuals (nan with fewer than 4 runs; nan for all with
    fewer than 2 stresses or without the columns)."""
    s = np.array([r[sigma] for r in rs])
    t = np.array([r[tau] for r in rs])
    if len({r["sigma_Pa"] for r in rs}) < 2 or not np.isfinite(t).all():
        return (float("nan"),) * 4
    if len(rs) < 4:  # numpy's covariance needs more points than parameters + 1
        slope, c = np.polyfit(s, t, 1)
        return float(slope), float(c), float("nan"), float("nan")
    (slope, c), cov = np.polyfit(s, t, 1, cov="unscaled")
    resid = t - (slope * s + c)
    scale = float(resid @ resid) / (len(rs) - 2)
    return float(slope), float(c), math.sqrt(scale * cov[0, 0]), math.sqrt(scale * cov[1, 1])


def sem(values):
    """Standard error of the mean (nan for fewer than two values)."""
    v = np.array(values, dtype=float)
    return float(v.std(ddof=1) / math.sqrt(len(v))) if len(v) > 1 else float("nan")


def fit_mohr_coulomb(rows, out):
    groups = {}
    for r in rows:
        groups.setdefault((r["engine"], r["protocol"], r["bonds"], r["w_percent"]), []).append(r)
    fits = []
    for (engine, protocol, bonds, w), rs in sorted(groups.items()):
        if len({r["sigma_Pa"] for r in rs}) < 2:
            continue
        slope, c, slope_se, c_se = line_fit(rs)
        per_seed = [line_fit([r for r in rs if r["seed"] == seed])
                    for seed in sorted({r["seed"] for r in rs})]
        per_seed = [f for f in per_seed if not math.isnan(f[0])]
        plane = line_fit(rs, "tau_plane_Pa", "sigma_n_plane_Pa")
        common = line_fit(rs, "tau_common_Pa", "sigma_n_common_Pa")
        fits.append(dict(engine=engine, protocol=protocol, bonds=bonds, w_percent=w,
                         n_stresses=len({r["sigma_Pa"] for r in rs}), n_runs=len(rs),
                         n_seeds=len(per_seed), tan_phi=slope, tan_phi_se=slope_se,
                         tan_phi_se_seeds=sem([f[0] for f in per_seed]),
                         phi_deg=math.degrees(math.atan(slope)), c_Pa=c, c_se_Pa=c_se,
                         c_se_seeds_Pa=sem([f[1] for f in per_seed]),
                         tan_phi_plane=plane[0], tan_phi_plane_se=plane[2],
                         c_plane_Pa=plane[1], c_plane_se_Pa=plane[3],
                         tan_phi_common=common[0], tan_phi_common_se=common[2],
                         c_common_Pa=common[1], c_common_se_Pa=common[3]))
    # the paper finds the Coulomb lines of all w parallel (section 3.1.3): c with the dry friction
    # of the same engine, the mean of tau - tan(phi_dry) sigma_n (robust with few, noisy points)
    for f in fits:
        dry = [d for d in fits if d["engine"] == f["engine"] and d["protocol"] == "dry"]
        rs = groups[(f["engine"], f["protocol"], f["bonds"], f["w_percent"])]
        f["c_dry_phi_Pa"] = (float(np.mean([r["tau_plateau_Pa"] - dry[0]["tan_phi"] * r["sigma_n_Pa"]
                                            for r in rs])) if dry else float("nan"))
    with open(os.path.join(out, "mohr_coulomb.csv"), "w", newline="") as f:
        names = ["engine", "protocol", "bonds", "w_percent", "n_stresses", "n_runs", "n_seeds",
                 "tan_phi", "tan_phi_se", "tan_phi_se_seeds", "phi_deg", "c_Pa", "c_se_Pa",
                 "c_se_seeds_Pa", "tan_phi_plane", "tan_phi_plane_se", "c_plane_Pa",
                 "c_plane_se_Pa", "tan_phi_common", "tan_phi_common_se", "c_common_Pa",
                 "c_common_se_Pa", "c_dry_phi_Pa"]
        writer = csv.DictWriter(f, fieldnames=names)
        writer.writeheader()
        for r in fits:
            writer.writerow({k: (f"{v:.6g}" if isinstance(v, float) else v) for k, v in r.items()})
    return fits


def runs_dry(runs, engine, sigma):
    return [(p, d) for _, p, d in runs
            if p["engine"] == engine and p["protocol"] == "dry" and float(p["sigma"]) == sigma]


def plots(runs, rows, fits, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    # Fig. 5: tau(dx/<D>), one file per engine/protocol/bonds, one panel per sigma
    for key in sorted({key_of(p) for _, p, _ in runs}):
        sel = [(p, d) for _, p, d in runs if key_of(p) == key]
        sigmas = sorted({float(p["sigma"]) for p, _ in sel})
        fig, axes = plt.subplots(1, len(sigmas), figsize=(max(6.5, 4.5 * len(sigmas)), 3.6), squeeze=False)
        for ax, sigma in zip(axes[0], sigmas):
            if key[1] != "dry":   # the dry run of the same engine and sigma, for reference (Fig. 5)
                for p, d in runs_dry(runs, key[0], sigma):
                    ax.plot(d["dx_over_D"], d["tau_Pa"], color="k", lw=1, label="dry")
            for p, d in sorted((pd for pd in sel if float(pd[0]["sigma"]) == sigma),
                               key=lambda pd: float(pd[0]["w"])):
                ax.plot(d["dx_over_D"], d["tau_Pa"], lw=1, label=f"w = {p['w']} %")
            ax.set_title(f"sigma = {sigma:g} Pa")
            ax.set_xlabel("dx / <D>")
            ax.set_ylabel("tau [Pa]")
            ax.legend(fontsize=8)
        engine, protocol, bonds = key
        fig.suptitle(f"direct shear, {engine}, protocol {protocol}, bonds {bonds} (size {sel[0][0]['size']})")
        fig.tight_layout()
        fig.savefig(os.path.join(out, f"curves_{engine}_{protocol}_{bonds}.png"), dpi=110)
        plt.close(fig)

    if fits:
        # Fig. 6a: yield loci
        fig, ax = plt.subplots(figsize=(5.5, 4.2))
        for f in fits:
            rs = [r for r in rows if (r["engine"], r["protocol"], r["bonds"], r["w_percent"]) ==
                  (f["engine"], f["protocol"], f["bonds"], f["w_percent"])]
            s = np.array([r["sigma_n_Pa"] for r in rs])
            label = f"{f['engine']} {f['protocol']} {f['bonds']} w={f['w_percent']:g}%"
            line = ax.plot(s, [r["tau_plateau_Pa"] for r in rs], "o")[0]
            xs = np.linspace(0, s.max() * 1.05, 20)
            ax.plot(xs, f["tan_phi"] * xs + f["c_Pa"], "-", color=line.get_color(), label=label)
        ax.set_xlabel("sigma_n [Pa]")
        ax.set_ylabel("tau (plateau) [Pa]")
        ax.set_title("yield loci (Richefeu Fig. 6a)")
        ax.legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(os.path.join(out, "yield_loci.png"), dpi=110)
        plt.close(fig)

        # Fig. 6b: c(w)
        fig, ax = plt.subplots(figsize=(5.5, 4.2))
        for key in sorted({(f["engine"], f["protocol"], f["bonds"]) for f in fits if f["protocol"] != "dry"}):
            dry = [f for f in fits if f["engine"] == key[0] and f["protocol"] == "dry"]
            fs = sorted(dry + [f for f in fits if (f["engine"], f["protocol"], f["bonds"]) == key],
                        key=lambda f: f["w_percent"])
            line = ax.plot([f["w_percent"] for f in fs], [f["c_Pa"] for f in fs], "o-",
                           label=" ".join(key) + ": free fit")[0]
            ax.plot([f["w_percent"] for f in fs], [f["c_dry_phi_Pa"] for f in fs], "s--",
                    color=line.get_color(), label=" ".join(key) + ": dry friction")
        ax.axhline(PAPER_CM_SIM, color="k", ls="--", lw=1, label="paper, simulation c_m")
        ax.axhline(PAPER_CM_EXP, color="gray", ls=":", lw=1, label="paper, experiment 1 mm beads")
        ax.set_xlabel("w [%]")
        ax.set_ylabel("c [Pa]")
        ax.set_title("Coulomb cohesion (Richefeu Fig. 6b)")
        ax.legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(os.path.join(out, "cohesion.png"), dpi=110)
        plt.close(fig)

    # Fig. 7: half bonds against all bonds (and dry) at the same sigma and w
    halves = [(p, d) for _, p, d in runs if p["bonds"] == "half"]
    if halves:
        fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 3.8))
        for ph, dh in halves:
            same = [(p, d) for _, p, d in runs if p["engine"] == ph["engine"] and
                    p["sigma"] == ph["sigma"] and (p["w"] == ph["w"] or float(p["w"]) == 0) and
                    p["bonds"] == "all" and (p["protocol"] == ph["protocol"] or float(p["w"]) == 0)]
            for p, d in same + [(ph, dh)]:
                label = f"{p['engine']} w={p['w']}% bonds {p['bonds']}"
                ax1.plot(d["dx_over_D"], d["tau_Pa"], lw=1, label=label)
                if float(p["w"]) > 0:
                    ax2.plot(d["dx_over_D"], d["z_bond"], lw=1, label=label)
        ax1.set_xlabel("dx / <D>")
        ax1.set_ylabel("tau [Pa]")
        ax1.legend(fontsize=7)
        ax1.set_title("half bonds (Richefeu Fig. 7)")
        ax2.set_xlabel("dx / <D>")
        ax2.set_ylabel("bond coordination z")
        ax2.legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(os.path.join(out, "half_bonds.png"), dpi=110)
        plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("runs", nargs="+", help="run directories (searched recursively for shear.txt)")
    parser.add_argument("--out", required=True, help="output directory for CSV and PNG")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    runs = find_runs(args.runs)
    rows = write_runs(runs, args.out)
    fits = fit_mohr_coulomb(rows, args.out)
    plots(runs, rows, fits, args.out)
    for r in rows:
        protocol = f"p{r['protocol']}" if str(r["protocol"]).isdigit() else r["protocol"]
        print(f"{r['engine']:8s} {protocol:10s} {r['bonds']:4s} sigma {r['sigma_Pa']:5g} Pa "
              f"w {r['w_percent']:4g} %: tau {r['tau_plateau_Pa']:7.1f} +- {r['tau_plateau_std_Pa']:5.1f} Pa "
              f"(peak {r['tau_peak_Pa']:6.1f}) sigma_n {r['sigma_n_Pa']:6.1f} Pa z_bond "
              f"{r['z_bond_start']:.2f} -> {r['z_bond_end']:.2f}; halves {r['tau_half1_Pa']:.1f} "
              f"+- {r['tau_half1_se_Pa']:.1f} / {r['tau_half2_Pa']:.1f} +- {r['tau_half2_se_Pa']:.1f} "
              f"Pa: steady {r['steady']}")
    for f in fits:
        print(f"fit {f['engine']} {f['protocol']} {f['bonds']} w {f['w_percent']:g} % "
              f"({f['n_runs']} runs, {f['n_seeds']} seeds): tan(phi) {f['tan_phi']:.3f} "
              f"+- {f['tan_phi_se']:.3f} (seeds {f['tan_phi_se_seeds']:.3f}; phi "
              f"{f['phi_deg']:.1f} deg), c {f['c_Pa']:.1f} +- {f['c_se_Pa']:.1f} Pa (seeds "
              f"{f['c_se_seeds_Pa']:.1f}); with the dry friction: c {f['c_dry_phi_Pa']:.1f} Pa; "
              f"across the split: tan(phi) {f['tan_phi_plane']:.3f} +- {f['tan_phi_plane_se']:.3f}, "
              f"c {f['c_plane_Pa']:.1f} +- {f['c_plane_se_Pa']:.1f} Pa; over the common "
              f"section: tan(phi) {f['tan_phi_common']:.3f} +- {f['tan_phi_common_se']:.3f}, "
              f"c {f['c_common_Pa']:.1f} +- {f['c_common_se_Pa']:.1f} Pa")


if __name__ == "__main__":
    main()
