#!/usr/bin/python3
"""Checks the smoke runs of the split-bottom scene (inputs/split_bottom/) of one engine, dry
and wet (fixed bridge volume 74.2 nl, law willett), made by tests/scenes/split_bottom.cmake
through scripts/scene.sh on 2 ranks into WORKDIR/dry and WORKDIR/wet, and asserts the
physics of the cell with inputs/split_bottom/post.py's analysis:

  * the split bottom shears: at the lowest height omega/Omega is near 0 next to the inner
    wall and near 1 next to the outer wall, and the fitted band centre R_C lies at the split
    radius Rs there (within 2 grain diameters);
  * the band is wider higher up (W at the top above W at the bottom), as in the split-bottom
    geometry (Fenistein & van Hecke);
  * dry: no bridge ever; wet: bridges at every output, 4-12 per grain (2 x bridges / grains,
    bridges with the wall grains included: a wet packing's contacts and near contacts), and with a fixed volume per bridge the liquid in bridges is exactly
    bridges x V (1e-12 relative) at every output;
  * the bridges hold the packing together: the torque needed to drive the wet cell is
    above the dry one;
  * post.py's own numbers: every fitted band centre inside the cell, the standard error of
    R_C at mid height positive and below a grain diameter, and band_shift's shift equal to
    wet minus dry from the two analyses.

Usage: split_bottom_check.py WORKDIR"""
import os
import sys

import numpy as np

TOP = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(TOP, "inputs", "split_bottom"))
import post  # noqa: E402

V_NL = 74.2
failures = []


def check(cond, what):
    print(("ok    " if cond else "FAIL  ") + what)
    if not cond:
        failures.append(what)


def shears(a, tag):
    P = a["params"]
    d = 2 * P["R"]
    z0, rc0, w0 = a["fits"][0]
    j = int(np.argmin(abs(a["zc"] - z0)))
    om, cnt, r = a["omega"][:, j], a["count"][:, j], a["rc"]
    inner = (r < P["Ri"] + 3 * d) & (cnt > 0)
    outer = (r > P["Ro"] - 2 * d) & (cnt > 0)
    wi = np.average(om[inner], weights=cnt[inner])
    wo = np.average(om[outer], weights=cnt[outer])
    check(wi < 0.15, f"{tag}: omega/Omega next to the inner wall at z={z0:.4f} m is {wi:.3f} < 0.15")
    check(wo > 0.75, f"{tag}: omega/Omega next to the outer wall at z={z0:.4f} m is {wo:.3f} > 0.75")
    check(abs(rc0 - P["Rs"]) < 2 * d,
          f"{tag}: band centre at the bottom R_C={rc0 * 1e3:.1f} mm within 2 d of Rs={P['Rs'] * 1e3:.1f} mm")
    wt = a["fits"][-1][2]
    check(wt > w0, f"{tag}: band width grows with height: W(top)={wt * 1e3:.1f} mm > W(bottom)={w0 * 1e3:.1f} mm")


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    try:
        dry = post.analyse(os.path.join(sys.argv[1], "dry"))
        wet = post.analyse(os.path.join(sys.argv[1], "wet"))
    except post.PostError as e:
        sys.exit(f"split_bottom_check: {e}")
    if wet["params"]["volume_nl"] != V_NL or dry["params"]["volume_nl"] != 0:
        sys.exit("split_bottom_check: WORKDIR/dry must be a run with volume 0, WORKDIR/wet with 74.2")
    shears(dry, "dry")
    shears(wet, "wet")
    check(np.all(dry["bridges"] == 0) and np.all(dry["liquid"] == 0), "dry: no bridge at any output")
    nb, liq = wet["bridges"], wet["liquid"]
    V = V_NL * 1e-12
    check(len(nb) > 0 and np.all(nb > 0), f"wet: bridges at every output ({len(nb)} outputs)")
    z = 2 * nb.mean() / wet["grains"]
    check(4 < z < 12, f"wet: {z:.2f} bridges per grain (2 x bridges / grains, walls included), in (4, 12)")
    err = np.max(np.abs(liq - nb * V) / (nb * V))
    check(err <= 1e-12, f"wet: liquid in bridges = bridges x V to {err:.1e} relative (<= 1e-12)")
    check(wet["torque_mean"] > dry["torque_mean"] > 0,
          f"torque wet {wet['torque_mean'] * 1e3:.3f} mN m > dry {dry['torque_mean'] * 1e3:.3f} mN m > 0")
    P = dry["params"]
    fits = np.array(dry["fits"] + wet["fits"])
    check(np.all((fits[:, 1] > P["Ri"]) & (fits[:, 1] < P["Ro"]) & (fits[:, 2] > 0)),
          f"every fitted band centre inside the cell ({P['Ri'] * 1e3:.1f}, {P['Ro'] * 1e3:.1f}) mm, "
          f"every width > 0 ({len(fits)} heights)")
    for a, tag in ((dry, "dry"), (wet, "wet")):
        se = a["Rc_mid_se"]
        check(0 < se < 2 * a["params"]["R"],
              f"{tag}: standard error of R_C at mid height {se * 1e3:.3f} mm, in (0, one grain "
              "diameter)")
    # band_shift.csv's wet-minus-dry shift at mid height, against the two analyses directly
    header, rows = post.band_shift_rows([dry, wet])
    row = dict(zip(header, next(r for r in rows if float(r[1]) == V_NL)))
    expected = (wet["Rc_mid"] - dry["Rc_mid"]) / P["Rs"]
    check(abs(float(row["shift_Rc_mid"]) - expected) <= 5e-5,
          f"band_shift: shift of R_C at mid height {row['shift_Rc_mid']} Rs = wet - dry "
          f"{expected:+.5f} Rs")
    print(f"band centre at mid height: dry {dry['Rc_mid'] * 1e3:.2f} mm, wet {wet['Rc_mid'] * 1e3:.2f} mm "
          "(reported, not asserted: the smoke cell is too small to resolve the shift)")
    if failures:
        sys.exit(f"{len(failures)} check(s) failed")
    print("all checks passed")


if __name__ == "__main__":
    main()
