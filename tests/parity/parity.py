#!/usr/bin/env python3
"""LAMMPS and LIGGGHTS at parity on the core's rules (issue 17 item 2).

One input for both engines: law richefeu (gamma 0.0728 N/m, theta 0), grains of radii
0.8 and 1.2 mm (density 2500), k_n = 1 N/m, and
  fixed:     a bridge volume V = 1e-11 m^3 for every pair, dt = 1e-3 s;
  protocol2: 1e-11 m^3 of liquid as free liquid in proportion to the grains' masses (LAMMPS
             `start free`), one grain A (1.2 mm) overlapping three dry grains (0.8, 0.9, 1.0
             mm) by 1 um: the three bridges form in one step.
Each engine's numbers are checked against the core's, computed here independently (the
rupture distance from the capbridge CLI, the formulas of capbridge.h's "engines' checks"):
  the design rupture distance of the reach, d = the largest rupture distance over the 5 x 5
    grid of the radius range (Richefeu eq. 6: (1 + theta/2) V^(1/3), the same at every
    radius), the reach 1.05 d (CB_REACH_MARGIN);  LAMMPS: its neighbor cutoff minus the
    largest radius sum and the skin;
  the design volume of Protocol 2 (no vmax given): max(2 V_total / N (r_max/r_min)^3,
    2 x the largest free liquid of a grain);
  the time-step bound 0.1 pi sqrt(m_min / k), k the capillary stiffness bound, the largest
    |dF/dgap| over the corners of the radius range (at contact for Richefeu's law, from the
    CLI's curve); LAMMPS prints it in its warning;
  Protocol 2's k-way share: a grain with k new contacts in one step gives each 1/k of its
    free liquid, so A's bridge to grain j holds free_A / 3 + free_j.

usage: parity.py CAPBRIDGE_CLI LAMMPS_ENV PLUGIN [--workdir DIR]
The LIGGGHTS half is not written yet: LIGGGHTS 3.8 prints neither its neighbor cutoff nor
the contact distance factor the model registers, so its reach needs an output first.
"""
import argparse
import math
import os
import re
import subprocess
import sys
import tempfile

R_SMALL, R_LARGE, RHO, GAMMA, VOLUME, SKIN = 0.8e-3, 1.2e-3, 2500.0, 0.0728, 1e-11, 1e-4
PARTNERS = (0.8e-3, 0.9e-3, 1.0e-3)    # the radii of A's three partners (x, y, z)
LIQUID, OVERLAP, MARGIN, DT = 1e-11, 1e-6, 0.05, 1e-3
FAILURES = []


def check(label, got, expected, tolerance):
    ok = got is not None and abs(got - expected) <= tolerance * abs(expected)
    print("%-58s %-22s core %-22r %s" % (label, got, expected, "ok" if ok else "FAIL"))
    if not ok:
        FAILURES.append(label)


def read_env(path):
    env = {}
    with open(path) as f:
        for line in f:
            line = line.strip()
            if line and not line.startswith("#") and "=" in line:
                key, value = line.split("=", 1)
                env[key] = value.strip('"')
    return env


# ---------------------------------------------------------------- the core's numbers

def cli_rupture(cli, r1, r2, volume):
    out = subprocess.run([cli, "force", "richefeu", "--r1", repr(r1), "--r2", repr(r2),
                          "--volume", repr(volume), "--gap", "0"],
                         capture_output=True, text=True, check=True).stdout
    return float(out.strip().splitlines()[-1].split(",")[3])


def cli_contact_stiffness(cli, r1, r2, volume):
    out = subprocess.run([cli, "curve", "richefeu", "--r1", repr(r1), "--r2", repr(r2),
                          "--volume", repr(volume), "--points", "2", "--to", "1e-6"],
                         capture_output=True, text=True, check=True).stdout
    return abs(float(out.strip().splitlines()[1].split(",")[2]))


def grid(lo, hi):
    return [hi if a == 4 else lo + (hi - lo) * a / 4 for a in range(5)]


def design_rupture(cli, volume):
    radii = grid(R_SMALL, R_LARGE)
    return max(cli_rupture(cli, r1, r2, volume) for r1 in radii for r2 in radii)


def timestep_bound(cli, volume):
    corners = (R_SMALL, R_LARGE)
    k = max(cli_contact_stiffness(cli, r1, r2, volume) for r1 in corners for r2 in corners)
    m = 4.0 / 3.0 * math.pi * R_SMALL ** 3 * RHO
    return 0.1 * math.pi * math.sqrt(m / k), k


def protocol2_free():
    """The grains' free liquid at the start, in proportion to their masses: A, its partners."""
    masses = [R_LARGE ** 3] + [r ** 3 for r in PARTNERS]
    return [LIQUID * m / sum(masses) for m in masses]


def protocol2_design_volume():
    """The larger of the Protocol 1 volume and twice the largest free liquid (A's, which
    does not decide here: 0.87 of the liquid against 1.69)."""
    protocol1 = 2.0 * LIQUID / 4 * (R_LARGE / R_SMALL) ** 3
    return max(protocol1, 2.0 * max(protocol2_free()))


