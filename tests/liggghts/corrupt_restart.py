#!/usr/bin/env python3
"""A restart file whose pair history holds a corrupted bridge is refused (LIGGGHTS; the
LAMMPS twin is the corrupt_* cases of tests/lammps/test_errors.sh).

in.corrupt_restart forms a richefeu bridge of 1e-11 m^3 between two spheres of radius 1 mm,
stretches it to a gap of 50 um and writes a restart file.  The bridge's 7 doubles
(cb_bridge: volume, active, rupture, force_contact, radius_sum, radius_product,
law_constant) are found in the file by the bytes of its volume and of active = 1.0, and
checked against the values the run gives them (radius sum 2 mm, product 1e-6 m^2, rupture
V^(1/3) at theta 0, richefeu's 1/lambda).  Then a second LIGGGHTS reads the file and runs
1 step:
  - unpatched (control): it runs, and the force on sphere 2 at the first output after the
    restart is the one before (equal to 1e-12 relative, not 0: the bridge came through);
  - active set to 0.5, or law_constant (the 7th double, a field the held path does not read)
    set to -1: it stops with an error that names both particles' IDs and that the bridge
    state at setup is not a valid bridge (the model's cb_bridge_check_state at the first
    pass of the run).  Without that check these two states are refused all the same, by the
    same core check inside cb_bridge_set_volume ("bridge constants at setup", measured
    with the check line removed from a copy of the header): the error's label pins the
    check that comes first, every state's, active or not;
  - active set to 0 with the other six values kept: refused the same way.  The pair is apart
    (gap 50 um), where the model skips a pair whose active value is 0 without reading the
    rest; at a run's setup it no longer skips, so this state is checked too (before, the run
    went on with the bridge gone, and under Protocols 2, 3 its liquid lost without a word).

usage: corrupt_restart.py LIGGGHTS_ENV [--workdir DIR]
"""
import os
import re
import struct
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import liggghts_common as lc  # noqa: E402

DECK = os.path.join(lc.HERE, "in.corrupt_restart")
R, VOLUME = 1e-3, 1e-11
FIELDS = ("volume", "active", "rupture", "force_contact", "radius_sum", "radius_product",
          "law_constant")
# (case, field, value written into it)
CORRUPTIONS = [("corrupt_active", "active", 0.5),
               ("corrupt_law_constant", "law_constant", -1.0),
               ("corrupt_inactive", "active", 0.0)]


def run(env, workdir, name, read, restart):
    return lc.liggghts(env, DECK, [("read", read), ("file", restart)], workdir,
                       log="log." + name)


def bridges_in(data):
    """Offsets of every active bridge of VOLUME in the restart file's bytes."""
    key = struct.pack("<dd", VOLUME, 1.0)
    found, start = [], data.find(key)
    while start >= 0:
        found.append(start)
        start = data.find(key, start + 1)
    return found


def last_force(log):
    """fx of sphere 2 at the last thermo output (step, gap, fx2)."""
    rows = lc.thermo_rows(log)
    return float(rows[-1][2]) if rows else None


def main():
    args = lc.argument_parser(__doc__).parse_args()
    env, workdir = lc.start(args.env, args.workdir, "corrupt_restart")
    ok = True

    def check(good, text):
        nonlocal ok
        ok = ok and good
        print("%s %s" % (text, "ok" if good else "FAIL"))

    restart = os.path.join(workdir, "bridge.restart")
    code, log = run(env, workdir, "write", 0, restart)
    if code != 0:
        lc.fail("writing the restart file: %s" % (lc.error_line(log) or log[-1500:]))
    before = last_force(log)
    with open(restart, "rb") as f:
        data = f.read()
    offsets = bridges_in(data)
    # newton off, one rank: the bridge is in the history of both its particles
    check(len(offsets) == 2, "%d bridges of %g m^3 found in the restart file (expected 2)"
          % (len(offsets), VOLUME))
    if not offsets:
        return 1
    state = dict(zip(FIELDS, struct.unpack_from("<7d", data, offsets[0])))
    # the constants the first run derived: Lian's rupture distance V^(1/3) at theta 0, and
    # richefeu's 1/lambda (Richefeu 2007 eq. 11, lambda = (c/sqrt 2) sqrt(V/r) sqrt(1/R1 + 1/R2)
    # = c sqrt(V/R) for R1 = R2 = R, r = 1; c = 0.9, the law's default)
    lam = 0.9 * (VOLUME / R) ** 0.5
    expected = {"rupture": VOLUME ** (1.0 / 3.0), "radius_sum": 2 * R,
                "radius_product": R * R, "law_constant": 1.0 / lam}
    for field, value in expected.items():
        check(abs(state[field] - value) <= 1e-12 * value,
              "stored %s %.17g (expected %.17g)" % (field, state[field], value))

    code, log = run(env, workdir, "unpatched", 1, restart)
    after = last_force(log)
    check(code == 0 and before is not None and after is not None and before != 0.0
          and abs(after - before) <= 1e-12 * abs(before),
          "unpatched: ran (exit %d), force on sphere 2 %s N after the restart, %s before"
          % (code, after, before))

    for name, field, value in CORRUPTIONS:
        patched = bytearray(data)
        for start in offsets:
            struct.pack_into("<d", patched, start + 8 * FIELDS.index(field), value)
        path = os.path.join(workdir, name + ".restart")
        with open(path, "wb") as f:
            f.write(patched)
        code, log = run(env, workdir, name, 1, path)
        line = lc.error_line(log) or ""
        named = re.search(r"bridge state at setup failed for particles (1 and 2|2 and 1) .*"
                          r"the stored bridge state is not a valid bridge", line)
        check(code != 0 and named is not None,
              "%s (%s = %g): exit %d, error '%s'" % (name, field, value, code, line.strip()))
    print("corrupt restart: %s (files in %s)" % ("PASS" if ok else "FAIL", workdir))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
