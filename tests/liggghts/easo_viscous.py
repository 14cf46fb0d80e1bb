#!/usr/bin/env python3
"""The viscous force of `cohesion capillary ... viscous on` beside easo/capillary/viscous's.

Both cohesion models run the same motion in LIGGGHTS (tests/liggghts/in.easo_viscous): two
spheres driven from an overlap, where both form their bridge, apart along x and past each
other along y, sphere 1 spinning, to beyond the bridge's rupture. Both take Soulié's
capillary force with Lian's rupture rule here (easo's own; `capillary law soulie`), so the
runs without viscosity give the same capillary force; the viscous force of a run is its
force on sphere 1 minus that of the same model's run without viscosity (the motion is
prescribed: the positions and velocities are the same in both). From it, the normal and
tangential damping coefficients c_n = -F_n / (ds/dt), c_t = -F_t . v_t / |v_t|^2 at every
step, against independent formulas to 1e-9 of the force:

- ours: Pitois, Moucheront & Chateau 2000 (a bridge of finite volume V)
  c_n = 6 pi eta R*^2 / s [1 - 1/sqrt(1 + V/(pi R* s^2))]^2 and Goldman, Cox & Brenner
  1967 with R*, c_t = 6 pi eta R* max(0, 8/15 ln(R*/s) + 0.9588), s = max(gap, min_gap),
  none in overlap;
- easo/capillary/viscous as its source (LIGGGHTS 3.8.0, cohesion_model_easo_capillary_
  viscous.h) writes it (Nase et al. 2001 as cited by Shi & McCarthy 2008):
  c_n = 6 pi eta R* / x, c_t = 6 pi eta R* (0.5333333 ln(1/x) + 0.9588),
  x = max(minSeparationDistanceRatio, gap/R*), and x = minSeparationDistanceRatio in overlap;
  run with the ratio its documentation recommends (1.01) and with min_gap/R* (ours).

The torque on sphere 1, -r_1 e_n x F_t, is checked apart (easo uses the contact radius in
overlap: there only its normal force is checked). --output writes the page
lammps_pair/liggghts/doc/easo_viscous.md.

usage: easo_viscous.py LIGGGHTS_ENV [--workdir DIR] [--output FILE]
"""
import math
import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import liggghts_common as lc  # noqa: E402
from easo_comparison import easo_content  # noqa: E402

TOLERANCE = 1e-9
ETA = 0.05       # Pa s (a glycerol-water mixture)
MIN_GAP = 1e-6   # m, ours (viscousMinGap)
RECOMMENDED = 1.01  # easo's minSeparationDistanceRatio, as its documentation recommends
RUN = {"r1": 0.5e-3, "r2": 0.8e-3, "volume": 2e-11, "vx": 0.05, "vy": 0.02, "w1": 60.0,
       "dt": 2e-6, "nsteps": 3000}
R_STAR = RUN["r1"] * RUN["r2"] / (RUN["r1"] + RUN["r2"])
GAPS = [0.0, 2e-7, 1e-6, 3e-6, 1e-5, 3e-5, 1e-4, 2.5e-4]  # the page's rows (0: overlap)


def ours(gap):
    if gap <= 0.0:
        return 0.0, 0.0
    s = max(gap, MIN_GAP)
    filled = 1.0 - 1.0 / math.sqrt(1.0 + RUN["volume"] / (math.pi * R_STAR * s * s))
    shear = 8.0 / 15.0 * math.log(R_STAR / s) + 0.9588
    return (6.0 * math.pi * ETA * R_STAR ** 2 / s * filled ** 2,
            6.0 * math.pi * ETA * R_STAR * max(shear, 0.0))


def easo(gap, ratio):
    x = max(ratio, gap / R_STAR) if gap > 0.0 else ratio
    stokes = 6.0 * math.pi * ETA * R_STAR
    return stokes / x, stokes * (0.5333333 * math.log(1.0 / x) + 0.9588)


def reynolds(gap):
    """Reynolds' c_n of an unbounded film and Goldman-Cox-Brenner's c_t, at the gap."""
    return (6.0 * math.pi * ETA * R_STAR ** 2 / gap,
            6.0 * math.pi * ETA * R_STAR * (8.0 / 15.0 * math.log(R_STAR / gap) + 0.9588))


def run(env, workdir, tag, cohesion, viscosity, ratio):
    content = easo_content({"r1": RUN["r1"], "r2": RUN["r2"], "volume": RUN["volume"]})
    variables = [(k, repr(v)) for k, v in RUN.items()] + [
        ("cohesion", cohesion), ("viscosity", repr(viscosity)), ("min_gap", repr(MIN_GAP)),
        ("ratio", repr(ratio)), ("content", repr(content))]
    code, log = lc.liggghts(env, os.path.join(lc.HERE, "in.easo_viscous"), variables,
                            workdir, log="log." + tag)
    if code != 0:
        lc.fail("in.easo_viscous (%s): %s" % (tag, lc.error_line(log) or log[-1500:]))
    return {int(row[0]): [float(v) for v in row[1:]] for row in lc.thermo_rows(log)}