# ---------------------------------------------------------------------------- LAMMPS

LAMMPS_DECK = """units           si
atom_style      sphere
atom_modify     map array
boundary        f f f
comm_modify     vel yes
region          box block -0.01 0.01 -0.01 0.01 -0.01 0.01 units box
create_box      1 box
create_atoms    1 single 0 0 0 units box
create_atoms    1 single {x[0]!r} 0 0 units box
create_atoms    1 single 0 {x[1]!r} 0 units box
create_atoms    1 single 0 0 {x[2]!r} units box
set             atom 1 diameter {d[0]!r}
set             atom 2 diameter {d[1]!r}
set             atom 3 diameter {d[2]!r}
set             atom 4 diameter {d[3]!r}
set             atom * density {rho!r}
plugin          load {plugin}
pair_style      gran/capillary
pair_coeff      * * 1 0.4 0 0.5 law richefeu gamma {gamma!r} {volume_keyword}
{fix}
neighbor        {skin!r} bin
timestep        {dt!r}
compute         pl all pair/local p3 p4 p5 p6
dump            bridges all local 1 {dump} c_pl[1] c_pl[2] c_pl[3] c_pl[4]
dump_modify     bridges format float %.17g
run             0
"""


def lammps_run(env, plugin, workdir, name, volume_keyword, fix, separated):
    x = [0.009 if separated else R_LARGE + r - OVERLAP for r in PARTNERS]
    deck = LAMMPS_DECK.format(
        x=x, d=[2 * r for r in (R_LARGE,) + PARTNERS], rho=RHO, plugin=plugin,
        gamma=GAMMA, volume_keyword=volume_keyword, fix=fix, skin=SKIN, dt=DT,
        dump=os.path.join(workdir, name + ".local"))
    path = os.path.join(workdir, "in." + name)
    with open(path, "w") as f:
        f.write(deck)
    log = os.path.join(workdir, name + ".log")
    done = subprocess.run([env["LAMMPS_BINARY"], "-in", path, "-log", log, "-nocite",
                           "-screen", "none"], capture_output=True, text=True)
    with open(log) as f:
        text = f.read()
    if done.returncode != 0:
        FAILURES.append("LAMMPS %s" % name)
        print("FAIL: LAMMPS %s: %s" % (name, re.findall(r"ERROR.*", text)[:1]))
        return text, {}
    volumes = {}    # the partner's radius: the volume of its bridge with A
    with open(os.path.join(workdir, name + ".local")) as f:
        lines = f.read().splitlines()
    start = max(k for k, line in enumerate(lines) if line.startswith("ITEM: ENTRIES"))
    for line in lines[start + 1:]:
        volume, bridge, r1, r2 = (float(x) for x in line.split())
        if bridge == 1.0:
            volumes[min(r1, r2)] = volume
    return text, volumes


def lammps_design_rupture(log):
    cutoff = float(re.search(r"master list distance cutoff = (\S+)", log).group(1))
    return (cutoff - SKIN - 2 * R_LARGE) / (1.0 + MARGIN)


def lammps_half(cli, env, plugin, workdir):
    log, _ = lammps_run(env, plugin, workdir, "lammps_fixed", "volume %r" % VOLUME, "", True)
    if log:
        check("LAMMPS fixed: design rupture distance of the reach",
              lammps_design_rupture(log), design_rupture(cli, VOLUME), 1e-6)
        limit, k = timestep_bound(cli, VOLUME)
        warning = re.search(r"time step \S+ s exceeds the limit (\S+) s .* capillary stiffness "
                            r"bound ([^)]+)\)", log)
        check("LAMMPS fixed: time-step bound", warning and float(warning.group(1)), limit, 1e-5)
        check("LAMMPS fixed: capillary stiffness bound", warning and float(warning.group(2)),
              k, 1e-5)
    log, volumes = lammps_run(env, plugin, workdir, "lammps_protocol2", "",
                              "fix liq all capillary/liquid protocol2 liquid %r start free"
                              % LIQUID, False)
    if log:
        check("LAMMPS protocol2: design rupture distance of the reach",
              lammps_design_rupture(log), design_rupture(cli, protocol2_design_volume()), 1e-6)
        free = protocol2_free()
        for k, r in enumerate(PARTNERS):
            check("LAMMPS protocol2: bridge A-%g mm, free_A / 3 + free_j" % (r * 1e3),
                  volumes.get(r), free[0] / 3 + free[k + 1], 1e-12)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("cli")
    parser.add_argument("lammps_env")
    parser.add_argument("plugin")
    parser.add_argument("--workdir", default="")
    args = parser.parse_args()
    workdir = args.workdir or tempfile.mkdtemp(prefix="capbridge-parity.")
    os.makedirs(workdir, exist_ok=True)
    lammps_half(args.cli, read_env(args.lammps_env), args.plugin, workdir)
    print("parity: %s (files in %s)" % ("FAIL: " + ", ".join(FAILURES) if FAILURES else "PASS",
                                        workdir))
    return 1 if FAILURES else 0


if __name__ == "__main__":
    sys.dont_write_bytecode = True
    sys.exit(main())
