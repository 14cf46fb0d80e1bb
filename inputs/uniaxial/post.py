#!/usr/bin/python3
"""Post-processing of the uniaxial compression scene (Richefeu 2007 section 4.2).

Usage: post.py OUTDIR RUNDIR [RUNDIR ...]
Each RUNDIR is the output directory of one run of in.lammps or in.liggghts (uniaxial.txt,
summary.txt, optionally start.dump/end.dump). Writes into OUTDIR:
  curves.csv     run, dh/<D>, sigma [Pa] of every run
  strength.csv   one line per run: engine, N, w [%], protocol, half, dry, sigma_rupt [Pa], inertial
                 number, the bridge coordination z at the start of the compression, and the
                 settlement after the mould's removal (below)
  strength-mean.csv  one line per sample (engine, N, w, protocol, half, dry; the packings, i.e.
                 seeds, pooled): n, the means and their standard errors
  stress.png     sigma(dh/<D>) of every run (Richefeu 2007 fig. 10)
  strength.png   sigma_rupt(w) per protocol, with the dry value (Richefeu 2007 fig. 12)
  snapshot.png   vertical slice of the first wet run coloured by displacement (fig. 11), if dumps exist
and prints the strength table.
sigma_rupt is the peak of sigma after a moving average over 5 outputs (1/40 of the travel),
which keeps single-contact spikes of small samples out of the strength.
The settlement (Richefeu 2007 4.2.1: "only a slight settlement of about 0.1 mm due to gravity"
after the cylinder is removed) is given two ways: the drop of the sample's top (the highest grain
touching another, Hseal - Hrelax), which one grain can set, and twice the drop of the centre of
mass (zcm_seal - zcm_relax), the top's drop for a uniform vertical strain of the column, which all
the grains set.
The water content w is in percent of the grains' mass (summary.txt: w_percent, as the decks
take it); a summary of the decks before December 2026 gives w as a mass fraction (key w) and
is refused, not read a hundred times too small.
"""
import csv
import os
import sys
import warnings

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.collections import PatchCollection
from matplotlib.patches import Circle

RHO = 2500.0  # grain density [kg/m^3], as in the decks
# Mohr-Coulomb estimate from Richefeu 2007 Table I (1 mm glass beads GB1: c_m = 150 Pa,
# friction angle 25 deg): unconfined compressive strength 2 c tan(45 + phi/2). The paper's own
# compression strengths (fig. 12) are given in a figure only.
PAPER_ESTIMATE = 2 * 150.0 * np.tan(np.radians(45 + 25 / 2))


def fail(msg):
    sys.exit("post.py: " + msg)


def mean_and_error(values):
    """The mean and its standard error (sample standard deviation / sqrt(n); NaN for n < 2)."""
    n = len(values)
    mean = sum(values) / n
    if n < 2:
        return mean, float("nan")
    sd = np.sqrt(sum((v - mean) ** 2 for v in values) / (n - 1))
    return mean, sd / np.sqrt(n)


def read_summary(run):
    path = os.path.join(run, "summary.txt")
    if not os.path.isfile(path):
        fail(f"missing {path} (did the run of {run} finish?)")
    summary = {}
    with open(path) as f:
        for line in f:
            parts = line.split()
            if len(parts) == 2:
                summary[parts[0]] = parts[1]
    if "w_percent" not in summary and "w" in summary:
        fail(f"{path} gives w {summary['w']} as a mass fraction (a run of the decks before "
             "December 2026, which took w = 0.02 for 2 %): run it again, the decks and this "
             "script take w in percent")
    for key in ("N", "dry", "Dmean", "Hseal", "vwall", "w_percent"):
        if key not in summary:
            fail(f"{path} has no '{key}'")
    return summary