def coefficients(with_eta, without):
    """Per step with a bridge: gap, rate, measured (c_n, c_t), the viscous force, e_n, v_t."""
    steps = []
    for step in sorted(set(with_eta) & set(without)):
        x1, y1, x2, y2, fx, fy, tz = with_eta[step]
        fx0, fy0, tz0 = without[step][4:7]
        if step == 0 or without[step][:4] != [x1, y1, x2, y2]:
            continue
        d = (x1 - x2, y1 - y2)
        r = math.hypot(*d)
        gap = r - RUN["r1"] - RUN["r2"]
        if gap > 0.0 and fx0 == 0.0 and fy0 == 0.0:
            continue  # no bridge (before contact is impossible here: beyond rupture)
        en = (d[0] / r, d[1] / r)
        vr = (-RUN["vx"], -RUN["vy"])  # sphere 1 held, sphere 2 driven
        rate = vr[0] * en[0] + vr[1] * en[1]
        spin = RUN["r1"] * RUN["w1"]  # e_n x (r1 w1 z) = spin (e_n,y, -e_n,x)
        vt = (vr[0] - rate * en[0] + spin * en[1], vr[1] - rate * en[1] - spin * en[0])
        force = (fx - fx0, fy - fy0, tz - tz0)
        speed = math.hypot(*vt)
        c_n = -(force[0] * en[0] + force[1] * en[1]) / rate
        c_t = -(force[0] * vt[0] + force[1] * vt[1]) / speed ** 2
        steps.append({"gap": gap, "rate": rate, "c_n": c_n, "c_t": c_t, "force": force,
                      "en": en, "vt": vt})
    return steps


def deviation(steps, formula):
    """Largest |F - F_formula| over the steps, relative to the formula's force (normal and
    tangential, and the torque / r_1 apart); in overlap the normal force only."""
    worst = 0.0
    for p in steps:
        c_n, c_t = formula(p["gap"])
        en, vt, (fx, fy, tz) = p["en"], p["vt"], p["force"]
        want = [-c_n * p["rate"] * en[k] - c_t * vt[k] for k in range(2)]
        scale = abs(c_n * p["rate"]) + c_t * math.hypot(*vt)
        if scale == 0.0:
            scale = 1e-300
        if p["gap"] <= 0.0:
            if formula is ours:  # none in overlap: exactly the run without viscosity
                worst = max(worst, 0.0 if fx == 0.0 and fy == 0.0 else math.inf)
                continue
            normal = fx * en[0] + fy * en[1]
            worst = max(worst, abs(normal + c_n * p["rate"]) / abs(c_n * p["rate"]))
            continue
        ft = (-c_t * vt[0], -c_t * vt[1])
        torque = -RUN["r1"] * (en[0] * ft[1] - en[1] * ft[0])
        worst = max(worst, abs(fx - want[0]) / scale, abs(fy - want[1]) / scale,
                    abs(tz - torque) / (scale * RUN["r1"]))
    return worst


