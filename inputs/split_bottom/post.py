#!/usr/bin/python3
"""Post-processing of the split-bottom runs (Gladkyy & Schwarze 2014, section 4.1).

Usage: /usr/bin/python3 inputs/split_bottom/post.py RUN_DIR [RUN_DIR ...] --out OUT_DIR
                                                    [--rate-min GDOT] [--no-plots]

Each RUN_DIR is the output directory of one run of in.lammps or in.liggghts (scripts/scene.sh
-out).  It must hold the log (log.lammps or log.liggghts, with its SPLIT_BOTTOM_PARAMS line),
torque.txt and the snap.*.txt snapshots.  Writes into OUT_DIR:
  summary.csv             one line per run: law, volume, band centre (with its standard
                          error) and width at mid height, mu and c of tau = mu p + c (c with
                          its standard error from the fit), torque, bridges, inertial number,
                          the seed of the realisation (params.in)
  <run>_omega.csv         omega(r, z)/Omega on the (r, z) grid, with the grain counts
  <run>_band.csv          R_C and W of the fit omega/Omega = 0.5 + 0.5 erf((r - R_C)/W)
                          (Gladkyy eq. 13) for every height
  <run>_stress.csv        p, tau, shear rate per (r, z) cell and whether it is in the band
  shared_mu.csv           tau = mu p + c_V with one mu per engine over all its runs and one c
                          per volume, with standard errors (shared_mu.py, Gladkyy's Fig. 7 fit)
  band_shift.csv          per engine and volume over its runs (seeds, laws): R_C at mid
                          height, R_C and R_C + W over the upper half, over Rs, with standard
                          errors, and each wet group's shift from the dry group
  omega_profiles.png      omega(r)/Omega at a few heights with the erf fits, every run
  shear_bands.png         R_C(z) and R_C + W(z), every run (Gladkyy Fig. 6)
  tau_p.png               tau against p in the band with the fits (Gladkyy Fig. 7)
  torque.png              mean torque on the rotating part per run (Gladkyy Fig. 8)

Definitions (kept simple; see docs/results/split_bottom.md):
  * omega of a grain = (x vy - y vx)/r^2; averaged per cell (r bins of d/2, z bins of d) over
    all grains and snapshots of the averaging window.
  * stress: per-atom stress*volume S (pair part) of the grains summed per cell and divided by
    the cell volume, pressure tensor P = -S/V_cell; p = tr(P)/3, tau = sqrt(P_rphi^2 + P_zphi^2).
  * shear rate = r sqrt((d omega/dr)^2 + (d omega/dz)^2), the engineering shear rate of the
    mean azimuthal flow (twice the r-phi, z-phi components of the strain rate tensor).  In the band: shear rate above GDOT, by default
    Gladkyy's 0.12 /s times Omega/Omega_paper (Omega_paper = 2 pi/100 s), since the rates
    scale with the rotation rate.
  * inertial number I = shear rate * d / sqrt(p/rho), median over the band cells.
  * standard error of R_C at mid height: block jackknife, the snapshots in 5 consecutive
    blocks, each left out once and the erf refitted (neighbouring snapshots are correlated).
"""
import argparse
import csv
import glob
import math
import os
import re
import sys
import warnings

import numpy as np

from shared_mu import write_shared_mu

OMEGA_PAPER = 2 * math.pi / 100.0
GDOT_PAPER = 0.12


class PostError(Exception):
    """A missing or malformed output of a run."""


def find_log(run):
    for name in ("log.lammps", "log.liggghts"):
        path = os.path.join(run, name)
        if os.path.isfile(path):
            return path
    raise PostError(f"{run}: no log.lammps or log.liggghts (is this a split_bottom run directory?)")


