#!/usr/bin/env python3
"""Smoke test of the direct shear scene (inputs/direct_shear/, Richefeu 2007 section 3.2).

Usage: direct_shear_smoke.py ENGINE SCENE_SH WORKDIR
  ENGINE    lammps or liggghts
  SCENE_SH  scripts/scene.sh (run with CAPBRIDGE_SKIP_CONFIGURE=1 and, for LAMMPS,
            CAPBRIDGE_PLUGIN set by the caller)
  WORKDIR   where the runs go (one directory per run)

Runs the smoke size on 2 ranks at sigma = 200 Pa: dry and w = 1 % under each liquid protocol the
engine has (LAMMPS: Protocols 1 and 2 and the half-bonds variant; LIGGGHTS: protocol2), then
asserts the physics the smoke size shows reliably (measured margins in the comments, with the
cell of the paper's heights, 15 mm + 10 mm, 11.8 mm wide at this size, since 2026-12-03):
  - every wet run is stronger than the dry run: plateau tau at least 1.2 x and 30 Pa above dry
    (measured: LAMMPS 365 (Protocol 1) and 389 Pa (Protocol 2) against 210 Pa, LIGGGHTS 324
    against 262 Pa);
  - the dry plateau friction tau/sigma_n lies in 0.2..1.0 (measured 0.59 LAMMPS, 0.81 LIGGGHTS);
  - the plate servo holds the vertical stress: plateau mean within 35 % of sigma (measured:
    LAMMPS +0 %, LIGGGHTS -17 % dry, +4 % wet);
  - the liquid is conserved under the protocols: |relative change| <= 1e-12 at every output
    (measured 2e-14);
  - bridges: none dry, a bond coordination above 2 wet;
  - half bonds (LAMMPS; fix_modify liq remove 0.5 just before shearing, Richefeu Fig. 7's "the
    initial particle configuration is the same in both samples"): the preparation is the
    all-bonds run's to the last digit (bond coordination after consolidation equal), the bond
    coordination at the start of shearing is 0.4..0.6 of the all-bonds run's (a binomial draw
    of half), and it grows during shearing (new bridges from the free liquid).
Standard library only.
"""
import os
import subprocess
import sys

SIGMA = 200.0


def run(scene_sh, engine, workdir, name, variables):
    out = os.path.join(workdir, name)
    cmd = [scene_sh, engine, "direct_shear", "-np", "2", "-size", "smoke", "-out", out,
           "-var", "sigma", str(SIGMA)]
    for key, value in variables.items():
        cmd += ["-var", key, str(value)]
    print("running:", " ".join(cmd), flush=True)
    with open(os.path.join(workdir, name + ".screen"), "w") as screen:
        status = subprocess.call(cmd, stdout=screen, stderr=subprocess.STDOUT)
    if status != 0:
        sys.exit(f"FAIL: {name}: the engine exited with status {status} (see {out}/log.*)")
    return out


def table(path):
    rows = []
    with open(path) as f:
        for line in f:
            if line.strip() and not line.startswith("#"):
                rows.append([float(v) for v in line.split()])
    if len(rows) < 3:
        sys.exit(f"FAIL: {path} has fewer than 3 output lines")
    return rows


class Run:
    """shear.txt columns: step dx dx/D tau sigma_plate sigma_n phi bridges z_bond liquid
    liquid_rel_change ke; prep.txt: step ... bridges z_bond (the last two columns)."""

    def __init__(self, out):
        self.rows = table(os.path.join(out, "shear.txt"))
        self.prep = table(os.path.join(out, "prep.txt"))
        end = self.rows[-1][2]
        plateau = [r for r in self.rows if r[2] >= min(1.0, end / 2)]
        self.tau = sum(r[3] for r in plateau) / len(plateau)
        self.sigma_plate = sum(r[4] for r in plateau) / len(plateau)
        self.sigma_n = sum(r[5] for r in plateau) / len(plateau)
        self.z_start = self.rows[0][8]
        self.z_end = self.rows[-1][8]
        self.z_consolidated = self.prep[-1][-1]
        self.max_liquid_change = max(abs(r[10]) for r in self.rows)


failures = []


def check(condition, message):
    print(("ok:   " if condition else "FAIL: ") + message)
    if not condition:
        failures.append(message)


def main():
    if len(sys.argv) != 4 or sys.argv[1] not in ("lammps", "liggghts"):
        sys.exit(__doc__)
    engine, scene_sh, workdir = sys.argv[1:]
    os.makedirs(workdir, exist_ok=True)
    wet_cases = {"lammps": {"protocol1": {"protocol": 1}, "protocol2": {"protocol": 2}},
                 "liggghts": {"protocol2": {"liquid": "protocol2"}}}[engine]
    dry = Run(run(scene_sh, engine, workdir, "dry", {"w": 0}))
    wet = {name: Run(run(scene_sh, engine, workdir, name, dict(v, w=1)))
           for name, v in wet_cases.items()}

    check(0.2 <= dry.tau / dry.sigma_n <= 1.0,
          f"dry: plateau friction tau/sigma_n = {dry.tau:.1f}/{dry.sigma_n:.1f} = "
          f"{dry.tau / dry.sigma_n:.2f} in 0.2..1.0")
    check(dry.z_end == 0 and dry.z_consolidated == 0, "dry: no bridges")
    for name, r in [("dry", dry)] + list(wet.items()):
        check(abs(r.sigma_plate - SIGMA) <= 0.35 * SIGMA,
              f"{name}: plate stress on the plateau {r.sigma_plate:.1f} Pa within 35 % of {SIGMA:g} Pa")
    for name, r in wet.items():
        check(r.tau >= 1.2 * dry.tau and r.tau >= dry.tau + 30,
              f"{name} w = 1 %: plateau tau {r.tau:.1f} Pa >= 1.2 x and 30 Pa above dry {dry.tau:.1f} Pa")
        check(r.max_liquid_change <= 1e-12,
              f"{name}: liquid conserved, largest |relative change| {r.max_liquid_change:.2e} <= 1e-12")
        check(r.z_consolidated > 2, f"{name}: bond coordination {r.z_consolidated:.2f} > 2 after consolidation")

    if engine == "lammps":
        half = Run(run(scene_sh, engine, workdir, "half", {"w": 1, "protocol": 2, "bonds": "half"}))
        full = wet["protocol2"]
        check(half.z_consolidated == full.z_consolidated,
              f"half bonds: the preparation is the all-bonds run's (bond coordination after "
              f"consolidation {half.z_consolidated:.4f} and {full.z_consolidated:.4f})")
        ratio = half.z_start / full.z_start
        check(0.4 <= ratio <= 0.6,
              f"half bonds: bond coordination at the start of shearing {half.z_start:.2f} = "
              f"{ratio:.2f} x all bonds ({full.z_start:.2f}), in 0.4..0.6")
        check(half.z_end > half.z_start,
              f"half bonds: the bond coordination grows while shearing "
              f"({half.z_start:.2f} -> {half.z_end:.2f})")
        check(half.max_liquid_change <= 1e-12,
              f"half bonds: liquid conserved, largest |relative change| {half.max_liquid_change:.2e}")

    print(f"direct_shear_smoke {engine}: {len(failures)} failed")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