def load_table(path, rows=None):
    """The numbers of a text table (a file, or its lines), or a one-line failure naming it:
    a truncated or damaged file (a run killed while writing) is not read as a short curve."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")    # numpy's "empty input" warning: an error here
        try:
            return np.loadtxt(path if rows is None else rows, comments="#", ndmin=2)
        except (ValueError, UserWarning) as e:
            fail(f"{path} is not a complete table of numbers ({e})")


def read_curve(run):
    path = os.path.join(run, "uniaxial.txt")
    if not os.path.isfile(path):
        fail(f"missing {path} (did the compression of {run} run?)")
    if not os.path.isfile(os.path.join(run, "end.dump")):
        fail(f"{run} has no end.dump: its compression did not finish, so its curve would "
             "give a strength of a part of the travel")
    data = load_table(path)
    if data.shape[0] < 5 or data.shape[1] < 4:
        fail(f"{path} has too few lines or columns ({data.shape})")
    return data


def strength(sigma):
    """Peak of the moving average over 5 outputs."""
    kernel = np.ones(5) / 5
    return float(np.max(np.convolve(sigma, kernel, mode="valid")))


def peak_travel(travel, sigma):
    """The travel (dh/<D>) at the centre of the window whose average is the peak."""
    average = np.convolve(sigma, np.ones(5) / 5, mode="valid")
    return float(travel[int(np.argmax(average)) + 2])


def label(s):
    if s["dry"] == "yes":
        return "dry"
    text = f"w={float(s['w_percent']):g}% {s.get('protocol', '?')}"
    return text + (" half bridges" if s.get("half") == "yes" else "")


def read_dump(path):
    with open(path) as f:
        lines = f.readlines()
    start = next((i for i, l in enumerate(lines) if l.startswith("ITEM: ATOMS")), None)
    if start is None:
        fail(f"{path} has no 'ITEM: ATOMS' section (an empty or truncated dump)")
    cols = lines[start].split()[2:]
    data = load_table(path, lines[start + 1:])
    if data.shape[1] != len(cols) or data.shape[0] == 0:
        fail(f"{path}: {data.shape[0]} atoms of {data.shape[1]} values, its header names "
             f"{len(cols)} columns")
    table = {c: data[:, k] for k, c in enumerate(cols)}
    order = np.argsort(table["id"])
    return {c: v[order] for c, v in table.items()}


def snapshot(run, out_png, dmean):
    a = read_dump(os.path.join(run, "start.dump"))
    b = read_dump(os.path.join(run, "end.dump"))
    if not np.array_equal(a["id"], b["id"]):
        fail(f"{run}: start.dump and end.dump hold different atoms")
    disp = np.sqrt((b["x"] - a["x"]) ** 2 + (b["y"] - a["y"]) ** 2 + (b["z"] - a["z"]) ** 2)
    inslice = np.abs(b["y"]) < dmean / 2
    fig, ax = plt.subplots(figsize=(6, 4.5))
    circles = [Circle((x * 1e3, z * 1e3), r * 1e3)
               for x, z, r in zip(b["x"][inslice], b["z"][inslice], b["radius"][inslice])]
    pc = PatchCollection(circles, cmap="viridis")
    pc.set_array(disp[inslice] * 1e3)
    pc.set_clim(0, np.percentile(disp[inslice] * 1e3, 98))  # a few fast grains would wash it out
    ax.add_collection(pc)
    ax.autoscale_view()
    ax.set_aspect("equal")
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("z [mm]")
    ax.set_title(f"{os.path.basename(os.path.normpath(run))}: slice |y| < <D>/2 at the end")
    fig.colorbar(pc, ax=ax, label="displacement during compression [mm]")
    fig.tight_layout()
    fig.savefig(out_png, dpi=120)
    plt.close(fig)


def pooled(rows):
    """The runs of one sample (engine, N, w, protocol, half, dry) over their packings: n, the
    mean and the standard error of sigma_rupt, z at the start and the two settlements."""
    groups = {}
    for r in rows:
        groups.setdefault((r["engine"], r["N"], r["label"]), []).append(r)
    out = []
    for (engine, n_grains, sample), runs in sorted(groups.items()):
        m = dict(engine=engine, N=n_grains, sample=sample, n=len(runs))
        for key, se in (("sigma_rupt_Pa", "sigma_rupt_se"), ("z_start", "z_start_se"),
                        ("peak_at_D", "peak_at_se"),
                        ("settlement_top_mm", "settlement_top_se"),
                        ("settlement_2cm_mm", "settlement_2cm_se")):
            m[key], m[se] = mean_and_error([float(r[key]) for r in runs])
        out.append(m)
    return out


def main(argv):
    if len(argv) < 3:
        fail("usage: post.py OUTDIR RUNDIR [RUNDIR ...]")
    outdir, runs = argv[1], argv[2:]
    os.makedirs(outdir, exist_ok=True)
    rows = []
    fig, ax = plt.subplots(figsize=(6, 4))
    with open(os.path.join(outdir, "curves.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["run", "dh_over_D", "sigma_Pa"])
        for run in runs:
            s, data = read_summary(run), read_curve(run)
            name = os.path.basename(os.path.normpath(run))
            for x, y in zip(data[:, 2], data[:, 3]):
                w.writerow([name, f"{x:.6g}", f"{y:.6g}"])
            peak = strength(data[:, 3])
            vwall, hseal, dmean = float(s["vwall"]), float(s["Hseal"]), float(s["Dmean"])
            # inertial number at the peak: (vwall/H) <D> sqrt(rho/sigma_rupt)
            inertial = (vwall / hseal) * dmean * np.sqrt(RHO / peak) if peak > 0 else float("inf")
            drift = float(np.max(np.abs(data[:, 6]))) if data.shape[1] > 6 else float("nan")
            top_mm = 1e3 * (hseal - float(s["Hrelax"])) if "Hrelax" in s else float("nan")
            cm_mm = (2e3 * (float(s["zcm_seal"]) - float(s["zcm_relax"]))
                     if "zcm_relax" in s else float("nan"))
            rows.append(dict(run=name, engine=s.get("engine", "lammps"), N=s["N"],
                             w_percent=s["w_percent"], protocol=s.get("protocol", ""),
                             half=s.get("half", "no"), dry=s["dry"],
                             sigma_rupt_Pa=f"{peak:.4g}", inertial=f"{inertial:.3g}",
                             vwall=s["vwall"], liquid_drift=f"{drift:.3g}", label=label(s),
                             z_start=f"{data[0, 5]:.4g}", seed=s.get("seed", ""),
                             peak_at_D=f"{peak_travel(data[:, 2], data[:, 3]):.3g}",
                             settlement_top_mm=f"{top_mm:.4g}",
                             settlement_2cm_mm=f"{cm_mm:.4g}"))
            ax.plot(data[:, 2], data[:, 3], label=f"{label(s)} ({s.get('engine', 'lammps')}, N={s['N']})")
    ax.set_xlabel("δh / <D>")
    ax.set_ylabel("σ [Pa]")
    ax.set_title("Uniaxial compression: axial stress on the top wall")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "stress.png"), dpi=120)
    plt.close(fig)

    keys = ["run", "engine", "N", "w_percent", "protocol", "half", "dry", "seed", "sigma_rupt_Pa",
            "inertial", "vwall", "liquid_drift", "z_start", "peak_at_D", "settlement_top_mm",
            "settlement_2cm_mm"]
    with open(os.path.join(outdir, "strength.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys, extrasaction="ignore")
        w.writeheader()
        w.writerows(rows)
    means = pooled(rows)
    with open(os.path.join(outdir, "strength-mean.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(means[0].keys()))
        w.writeheader()
        w.writerows(means)

    fig, ax = plt.subplots(figsize=(5, 4))
    groups = {}
    for r in rows:
        if r["dry"] == "yes":
            ax.axhline(float(r["sigma_rupt_Pa"]), color="k", ls=":", label=f"dry ({r['engine']})")
            continue
        key = (r["engine"], r["protocol"] + (" half" if r["half"] == "yes" else ""))
        groups.setdefault(key, []).append((float(r["w_percent"]), float(r["sigma_rupt_Pa"])))
    for (engine, proto), pts in sorted(groups.items()):
        pts.sort()
        ax.plot([p[0] for p in pts], [p[1] for p in pts], "o-", label=f"{proto} ({engine})")
    ax.axhline(PAPER_ESTIMATE, color="r", ls="--", lw=0.8,
               label="Mohr-Coulomb from Richefeu Table I (GB1)")
    ax.set_xlabel("water content w [%]")
    ax.set_ylabel("σ_rupt [Pa]")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "strength.png"), dpi=120)
    plt.close(fig)

    wet = [r for r in rows if r["dry"] == "no"]
    if wet and os.path.isfile(os.path.join(runs[rows.index(wet[0])], "end.dump")):
        run = runs[rows.index(wet[0])]
        snapshot(run, os.path.join(outdir, "snapshot.png"), float(read_summary(run)["Dmean"]))

    print(f"{'engine':<9} {'run':<26} {'N':>5} {'sample':<30} {'sigma_rupt [Pa]':>15} {'inertial I':>10}")
    for r in rows:
        print(f"{r['engine']:<9} {r['run']:<26} {r['N']:>5} {r['label']:<30} {r['sigma_rupt_Pa']:>15} {r['inertial']:>10}")
    print("\n| engine | N | sample | packings | sigma_rupt [Pa] | z at the start | peak at dh/<D> | "
          "settlement: top, 2 x centre of mass [mm] |")
    print("|---|---|---|---|---|---|---|---|")
    for m in means:
        print(f"| {m['engine']} | {m['N']} | {m['sample']} | {m['n']} | {m['sigma_rupt_Pa']:.4g} ± "
              f"{m['sigma_rupt_se']:.2g} | {m['z_start']:.3g} ± {m['z_start_se']:.2g} | "
              f"{m['peak_at_D']:.2g} ± {m['peak_at_se']:.2g} | "
              f"{m['settlement_top_mm']:.3f} ± {m['settlement_top_se']:.2g}, "
              f"{m['settlement_2cm_mm']:.3f} ± {m['settlement_2cm_se']:.2g} |")
    print(f"paper scale (Mohr-Coulomb from Richefeu 2007 Table I, 1 mm glass beads: c = 150 Pa, "
          f"25 deg): sigma_rupt ~ {PAPER_ESTIMATE:.0f} Pa")


if __name__ == "__main__":
    main(sys.argv)
