#!/usr/bin/python3
"""The wet collision (issue 19 item 3): the restitution of a head-on collision of two wet glass
spheres against the Stokes number, in LAMMPS and LIGGGHTS, next to the lubrication estimate.

Usage: /usr/bin/python3 inputs/wet_collision/study.py [--out DIR] [--engines lammps liggghts]
  --out      where restitution.csv, restitution.png and summary.txt go
             (default docs/results/wet_collision)
  --engines  default both

The decks are the tests' (tests/lammps/in.wet_collision, tests/liggghts/in.wet_collision):
equal spheres of radius 1 mm and density 2500 kg/m^3, v0 1 m/s, a bridge of 1e-11 m^3 formed at
contact (Richefeu's law, theta 0), the viscous force with viscousMinGap 1 um, k_n 1e4 N/m, the
dashpot of alpha_n 0.1 both ways.  St = m* v0 / (6 pi eta R*^2); the runs sweep eta so that St
goes from 2 to 1000, and one run without viscosity gives e_dry.  The estimate: the viscous
impulse while the spheres separate, over m* v0, takes L / St off e_dry (e = e_dry - L / St,
stuck below St_c = L / e_dry), L = chi(min_gap) + the integral of chi(s)/s ds from min_gap to
the rupture distance, chi = (1 - 1/sqrt(1 + V/(pi R* s^2)))^2 (Pitois et al. 2000's volume
factor; Simpson's rule here, independent of the core).  The tests assert this trend at nine
viscosities (tests/lammps/test_viscous.sh, tests/liggghts/wet_collision.py); this study gives
the curve and writes the table the results page shows.
Engines: LAMMPS with the plugin ($CAPBRIDGE_PLUGIN or build/lammps_pair/lammps/capbridgeplugin.so),
LIGGGHTS from the engine cache ($CAPBRIDGE_CACHE or ~/.cache/capbridge), as scripts/scene.sh.
"""
import argparse
import csv
import glob
import math
import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
TOP = os.path.dirname(os.path.dirname(HERE))
RADIUS, DENSITY, V0, KN, ALPHA = 1e-3, 2500.0, 1.0, 1e4, 0.1
VOLUME, MIN_GAP = 1e-11, 1e-6
# 2 ms of dt 1e-7 s, as the tests; a rebound still held by its bridge at the end (a slow one,
# near St_c) runs again for 10 ms (the box of the decks holds a rebound of up to 0.5 m/s then)
NSTEPS, NSTEPS_SLOW = 20000, 100000
MSTAR = 0.5 * DENSITY * 4.0 / 3.0 * math.pi * RADIUS ** 3
RSTAR = RADIUS / 2.0
STOKES = (2, 3, 4, 5, 5.5, 6, 6.5, 7, 8, 10, 12, 15, 20, 30, 50, 100, 200, 500, 1000)


def fail(message):
    sys.exit("wet_collision/study.py: " + message)


def viscosity(st):
    return MSTAR * V0 / (6.0 * math.pi * RSTAR ** 2 * st)


def impulse_integral():
    """L: chi(min_gap) for the clamped gaps below min_gap, then chi(s)/s ds to V^(1/3) (Lian's
    rupture distance at theta 0), Simpson's rule in ln s."""
    def chi(s):
        return (1.0 - 1.0 / math.sqrt(1.0 + VOLUME / (math.pi * RSTAR * s * s))) ** 2
    n, a, b = 20000, math.log(MIN_GAP), math.log(VOLUME ** (1.0 / 3.0))
    h = (b - a) / n
    total = sum((1 if k in (0, n) else (4 if k % 2 else 2)) * chi(math.exp(a + k * h))
                for k in range(n + 1))
    return chi(MIN_GAP) + total * h / 3.0


def read_env(path):
    env = {}
    with open(path) as f:
        for line in f:
            if "=" in line and not line.startswith("#"):
                name, value = line.rstrip("\n").split("=", 1)
                env[name] = value.strip('"')
    return env


def engine_env(name):
    cache = os.environ.get("CAPBRIDGE_CACHE", os.path.expanduser("~/.cache/capbridge"))
    found = sorted(glob.glob(os.path.join(cache, "%s-*" % name, "%s.env" % name)))
    if not found:
        fail("no %s build in %s: run scripts/configure.sh" % (name, cache))
    return read_env(found[-1])


def run(command, workdir, log):
    result = subprocess.run(command, cwd=workdir, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, universal_newlines=True)
    text = open(os.path.join(workdir, log)).read() if os.path.exists(
        os.path.join(workdir, log)) else ""
    found = re.search(r"^RESTITUTION (\S+) BRIDGES (\S+) GAP", text + result.stdout, re.M)
    if result.returncode != 0 or not found:
        fail("%s failed:\n%s" % (" ".join(command), (text + result.stdout)[-1500:]))
    return float(found.group(1)), int(float(found.group(2)))


