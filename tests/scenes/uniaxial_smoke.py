#!/usr/bin/python3
"""Smoke test of the uniaxial compression scene (inputs/uniaxial/, Richefeu 2007 section 4.2).

Usage: uniaxial_smoke.py ENGINE WORKDIR   (ENGINE = lammps or liggghts)
Runs the smoke deck on 2 ranks through scripts/scene.sh (environment CAPBRIDGE_SKIP_CONFIGURE=1,
and CAPBRIDGE_PLUGIN for LAMMPS), wet (LAMMPS Protocol 1, LIGGGHTS Protocol 2) and dry (a short
travel: it only has to show sigma ~ 0), LAMMPS also Protocol 3 with half of the bridges removed,
then asserts the physics:
  - the wet sample stands when the mould is removed (its centre of mass sinks by less than
    0.2 <D>), the dry one does not (centre of mass down by more than 0.5 <D>, top by 2 <D>);
  - the wet compressive strength is well above capillary-free noise: > 0.2 of the capillary
    stress scale 2 pi gamma (<D>/2) / <D>^2 and > 10 times the dry strength;
  - under the protocols the total liquid is conserved to 1e-12 relative at every output;
  - the water content is in percent of the grains' mass (the wet runs pass -var w 2): the
    liquid of the sample (summary.txt liquid_total) is w/100 of the grain mass M over the
    water density, M = 2500 kg/m^3 x the spheres' volume from start.dump, to 1e-9 relative;
  - the bridges exist (bridge coordination z between 2 and 12 at the start of the compression);
  - half of the bridges removed: z between 0.35 and 0.65 of the full sample's z;
  - LIGGGHTS, the wet bottom plate (Protocol 3, start free, plate wet: the floor's bridges under
    the pair's protocol): the plate holds bridges (> 10) at the compression's start, the liquid
    is conserved to 1e-12 with them, the strength is a wet sample's.
Numpy only; standard library otherwise.
"""
import math
import os
import subprocess
import sys

import numpy as np

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
GAMMA, DMEAN = 0.0728, 1.05e-3
RHO, RHO_WATER = 2500.0, 1000.0                             # glass, water [kg/m^3]
W_PERCENT = 2.0                                             # water content of the wet runs [%]
SIGMA_CAP = 2 * math.pi * GAMMA * (DMEAN / 2) / DMEAN ** 2   # capillary stress scale [Pa]
failures = []


def check(ok, message):
    print(("ok   " if ok else "FAIL ") + message)
    if not ok:
        failures.append(message)


def run(engine, workdir, name, *variables):
    out = os.path.join(workdir, name)
    cmd = [os.path.join(REPO, "scripts", "scene.sh"), engine, "uniaxial", "-np", "2",
           "-size", "smoke", "-out", out]
    for k, v in variables:
        cmd += ["-var", k, v]
    print("+ " + " ".join(cmd), flush=True)
    proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if proc.returncode != 0:
        print(proc.stdout[-4000:])
        sys.exit(f"FAIL: {name}: scene.sh exited with {proc.returncode}")
    summary = {}
    with open(os.path.join(out, "summary.txt")) as f:
        for line in f:
            parts = line.split()
            if len(parts) == 2:
                summary[parts[0]] = parts[1]
    curve = np.loadtxt(os.path.join(out, "uniaxial.txt"), comments="#", ndmin=2)
    return summary, curve


def water_volume(out):
    """(w/100) M / rho_water, M from the radii of start.dump: the liquid of W_PERCENT %."""
    with open(os.path.join(out, "start.dump")) as f:
        lines = f.readlines()
    start = next(i for i, line in enumerate(lines) if line.startswith("ITEM: ATOMS"))
    col = lines[start].split()[2:].index("radius")
    radii = np.array([float(line.split()[col]) for line in lines[start + 1:] if line.strip()])
    mass = RHO * np.sum(4.0 / 3.0 * math.pi * radii ** 3)
    return W_PERCENT / 100 * mass / RHO_WATER


def check_water(name, summary, out):
    expected = water_volume(out)
    if "liquid_total" not in summary:
        check(False, f"{name}: summary.txt gives the liquid of the sample (liquid_total)")
        return
    got = float(summary["liquid_total"])
    check(abs(got - expected) <= 1e-9 * expected,
          f"{name}: liquid {got:.6g} m^3 = w {summary['w_percent']} % of the grain mass / rho_water "
          f"{expected:.6g} m^3 (1e-9 relative)")