def load_table(path, rows=None):
    """The numbers of a text table (a file, or its lines): a truncated or damaged file (a
    run killed while writing) is a PostError naming it, not a traceback or a short table."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")    # numpy's "empty input" warning: an error here
        try:
            return np.loadtxt(path if rows is None else rows, comments="#", ndmin=2)
        except (ValueError, UserWarning) as e:
            raise PostError(f"{path} is not a complete table of numbers ({e})")


def read_params(log):
    """The SPLIT_BOTTOM_PARAMS line the deck prints: name value pairs; and the run must have
    finished (SPLIT_BOTTOM_DONE), or its averages would be of a part of the window."""
    with open(log) as f:
        if not any(line.startswith("SPLIT_BOTTOM_DONE") for line in f):
            raise PostError(f"{log}: no SPLIT_BOTTOM_DONE line: the run did not finish")
    with open(log) as f:
        for line in f:
            if line.startswith("SPLIT_BOTTOM_PARAMS"):
                words = line.split()[1:]
                params = dict(zip(words[0::2], words[1::2]))
                for k, v in params.items():
                    try:
                        params[k] = float(v)
                    except ValueError:
                        pass
                return params
    raise PostError(f"{log}: no SPLIT_BOTTOM_PARAMS line (the deck stopped before it?)")


def read_thermo(log):
    """All thermo rows (Step v_tnow Atoms c_ke bridges liquid torque) of the log."""
    rows = []
    header = None
    with open(log) as f:
        for line in f:
            words = line.split()
            # LAMMPS prints "Step v_tnow ...", LIGGGHTS "Step tnow ..."
            if words[:2] in (["Step", "v_tnow"], ["Step", "tnow"]):
                header = words
                continue
            if header and len(words) == len(header):
                try:
                    rows.append([float(w) for w in words])
                except ValueError:
                    header = None
            elif header:
                header = None
    if not rows:
        raise PostError(f"{log}: no thermo rows")
    return np.array(rows)


def read_torque(run):
    path = os.path.join(run, "torque.txt")
    if not os.path.isfile(path):
        raise PostError(f"{path} missing")
    data = load_table(path)
    if data.size == 0:
        raise PostError(f"{path} is empty")
    return data  # step, torque


def read_snapshots(run):
    files = sorted(glob.glob(os.path.join(run, "snap.*.txt")),
                   key=lambda p: int(re.findall(r"snap\.(\d+)\.txt", p)[0]))
    if not files:
        raise PostError(f"{run}: no snap.*.txt snapshots (did the averaging window run?)")
    snaps = []
    for path in files:
        with open(path) as f:
            lines = f.readlines()
        start = next((i for i, l in enumerate(lines) if l.startswith("ITEM: ATOMS")), None)
        if start is None:
            raise PostError(f"{path}: not a dump custom file")
        cols = lines[start].split()[2:]
        data = load_table(path, lines[start + 1:])
        if data.shape[1] != len(cols):
            raise PostError(f"{path}: {data.shape[1]} values an atom, its header names "
                            f"{len(cols)}")
        snaps.append({c: data[:, i] for i, c in enumerate(cols)})
    return snaps


def erf_fit(r, y, w):
    """Least-squares fit of y = 0.5 + 0.5 erf((r - rc)/W), weights w: grid, then Gauss-Newton."""
    erf = np.vectorize(math.erf)
    span = r.max() - r.min()
    best = None
    for rc in np.linspace(r.min(), r.max(), 60):
        for W in np.linspace(span / 100, span, 60):
            res = np.sum(w * (0.5 + 0.5 * erf((r - rc) / W) - y) ** 2)
            if best is None or res < best[0]:
                best = (res, rc, W)
    _, rc, W = best
    for _ in range(30):
        u = (r - rc) / W
        f = 0.5 + 0.5 * erf(u) - y
        g = np.exp(-u * u) / math.sqrt(math.pi)
        J = np.column_stack([-g / W, -g * u / W])
        A = J.T @ (J * w[:, None])
        b = J.T @ (w * f)
        try:
            step = np.linalg.solve(A, -b)
        except np.linalg.LinAlgError:
            break
        rc, W = rc + step[0], abs(W + step[1])
        if abs(step[0]) < 1e-12 and abs(step[1]) < 1e-12:
            break
    return rc, W


def analyse(run, rate_min=None):
    log = find_log(run)
    P = read_params(log)
    thermo = read_thermo(log)
    torque = read_torque(run)
    snaps = read_snapshots(run)
    R, d, Omega = P["R"], 2 * P["R"], P["Omega"]
    Ri, Ro, H = P["Ri"], P["Ro"], P["H"]
    dr, dz = d / 2, d
    redges = np.arange(Ri, Ro + dr / 2, dr)
    zedges = np.arange(0.5 * d, 1.6 * H, dz)
    nr, nz = len(redges) - 1, len(zedges) - 1
    count = np.zeros((nr, nz))
    wsum = np.zeros((nr, nz))
    S = {k: np.zeros((nr, nz)) for k in ("rphi", "zphi", "tr")}
    count_of, wsum_of = [], []  # per snapshot, for the standard error of R_C
    for s in snaps:
        x, y, z = s["x"], s["y"], s["z"]
        r = np.hypot(x, y)
        ir = np.searchsorted(redges, r) - 1
        iz = np.searchsorted(zedges, z) - 1
        ok = (ir >= 0) & (ir < nr) & (iz >= 0) & (iz < nz)
        ir, iz = ir[ok], iz[ok]
        omega = ((x * s["vy"] - y * s["vx"]) / r ** 2)[ok]
        c, sn = (x / r)[ok], (y / r)[ok]
        sxx, syy, szz = s["c_stress[1]"][ok], s["c_stress[2]"][ok], s["c_stress[3]"][ok]
        sxy, sxz, syz = s["c_stress[4]"][ok], s["c_stress[5]"][ok], s["c_stress[6]"][ok]
        # e_r = (c, s, 0), e_phi = (-s, c, 0): S_rphi = e_r.S.e_phi, S_zphi = e_z.S.e_phi
        s_rphi = -c * sn * sxx + c * sn * syy + (c * c - sn * sn) * sxy
        s_zphi = -sn * sxz + c * syz
        count_of.append(np.zeros((nr, nz)))
        wsum_of.append(np.zeros((nr, nz)))
        np.add.at(count_of[-1], (ir, iz), 1)
        np.add.at(wsum_of[-1], (ir, iz), omega)
        count += count_of[-1]
        wsum += wsum_of[-1]
        np.add.at(S["rphi"], (ir, iz), s_rphi)
        np.add.at(S["zphi"], (ir, iz), s_zphi)
        np.add.at(S["tr"], (ir, iz), sxx + syy + szz)
    nsnap = len(snaps)
    rc_ = 0.5 * (redges[1:] + redges[:-1])
    zc_ = 0.5 * (zedges[1:] + zedges[:-1])
    with np.errstate(invalid="ignore", divide="ignore"):
        omega = wsum / count  # rad/s
    vol = (math.pi * (redges[1:] ** 2 - redges[:-1] ** 2))[:, None] * dz
    # pressure tensor P = -S/V (compression positive), averaged over the snapshots
    p = -S["tr"] / 3 / vol / nsnap
    tau = np.hypot(S["rphi"], S["zphi"]) / vol / nsnap
    # shear rate of the mean flow
    dwdr = np.gradient(omega, rc_, axis=0)
    dwdz = np.gradient(omega, zc_, axis=1)
    gdot = rc_[:, None] * np.hypot(dwdr, dwdz)
    # cells fully inside the material: enough grains per snapshot, away from walls and surface
    dense = count / nsnap >= 0.5 * (0.55 * vol / (4 / 3 * math.pi * R ** 3))
    interior = dense & (rc_[:, None] > Ri + d) & (rc_[:, None] < Ro - d) & (zc_[None, :] > 1.5 * d)
    if rate_min is None:
        rate_min = GDOT_PAPER * Omega / OMEGA_PAPER
    band = interior & (gdot > rate_min)
    # the erf fit per height: rows with at least 6 dense cells
    fits = []
    for j in range(nz):
        m = dense[:, j] & np.isfinite(omega[:, j])
        if m.sum() < 6:
            continue
        rcen, W = erf_fit(rc_[m], omega[m, j] / Omega, count[m, j])
        # a profile that is not a step (e.g. at the free surface of a large cell) sends the
        # fit away: a centre outside the cells fitted or a width beyond their span is no band
        span = rc_[m].max() - rc_[m].min()
        if not (rc_[m].min() <= rcen <= rc_[m].max() and 0.0 < W <= span):
            continue
        fits.append((zc_[j], rcen, W))
    if not fits:
        raise PostError(f"{run}: no height with enough grains for the erf fit")
    mid = min(fits, key=lambda f: abs(f[0] - 0.5 * H))
    rc_mid_se = block_jackknife_rc(count_of, wsum_of, mid, zc_, rc_, dense, Omega)
    # tau = mu p + c over the band cells; the intercept's standard error from the fit
    mu = c0 = c_se = inertial = float("nan")
    if band.sum() >= 4:  # numpy's covariance needs more points than parameters + 2
        (mu, c0), cov = np.polyfit(p[band], tau[band], 1, cov=True)
        c_se = float(math.sqrt(cov[1, 1]))
    elif band.sum() == 3:
        mu, c0 = np.polyfit(p[band], tau[band], 1)
    if band.sum() >= 3:
        inertial = float(np.median(gdot[band] * d / np.sqrt(np.maximum(p[band], 1e-30) / P["rho"])))
    # time series: averaging window is t >= tavg after the start of the shear
    dt = P["dt"]
    tt = torque[:, 0] * dt
    win = tt >= P["tavg"]
    if not win.any():
        raise PostError(f"{run}: torque.txt does not reach the averaging window")
    # the drive: minus the torque of the grains on the rotating part
    M = -torque[win, 1]
    th = thermo
    shear = th[:, 1] >= 0  # all rows; the shear rows are those after the reset of time
    # rows of the shear stage: the last block where time restarts from 0
    restart = np.where(np.diff(th[:, 1]) < 0)[0]
    if len(restart):
        th_shear = th[restart[-1] + 1:]
    else:
        th_shear = th[shear]
    in_win = th_shear[:, 1] >= P["tavg"]
    bridges = th_shear[in_win, 4]
    liquid = th_shear[in_win, 5]
    grains = int(np.median([len(s["id"]) for s in snaps]))
    lost = int(th[0, 2] - th[-1, 2])
    if lost:
        print(f"post.py: {run}: {lost} grain(s) lost during the run (dropped through the split; "
              "see the deck's thermo_modify)", file=sys.stderr)
    return {
        "run": os.path.basename(os.path.normpath(run)), "params": P, "fits": fits,
        "omega": omega / Omega, "count": count / nsnap, "rc": rc_, "zc": zc_,
        "p": p, "tau": tau, "gdot": gdot, "band": band, "rate_min": rate_min,
        "mu": mu, "c": c0, "inertial": inertial, "torque_mean": float(M.mean()),
        "torque_sem": float(M.std(ddof=1) / math.sqrt(len(M))) if len(M) > 1 else float("nan"),
        "bridges": bridges, "liquid": liquid, "grains": grains, "snapshots": nsnap,
        "z_mid": mid[0], "Rc_mid": mid[1], "W_mid": mid[2], "Rc_mid_se": rc_mid_se,
        "c_se": c_se,
    }


def block_jackknife_rc(count_of, wsum_of, mid, zc_, rc_, dense, Omega, blocks=5):
    """Standard error of R_C at mid height: the snapshots in `blocks` consecutive blocks
    (neighbouring snapshots are correlated), R_C fitted again with each block left out,
    SE = sqrt((n - 1)/n sum (R_C,i - mean)^2).  nan with fewer snapshots than blocks."""
    n = len(count_of)
    if n < blocks:
        return float("nan")
    j = int(np.argmin(abs(zc_ - mid[0])))
    edges = np.linspace(0, n, blocks + 1).round().astype(int)
    count_all = sum(c[:, j] for c in count_of)
    wsum_all = sum(w[:, j] for w in wsum_of)
    estimates = []
    for b in range(blocks):
        left = range(edges[b], edges[b + 1])
        count = count_all - sum(count_of[k][:, j] for k in left)
        wsum = wsum_all - sum(wsum_of[k][:, j] for k in left)
        with np.errstate(invalid="ignore", divide="ignore"):
            omega = wsum / count
        m = dense[:, j] & np.isfinite(omega) & (count > 0)
        if m.sum() < 6:
            return float("nan")
        estimates.append(erf_fit(rc_[m], omega[m] / Omega, count[m])[0])
    estimates = np.array(estimates)
    return float(math.sqrt((blocks - 1) / blocks * np.sum((estimates - estimates.mean()) ** 2)))


def write_csv(path, header, rows):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(header)
        w.writerows(rows)


def engine_label(P):
    """The engine, and the contact where it is not Gladkyy's (dashpot repulsive, overlap none;
    a run without these parameters predates them: LAMMPS dashpot approach or both, LIGGGHTS
    its hooke dashpot both ways, both with overlap contact)."""
    dashpot = P.get("dashpot", "approach" if P["engine"] == "lammps" else "both")
    label = P["engine"] + ("" if dashpot == "repulsive" else " dashpot " + dashpot)
    return label + ("" if P.get("overlap", "contact") == "none" else " overlap contact")


def label(a):
    P = a["params"]
    v = P["volume_nl"]
    return "dry" if v == 0 else f"{P['law']} {v:g} nl"


def mean_se(values):
    """Mean and its standard error (nan for fewer than two values)."""
    v = np.array(values, dtype=float)
    se = float(v.std(ddof=1) / math.sqrt(len(v))) if len(v) > 1 else float("nan")
    return float(v.mean()), se


def band_shift_rows(results):
    """The band per engine and volume over its runs (dry: every seed; wet: every law and seed,
    taken as realisations of one wet material, since the laws give nearly the same flow), and
    each wet group's shift from the same engine's dry group: R_C at mid height, and R_C and
    R_C + W averaged over the fitted heights in the upper half (z >= H/2), where Gladkyy's
    Fig. 6 shows the shift.  Lengths over Rs; standard errors from the run-to-run scatter."""
    groups = {}
    for a in results:
        P = a["params"]
        f = np.array(a["fits"])
        upper = f[f[:, 0] >= 0.5 * P["H"]]
        if not len(upper):
            continue
        groups.setdefault((engine_label(P), P["volume_nl"]), []).append(
            (a["Rc_mid"] / P["Rs"], upper[:, 1].mean() / P["Rs"],
             (upper[:, 1] + upper[:, 2]).mean() / P["Rs"]))
    stats = {key: [mean_se([r[k] for r in runs]) for k in range(3)] + [len(runs)]
             for key, runs in groups.items()}
    rows = []
    for (engine, volume), st in sorted(stats.items()):
        dry = stats.get((engine, 0.0))
        row = [engine, f"{volume:g}", st[3]]
        for k in range(3):
            row += [f"{st[k][0]:.4f}", f"{st[k][1]:.4f}"]
        for k in range(3):
            if dry is None or volume == 0.0:
                row += ["", ""]
            else:
                row += [f"{st[k][0] - dry[k][0]:+.4f}",
                        f"{math.sqrt(st[k][1] ** 2 + dry[k][1] ** 2):.4f}"]
        rows.append(row)
    header = ["engine", "volume_nl", "runs", "Rc_mid", "Rc_mid_se", "Rc_upper", "Rc_upper_se",
              "outer_upper", "outer_upper_se", "shift_Rc_mid", "shift_Rc_mid_se",
              "shift_Rc_upper", "shift_Rc_upper_se", "shift_outer_upper",
              "shift_outer_upper_se"]
    return header, rows


def write_outputs(results, out):
    os.makedirs(out, exist_ok=True)
    rows = []
    for a in results:
        P = a["params"]
        nb = float(np.mean(a["bridges"])) if len(a["bridges"]) else float("nan")
        rows.append([a["run"], engine_label(P), P["size"], P["law"] if P["volume_nl"] else "dry",
                     P["volume_nl"], a["grains"], a["snapshots"], f"{a['z_mid'] / P['H']:.3f}",
                     f"{a['Rc_mid'] / P['Rs']:.4f}", f"{a['Rc_mid_se'] / P['Rs']:.4f}",
                     f"{a['W_mid'] / (2 * P['R']):.3f}",
                     f"{a['mu']:.4f}", f"{a['c']:.4f}", f"{a['c_se']:.4f}",
                     f"{a['torque_mean']:.6e}",
                     f"{a['torque_sem']:.2e}", f"{nb:.1f}", f"{2 * nb / a['grains']:.3f}",
                     f"{a['inertial']:.4f}", f"{a['rate_min']:.4f}", int(P.get("seed", 0))])
        nr, nz = a["omega"].shape
        write_csv(os.path.join(out, f"{a['run']}_omega.csv"),
                  ["r_m", "z_m", "omega_over_Omega", "grains_per_snapshot"],
                  [[f"{a['rc'][i]:.6g}", f"{a['zc'][j]:.6g}", f"{a['omega'][i, j]:.6g}",
                    f"{a['count'][i, j]:.3f}"] for i in range(nr) for j in range(nz)])
        write_csv(os.path.join(out, f"{a['run']}_band.csv"), ["z_m", "R_C_m", "W_m"],
                  [[f"{z:.6g}", f"{rc:.6g}", f"{w:.6g}"] for z, rc, w in a["fits"]])
        write_csv(os.path.join(out, f"{a['run']}_stress.csv"),
                  ["r_m", "z_m", "p_Pa", "tau_Pa", "shear_rate_per_s", "in_band"],
                  [[f"{a['rc'][i]:.6g}", f"{a['zc'][j]:.6g}", f"{a['p'][i, j]:.6g}",
                    f"{a['tau'][i, j]:.6g}", f"{a['gdot'][i, j]:.6g}", int(a["band"][i, j])]
                   for i in range(nr) for j in range(nz)])
    write_csv(os.path.join(out, "summary.csv"),
              ["run", "engine", "size", "law", "volume_nl", "grains", "snapshots", "z_mid_over_H",
               "Rc_mid_over_Rs", "Rc_mid_se_over_Rs", "W_mid_over_d", "mu", "c_Pa", "c_se_Pa",
               "torque_Nm", "torque_sem_Nm",
               "bridges", "bridges_per_grain_z", "inertial_number", "band_rate_min_per_s",
               "seed"], rows)
    write_csv(os.path.join(out, "band_shift.csv"), *band_shift_rows(results))
    try:
        write_shared_mu(os.path.join(out, "shared_mu.csv"),
                        [{"engine": engine_label(a["params"]), "volume": a["params"]["volume_nl"],
                          "seed": int(a["params"].get("seed", 0)), "p": a["p"][a["band"]],
                          "tau": a["tau"][a["band"]]} for a in results])
    except ValueError as e:
        print(f"post.py: no shared_mu.csv: {e}", file=sys.stderr)


def plot(results, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from math import erf
    colors = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    # omega profiles: three heights per run
    fig, axes = plt.subplots(1, 3, figsize=(13, 4), sharey=True)
    for k, a in enumerate(results):
        P = a["params"]
        fits = a["fits"]
        picks = [fits[0], fits[len(fits) // 2], fits[-1]]
        for ax, (z, rcen, W) in zip(axes, picks):
            j = int(np.argmin(abs(a["zc"] - z)))
            m = a["count"][:, j] > 0
            col = colors[k % len(colors)]
            ax.plot(a["rc"][m] / P["Rs"], a["omega"][m, j], "o", ms=3, color=col)
            rr = np.linspace(a["rc"][m].min(), a["rc"][m].max(), 200)
            ax.plot(rr / P["Rs"], [0.5 + 0.5 * erf((q - rcen) / W) for q in rr], "-", color=col,
                    label=f"{label(a)} ({engine_label(a['params'])}), z/H={z / P['H']:.2f}")
    for ax in axes:
        ax.set_xlabel("r / R_s")
        ax.legend(fontsize=6)
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("omega / Omega")
    fig.suptitle("Angular velocity profiles and erf fits (Gladkyy eq. 13): bottom, middle, top")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "omega_profiles.png"), dpi=110)
    plt.close(fig)
    # shear bands
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for k, a in enumerate(results):
        P = a["params"]
        f = np.array(a["fits"])
        col = colors[k % len(colors)]
        ax.plot(f[:, 1] / P["Rs"], f[:, 0] / P["H"], "-o", ms=3, color=col,
                label=f"R_C {label(a)} ({engine_label(P)})")
        ax.plot((f[:, 1] + f[:, 2]) / P["Rs"], f[:, 0] / P["H"], ":", color=col)
    ax.set_xlabel("r / R_s  (solid: R_C, dotted: R_C + W)")
    ax.set_ylabel("z / H")
    ax.legend(fontsize=7)
    ax.grid(alpha=0.3)
    ax.set_title("Shear band centre and width (Gladkyy Fig. 6)")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "shear_bands.png"), dpi=110)
    plt.close(fig)
    # tau against p
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for k, a in enumerate(results):
        b = a["band"]
        if b.sum() < 3:
            continue
        col = colors[k % len(colors)]
        ax.plot(a["p"][b], a["tau"][b], "o", ms=3, color=col, alpha=0.6)
        pp = np.linspace(0, a["p"][b].max(), 10)
        ax.plot(pp, a["mu"] * pp + a["c"], "-", color=col,
                label=f"{label(a)} ({engine_label(a['params'])}): mu={a['mu']:.3f}, c={a['c']:.2f} Pa")
    ax.set_xlabel("p [Pa]")
    ax.set_ylabel("tau [Pa]")
    ax.legend(fontsize=7)
    ax.grid(alpha=0.3)
    ax.set_title("tau against p in the shear band (Gladkyy Fig. 7)")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "tau_p.png"), dpi=110)
    plt.close(fig)
    # torque
    fig, ax = plt.subplots(figsize=(max(5, 0.7 * len(results) + 2), 4.5))
    names = [f"{label(a)}\n{engine_label(a['params'])}" for a in results]
    ax.bar(range(len(results)), [a["torque_mean"] * 1e3 for a in results],
           yerr=[a["torque_sem"] * 1e3 for a in results], color=colors[:len(results)])
    ax.set_xticks(range(len(results)))
    ax.set_xticklabels(names, fontsize=7, rotation=30, ha="right")
    ax.set_ylabel("torque on the rotating part [mN m]")
    ax.set_title("Mean torque (Gladkyy Fig. 8)")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "torque.png"), dpi=110)
    plt.close(fig)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("runs", nargs="+", help="run directories (scripts/scene.sh -out)")
    ap.add_argument("--out", required=True, help="directory for the CSV files and plots")
    ap.add_argument("--rate-min", type=float, default=None,
                    help="shear rate bound of the band [1/s] (default 0.12 Omega/Omega_paper)")
    ap.add_argument("--no-plots", action="store_true")
    args = ap.parse_args(argv)
    try:
        results = [analyse(run, args.rate_min) for run in args.runs]
    except PostError as e:
        sys.exit(f"post.py: {e}")
    write_outputs(results, args.out)
    if not args.no_plots:
        plot(results, args.out)
    with open(os.path.join(args.out, "summary.csv")) as f:
        print(f.read(), end="")


if __name__ == "__main__":
    main()