def lammps(workdir, eta, nsteps):
    env = engine_env("lammps")
    plugin = os.environ.get("CAPBRIDGE_PLUGIN",
                            os.path.join(TOP, "build/lammps_pair/lammps/capbridgeplugin.so"))
    if not os.path.exists(plugin):
        fail("no plugin %s: run scripts/configure.sh" % plugin)
    log = "log.lammps.eta%g.n%d" % (eta, nsteps)
    return run([env["LAMMPS_BINARY"], "-in", os.path.join(TOP, "tests/lammps/in.wet_collision"),
                "-log", log, "-screen", "none", "-nocite", "-var", "plugin", plugin,
                "-var", "plugin_load", "yes", "-var", "v0", repr(V0), "-var", "alpha",
                repr(ALPHA), "-var", "kn", repr(KN), "-var", "volume", repr(VOLUME),
                "-var", "eta", repr(eta), "-var", "min_gap", repr(MIN_GAP),
                "-var", "nsteps", str(nsteps)], workdir, log)


def liggghts(workdir, eta, nsteps):
    env = engine_env("liggghts")
    gamman = 2.0 * ALPHA * math.sqrt(KN / MSTAR)   # the dashpot of alpha_n, as the test's
    log = "log.liggghts.eta%g.n%d" % (eta, nsteps)
    return run([env["LIGGGHTS_BINARY"], "-in",
                os.path.join(TOP, "tests/liggghts/in.wet_collision"), "-log", log,
                "-screen", "none", "-var", "v0", repr(V0), "-var", "kn", repr(KN),
                "-var", "gamman", repr(gamman), "-var", "volume", repr(VOLUME),
                "-var", "eta", repr(eta), "-var", "min_gap", repr(MIN_GAP),
                "-var", "nsteps", str(nsteps)], workdir, log)


def plot(rows, e_dry, L, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6, 4))
    for engine, marker in (("lammps", "o"), ("liggghts", "x")):
        pts = [(r["St"], r["e"]) for r in rows if r["engine"] == engine]
        if pts:
            ax.plot(*zip(*pts), marker, label=engine, mfc="none")
    grid = [1.5 * 1.05 ** k for k in range(140)]
    ax.plot(grid, [max(0.0, e_dry - L / st) for st in grid], "-", lw=0.8,
            label="e_dry - L/St (L = %.2f)" % L)
    ax.axhline(e_dry, ls=":", lw=0.8, color="grey", label="e_dry = %.3f (no viscosity)" % e_dry)
    ax.set_xscale("log")
    ax.set_xlabel("St = m* v0 / (6 pi eta R*^2)")
    ax.set_ylabel("restitution e")
    ax.set_title("wet head-on collision, R 1 mm, V 1e-11 m^3, min_gap 1 um")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", default=os.path.join(TOP, "docs/results/wet_collision"))
    ap.add_argument("--engines", nargs="+", default=["lammps", "liggghts"],
                    choices=["lammps", "liggghts"])
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    L = impulse_integral()
    rows, lines = [], []
    with tempfile.TemporaryDirectory() as workdir:
        for engine in args.engines:
            engine_run = lammps if engine == "lammps" else liggghts

            def collide(workdir, eta):
                e, left = engine_run(workdir, eta, NSTEPS)
                if left and e > 0.0:
                    e, left = engine_run(workdir, eta, NSTEPS_SLOW)
                return e, left
            e_dry, _ = collide(workdir, 0.0)
            rows.append(dict(engine=engine, eta=0.0, St=math.inf, e=e_dry, bridge_left=0,
                             e_estimate=e_dry))
            for st in STOKES:
                eta = viscosity(st)
                e, left = collide(workdir, eta)
                rows.append(dict(engine=engine, eta=eta, St=st, e=e, bridge_left=left,
                                 e_estimate=max(0.0, e_dry - L / st)))
            stuck = [r["St"] for r in rows if r["engine"] == engine and r["bridge_left"]]
            moving = [r["St"] for r in rows if r["engine"] == engine and not r["bridge_left"]
                      and r["St"] != math.inf]
            lines.append("%s: e_dry %.4f; stuck up to St %s, rebound from St %s; estimate "
                         "St_c = L/e_dry = %.2f" % (engine, e_dry, max(stuck) if stuck else "-",
                                                    min(moving) if moving else "-", L / e_dry))
    with open(os.path.join(args.out, "restitution.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        for r in rows:
            writer.writerow({k: ("%.6g" % v if isinstance(v, float) else v) for k, v in r.items()})
    e_ref = {r["engine"]: r["e"] for r in rows if r["St"] == math.inf}
    lines.insert(0, "L = %.4f (V %g m^3, R* %g m, min_gap %g m)" % (L, VOLUME, RSTAR, MIN_GAP))
    lines.append("St     " + "  ".join("%-9s" % e for e in args.engines) + "  estimate")
    for st in STOKES:
        es = [next(r["e"] for r in rows if r["engine"] == e and r["St"] == st)
              for e in args.engines]
        lines.append("%-6g " % st + "  ".join("%-9.4f" % e for e in es) +
                     "  %.4f" % max(0.0, e_ref[args.engines[0]] - L / st))
    with open(os.path.join(args.out, "summary.txt"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    plot(rows, e_ref[args.engines[0]], L, os.path.join(args.out, "restitution.png"))


if __name__ == "__main__":
    main()