def strength(curve):
    """Peak of sigma after a moving average over 5 outputs (as inputs/uniaxial/post.py)."""
    return float(np.max(np.convolve(curve[:, 3], np.ones(5) / 5, mode="valid")))


def main():
    if len(sys.argv) != 3 or sys.argv[1] not in ("lammps", "liggghts"):
        sys.exit("usage: uniaxial_smoke.py lammps|liggghts WORKDIR")
    engine, workdir = sys.argv[1], sys.argv[2]
    os.makedirs(workdir, exist_ok=True)
    wet_protocol = "protocol1" if engine == "lammps" else "protocol2"
    w = f"{W_PERCENT:g}"
    wet, wet_curve = run(engine, workdir, "wet", ("protocol", wet_protocol), ("w", w))
    check_water(wet_protocol, wet, os.path.join(workdir, "wet"))
    dry, dry_curve = run(engine, workdir, "dry", ("dry", "yes"), ("travel", "0.3e-3"))
    d = float(wet["Dmean"])

    sink_wet = float(wet["zcm_seal"]) - float(wet["zcm_relax"])
    sink_dry = float(dry["zcm_seal"]) - float(dry["zcm_relax"])
    top_dry = float(dry["Hseal"]) - float(dry["Hrelax"])
    check(sink_wet < 0.2 * d, f"wet sample stands: centre of mass sinks {sink_wet:.3g} m < 0.2 <D>")
    check(sink_dry > 0.5 * d, f"dry sample collapses: centre of mass sinks {sink_dry:.3g} m > 0.5 <D>")
    check(top_dry > 2 * d, f"dry sample collapses: its top sinks {top_dry:.3g} m > 2 <D>")

    s_wet, s_dry = strength(wet_curve), strength(dry_curve)
    check(s_wet > 0.2 * SIGMA_CAP,
          f"wet strength {s_wet:.4g} Pa > 0.2 x capillary scale {SIGMA_CAP:.4g} Pa")
    check(s_wet > 10 * max(s_dry, 0.0) and s_wet > 0,
          f"wet strength {s_wet:.4g} Pa > 10 x dry strength {s_dry:.4g} Pa")

    z0 = wet_curve[0, 5]
    check(2 < z0 < 12, f"bridge coordination at the start of the compression z = {z0:.3g} in (2, 12)")
    check(np.all(np.abs(wet_curve[:, 6]) < 1e-12),
          f"{wet_protocol}: liquid conserved, max |relative change| {np.max(np.abs(wet_curve[:, 6])):.3g} < 1e-12")

    if engine == "lammps":
        half, half_curve = run(engine, workdir, "protocol3_half", ("protocol", "protocol3"),
                               ("half", "yes"), ("w", w))
        check_water("protocol3, half the bridges", half, os.path.join(workdir, "protocol3_half"))
        check(np.all(np.abs(half_curve[:, 6]) < 1e-12),
              f"protocol3: liquid conserved, max |relative change| {np.max(np.abs(half_curve[:, 6])):.3g} < 1e-12")
        ratio = half_curve[0, 5] / z0
        check(0.35 < ratio < 0.65, f"half of the bridges removed: z ratio {ratio:.3g} in (0.35, 0.65)")
        s_half = strength(half_curve)
        check(s_half > 10 * max(s_dry, 0.0) and s_half > 0.1 * SIGMA_CAP,
              f"protocol3, half the bridges: strength {s_half:.4g} Pa well above dry")

    if engine == "liggghts":
        plate, plate_curve = run(engine, workdir, "plate_wet", ("protocol", "protocol3"),
                                 ("start", "free"), ("plate", "wet"), ("w", w))
        check_water("protocol3, wet plate", plate, os.path.join(workdir, "plate_wet"))
        bridges = int(float(plate.get("plate_bridges", 0)))
        check(bridges > 10, f"wet plate: {bridges} plate bridges at the compression's start > 10")
        check(np.all(np.abs(plate_curve[:, 6]) < 1e-12),
              f"protocol3, wet plate: liquid conserved, max |relative change| "
              f"{np.max(np.abs(plate_curve[:, 6])):.3g} < 1e-12")
        s_plate = strength(plate_curve)
        check(s_plate > 0.2 * SIGMA_CAP,
              f"wet plate: strength {s_plate:.4g} Pa > 0.2 x capillary scale {SIGMA_CAP:.4g} Pa")

    if failures:
        sys.exit(f"uniaxial_smoke ({engine}): {len(failures)} checks failed")
    print(f"uniaxial_smoke ({engine}): all checks passed")


if __name__ == "__main__":
    main()