def nearest(steps, gap):
    if gap <= 0.0:
        inside = [p for p in steps if p["gap"] <= 0.0]
        return inside[len(inside) // 2] if inside else None
    return min(steps, key=lambda p: abs(math.log(max(p["gap"], 1e-300) / gap)))


def impulse(steps):
    """The normal viscous impulse per unit speed, sum of c_n ds: from contact to rupture
    (apart), and over the overlap of this motion (the film squeezed at constant speed)."""
    apart = [p for p in steps if p["gap"] > 0.0]
    total = sum(p["c_n"] * p["rate"] * RUN["dt"] for p in apart)
    inside = sum(p["c_n"] * p["rate"] * RUN["dt"] for p in steps if p["gap"] <= 0.0)
    return total, inside


def page(results, deviations):
    out = ["<!-- generated by tests/liggghts/easo_viscous.py; do not edit -->",
           "Regenerate: `python3 tests/liggghts/easo_viscous.py "
           "$CAPBRIDGE_CACHE/liggghts-3.8.0/liggghts.env --output "
           "lammps_pair/liggghts/doc/easo_viscous.md` (after scripts/build_liggghts.sh).", "",
           "# The bridge's viscous force: `cohesion capillary ... viscous on` and "
           "`easo/capillary/viscous`", "",
           "One motion in LIGGGHTS 3.8.0 for both models (tests/liggghts/in.easo_viscous): "
           "spheres of radii %g and %g mm (R* = %.4g mm), a bridge of V = %g m^3 "
           "(easo: the liquid content that gives it), viscosity %g Pa s; sphere 2 leaves "
           "sphere 1 at %g m/s along the line of centres and slides at %g m/s across it, "
           "sphere 1 spins at %g rad/s, from an overlap of 1 um to past the rupture "
           "distance (Lian's, %.3g mm in both). Both take Soulié's capillary force (easo's "
           "own; ours `law soulie`), and the viscous force is each model's force minus its "
           "run without viscosity. Ours: viscousMinGap %g um (%.3g R*). easo: "
           "minSeparationDistanceRatio %g, as its documentation recommends, and %.4g "
           "(ours, as a ratio to R*)." % (
               1e3 * RUN["r1"], 1e3 * RUN["r2"], 1e3 * R_STAR, RUN["volume"], ETA, RUN["vx"],
               RUN["vy"], RUN["w1"], 1e3 * RUN["volume"] ** (1.0 / 3.0), 1e6 * MIN_GAP,
               MIN_GAP / R_STAR, RECOMMENDED, MIN_GAP / R_STAR), "",
           "Each run's measured force, at every step with a bridge, against the formula it "
           "is documented by (relative to the force):", ""]
    for label, value in deviations:
        out.append("- %s: %.2g" % (label, value))
    out += ["", "## Normal: the damping coefficient c_n = -F_n / (ds/dt), over Reynolds' "
            "6 pi eta R*^2 / s", "",
            "| gap s | s / R* | Reynolds, N s/m | ours | easo, ratio %g | easo, ratio %.4g |"
            % (RECOMMENDED, MIN_GAP / R_STAR), "|---|---|---|---|---|---|"]
    for gap in GAPS:
        cells = []
        points = [nearest(results[key], gap) for key in ("ours", "easo", "easo_matched")]
        if any(p is None for p in points):
            continue
        s = points[0]["gap"]
        if gap <= 0.0:
            out.append("| overlap (contact) | – | – | c_n = 0 | c_n = %.4g N s/m | c_n = "
                       "%.4g N s/m |" % (points[1]["c_n"], points[2]["c_n"]))
            continue
        ref = reynolds(s)[0]
        cells = ["%.3g" % (p["c_n"] / ref) for p in points]
        out.append("| %.3g um | %.3g | %.3g | %s |" % (1e6 * s, s / R_STAR, ref,
                                                        " | ".join(cells)))
    out += ["", "## Tangential: c_t = -F_t / v_t, over Goldman-Cox-Brenner's "
            "6 pi eta R* (8/15 ln(R*/s) + 0.9588)", "",
            "| gap s | s / R* | GCB, N s/m | ours | easo, ratio %g | easo, ratio %.4g |"
            % (RECOMMENDED, MIN_GAP / R_STAR), "|---|---|---|---|---|---|"]
    for gap in GAPS:
        points = [nearest(results[key], gap) for key in ("ours", "easo", "easo_matched")]
        if any(p is None for p in points):
            continue
        s = points[0]["gap"]
        if gap <= 0.0:
            out.append("| overlap (contact) | – | – | c_t = 0 | c_t = %.4g N s/m | c_t = "
                       "%.4g N s/m |" % (points[1]["c_t"], points[2]["c_t"]))
            continue
        ref = reynolds(s)[1]
        cells = ["%.3g" % (p["c_t"] / ref) for p in points]
        out.append("| %.3g um | %.3g | %.3g | %s |" % (1e6 * s, s / R_STAR, ref,
                                                        " | ".join(cells)))
    at_gap = {key: nearest(results[key], MIN_GAP) for key in results}
    far = {key: nearest(results[key], 1e-4) for key in results}
    reach = math.sqrt(RUN["volume"] / (math.pi * R_STAR))
    out += ["", "## Where and why they differ", "",
            "- **easo's smallest gap is a ratio to R\*.** Its force uses max(ratio, s/R*) "
            "for s/R*, so minSeparationDistanceRatio 1.01 (the value its documentation "
            "recommends, next to maxSeparationDistanceRatio 1.1, which is a ratio of the "
            "centre distance to the radius sum) clamps the gap at 1.01 R* = %.3g um, beyond "
            "this bridge's rupture distance: over the whole bridge the normal force is "
            "6 pi eta R* v / 1.01, a Stokes drag, not a lubrication force (%.3g of Reynolds' "
            "at s = 1 um, %.3g of ours), and the tangential force %.2g of Goldman's there. "
            "With the ratio set to min_gap / R* it is Reynolds' force of an unbounded film "
            "with our clamp." % (1.01e6 * R_STAR, at_gap["easo"]["c_n"] /
                                    reynolds(at_gap["easo"]["gap"])[0],
                                    at_gap["easo"]["c_n"] / at_gap["ours"]["c_n"],
                                    at_gap["easo"]["c_t"] / reynolds(at_gap["easo"]["gap"])[1]),
            "- **A finite bridge (ours).** Reynolds' film fills the gap to infinity; a bridge "
            "of volume V wets a radius where the gap holds V, and the pressure is zero there "
            "(Pitois et al. 2000): the factor [1 - 1/sqrt(1 + V/(pi R* s^2))]^2 is 1 for "
            "s << sqrt(V/(pi R*)) = %.3g um and falls beyond (%.3g of Reynolds' at 100 um). "
            "easo's force with the matched ratio is %.3g times ours there." % (
                1e6 * reach, far["ours"]["c_n"] / reynolds(far["ours"]["gap"])[0],
                far["easo_matched"]["c_n"] / far["ours"]["c_n"]),
            "- **In overlap** easo keeps its largest coefficient (6 pi eta R* / ratio: %.3g N s/m "
            "with the matched ratio), a dashpot added to the contact's whose effect depends "
            "on k_n through the duration of the contact; ours has none there (the film is "
            "squeezed out; the contact law's dashpot governs)." % (
                nearest(results["easo_matched"], 0.0)["c_n"]),
            "- **The same elsewhere:** the tangential force (Goldman, Cox & Brenner with R*, "
            "the spheres' rotation in the sliding velocity, the torque of a force at the "
            "contact point) and, here, the capillary force (Soulié's law with Lian's "
            "rupture in both)."]
    out += ["", "## The normal impulse of the separation", "",
            "Sum of c_n ds per unit speed (N s/m times m): from contact to rupture, and over "
            "the 1 um of overlap this motion starts from. In a wet collision this impulse "
            "sets how much of the rebound the bridge takes (e = e_dry - L/St).", "",
            "| model | contact to rupture | in the overlap |", "|---|---|---|"]
    for key, label in (("ours", "ours"), ("easo", "easo, ratio %g" % RECOMMENDED),
                       ("easo_matched", "easo, ratio %.4g" % (MIN_GAP / R_STAR))):
        apart, inside = impulse(results[key])
        out.append("| %s | %.4g | %.4g |" % (label, apart, inside))
    return "\n".join(out) + "\n"


def main():
    parser = lc.argument_parser(__doc__)
    parser.add_argument("--output", default="")
    args = parser.parse_args()
    env, workdir = lc.start(args.env, args.workdir, "easo_viscous")
    matched = MIN_GAP / R_STAR
    ours0 = run(env, workdir, "ours0", "capillary law soulie", 0.0, RECOMMENDED)
    ours1 = run(env, workdir, "ours", "capillary law soulie viscous on", ETA, RECOMMENDED)
    easo0 = run(env, workdir, "easo0", "easo/capillary/viscous", 0.0, RECOMMENDED)
    easo1 = run(env, workdir, "easo", "easo/capillary/viscous", ETA, RECOMMENDED)
    easo2 = run(env, workdir, "easo_matched", "easo/capillary/viscous", ETA, matched)
    # without viscosity the two models give the same force (Soulie's law, Lian's rupture)
    same = [abs(ours0[s][4] - easo0[s][4]) <= 1e-6 * max(abs(easo0[s][4]), 1e-300)
            for s in ours0 if s in easo0 and s > 0]
    results = {"ours": coefficients(ours1, ours0), "easo": coefficients(easo1, easo0),
               "easo_matched": coefficients(easo2, easo0)}
    deviations = [
        ("ours (viscousMinGap %g m) against Pitois et al. and Goldman et al." % MIN_GAP,
         deviation(results["ours"], ours)),
        ("easo, ratio %g, against its source's formula" % RECOMMENDED,
         deviation(results["easo"], lambda g: easo(g, RECOMMENDED))),
        ("easo, ratio %.4g, against its source's formula" % matched,
         deviation(results["easo_matched"], lambda g: easo(g, matched)))]
    text = page(results, deviations)
    print(text)
    if args.output:
        with open(args.output, "w") as f:
            f.write(text)
    ok = all(same) and len(same) > 100
    print("without viscosity, the two models' f_x agree to 1e-6 at %d of %d steps %s" % (
        sum(same), len(same), "ok" if ok else "FAIL"))
    for label, value in deviations:
        good = value <= TOLERANCE
        ok = ok and good
        print("%s: within %.1e (tolerance %g) %s" % (label, value, TOLERANCE,
                                                    "ok" if good else "FAIL"))
    apart = [p["gap"] for p in results["ours"] if p["gap"] > 0.0]
    covered = bool(apart) and min(apart) < MIN_GAP and max(apart) > 100 * MIN_GAP
    ok = ok and covered
    print("gaps with a bridge: %.3g to %.3g m %s" % (min(apart) if apart else 0.0,
                                                     max(apart) if apart else 0.0,
                                                     "ok" if covered else "FAIL"))
    print("easo viscous comparison: %s (files in %s)" % ("PASS" if ok else "FAIL", workdir))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
