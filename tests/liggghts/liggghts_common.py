"""Helpers shared by the LIGGGHTS tests of capbridge (tests/liggghts/*.py).

Standard library only. Runs LIGGGHTS from a liggghts.env written by
scripts/build_liggghts.sh, runs the capbridge CLI, and reads Gladkyy's 13 cases from
reference_data/cases.csv.
"""
import argparse
import hashlib
import os
import shlex
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
LAWS = ["richefeu", "willett", "willett/reduced", "rabinovich", "rabinovich/uncorrected",
        "weigert", "soulie", "table"]


def fail(message):
    print("FAIL: " + message, file=sys.stderr)
    sys.exit(1)


def read_env(path):
    """KEY=VALUE lines of liggghts.env (values may be double-quoted)."""
    env = {}
    with open(path) as f:
        for line in f:
            line = line.strip()
            if not line or line.startswith("#") or "=" not in line:
                continue
            key, value = line.split("=", 1)
            if len(value) >= 2 and value[0] == value[-1] == '"':
                value = value[1:-1]
            env[key] = value
    for key in ("LIGGGHTS_BINARY", "LIGGGHTS_MPIRUN"):
        if key not in env:
            fail("%s has no %s (rerun scripts/build_liggghts.sh)" % (path, key))
    return env


def argument_parser(doc):
    """The command line every LIGGGHTS test shares: the liggghts.env file and --workdir;
    a test adds its own options."""
    parser = argparse.ArgumentParser(description=doc.split("\n")[0])
    parser.add_argument("env")
    parser.add_argument("--workdir", default="")
    return parser


def start(env_path, workdir, name):
    """The engine's env (checked to hold this repository's models and core) and the test's
    working directory: --workdir, or a new temporary one named after the test."""
    env = read_env(env_path)
    check_models_current(env)
    workdir = workdir or tempfile.mkdtemp(prefix="capbridge-liggghts-%s." % name)
    os.makedirs(workdir, exist_ok=True)
    return env, workdir


def check_models_current(env):
    """The LIGGGHTS build must contain this repository's model headers."""
    models = os.path.join(REPO, "lammps_pair", "liggghts")
    built = env.get("LIGGGHTS_MODELS_DIR", "")
    if not built or os.path.realpath(built) != os.path.realpath(models):
        fail("LIGGGHTS was built without %s (LIGGGHTS_MODELS_DIR=%r); run "
             "scripts/build_liggghts.sh" % (models, built))
    for name in sorted(os.listdir(models)):
        if not name.endswith(".h"):
            continue
        src = os.path.join(env["LIGGGHTS_SOURCE_DIR"], name)
        with open(os.path.join(models, name), "rb") as a:
            mine = a.read()
        try:
            with open(src, "rb") as b:
                theirs = b.read()
        except OSError:
            theirs = None
        if mine != theirs:
            fail("the LIGGGHTS build is older than %s; run scripts/build_liggghts.sh" % name)
    # the C core linked into LIGGGHTS: the hash scripts/build_liggghts.sh computes
    # (hash_files in scripts/engine_common.sh) over src_c/*.c and src_c/*.h
    core = os.path.join(REPO, "src_c")
    names = sorted((n for n in os.listdir(core) if n.endswith((".c", ".h"))),
                   key=lambda n: os.path.join(core, n).encode())
    digest = hashlib.sha256()
    for name in names:
        digest.update(name.encode() + b"\n")
        with open(os.path.join(core, name), "rb") as f:
            digest.update(f.read())
    if env.get("LIGGGHTS_CORE_SOURCES_HASH") != digest.hexdigest()[:16]:
        fail("the capbridge core in LIGGGHTS (%s) is not the one in src_c/ (%s); run "
             "scripts/build_liggghts.sh" % (env.get("LIGGGHTS_CORE_SOURCES_HASH"),
                                            digest.hexdigest()[:16]))


def liquid_words(protocol):
    """The model's keywords after `liquid` for `protocol`, Protocols 2 and 3 starting from
    the free liquid (`start free`), as the tests written before `start bridges` expect."""
    return protocol if protocol == "protocol1" else protocol + " start free"


def free_liquid_header(ranks, box, neighbor, stiffness, friction, free):
    """The start of a LIGGGHTS deck with per-atom free liquid: SI units, `ranks` along x, a
    cube box of x from box[0] to box[1] (y and z +-0.01 m), a bin neighbor skin `neighbor`,
    undamped k_n = k_t = `stiffness`, friction `friction`, water's surface tension, theta 0,
    and fix freeLiquid with `free` m^3 per atom.  Each argument is written as given (a
    number by repr), so that the deck is the same text for the same values."""
    return """units           si
atom_style      granular
atom_modify     map array
boundary        f f f
newton          off
communicate     single vel yes
processors      {ranks} 1 1
region          box block {x0} {x1} -0.01 0.01 -0.01 0.01 units box
create_box      1 box
neighbor        {neighbor} bin
neigh_modify    delay 0
fix m1 all property/global kn peratomtypepair 1 {stiffness}
fix m2 all property/global kt peratomtypepair 1 {stiffness}
fix m3 all property/global gamman peratomtypepair 1 0
fix m4 all property/global gammat peratomtypepair 1 0
fix m5 all property/global coefficientFriction peratomtypepair 1 {friction}
fix m6 all property/global surfaceTension scalar 0.0728
fix m7 all property/global contactAngle peratomtype 0
fix freeLiquid all property/atom freeLiquid scalar yes yes no {free!r}
""".format(ranks=ranks, x0=box[0], x1=box[1], neighbor=neighbor, stiffness=stiffness,
           friction=friction, free=free)


def two_spheres_deck(kn, mu, gamma, cohesion, x2, diameter):
    """The start of a LIGGGHTS deck: two spheres of `diameter` at x = 0 and x = x2 (both on
    the x axis, a 2 cm box), a linear spring k_n (hooke/stiffness, no damping, k_t 1e4 N/m,
    friction mu), surface tension gamma, theta 0, bridge volume 1e-11 m^3, and
    `cohesion capillary COHESION` (the model's keywords). The test appends its run."""
    return """units           si
atom_style      granular
atom_modify     map array
boundary        f f f
newton          off
communicate     single vel yes
region          box block -0.01 0.01 -0.01 0.01 -0.01 0.01 units box
create_box      1 box
neighbor        5e-4 bin
neigh_modify    delay 0
fix m1 all property/global kn peratomtypepair 1 {kn!r}
fix m2 all property/global kt peratomtypepair 1 1e4
fix m3 all property/global gamman peratomtypepair 1 0
fix m4 all property/global gammat peratomtypepair 1 0
fix m5 all property/global coefficientFriction peratomtypepair 1 {mu!r}
fix m6 all property/global surfaceTension scalar {gamma!r}
fix m7 all property/global contactAngle peratomtype 0
fix m8 all property/global bridgeVolume peratomtypepair 1 1e-11
pair_style      gran model hooke/stiffness tangential history cohesion capillary {cohesion}
pair_coeff      * *
timestep        1e-6
create_atoms    1 single 0 0 0 units box
create_atoms    1 single {x2!r} 0 0 units box
set             atom * diameter {diameter!r} density 2500
""".format(kn=kn, mu=mu, gamma=gamma, cohesion=cohesion, x2=x2, diameter=diameter)


def gladkyy_cases():
    """The 13 configurations of Gladkyy & Schwarze 2014, Table 1, with their exact curves:
    {name: {r1, r2, gamma, theta, volume, rupture, gaps[], forces[]}} in file order."""
    path = os.path.join(REPO, "reference_data", "cases.csv")
    cases = {}
    order = []
    with open(path) as f:
        header = None
        for line in f:
            if line.startswith("#"):
                continue
            fields = line.strip().split(",")
            if header is None:
                header = fields
                continue
            row = dict(zip(header, fields))
            name = row["case"]
            if name not in cases:
                order.append(name)
                cases[name] = {
                    "name": name, "r1": row["r1"], "r2": row["r2"],
                    "gamma": row["surface_tension"], "theta": row["contact_angle"],
                    "volume": row["volume"], "rupture": float(row["rupture_distance"]),
                    "gaps": [], "forces": []}
            cases[name]["gaps"].append(float(row["gap"]))
            cases[name]["forces"].append(float(row["force"]))
    return [cases[n] for n in order]


def run(command, cwd, what, timeout=600):
    # LIGGGHTS may print undecodable bytes (its Error::all appends a "special message"
    # that is sometimes uninitialised memory)
    result = subprocess.run(command, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            universal_newlines=True, encoding="utf-8", errors="replace",
                            timeout=timeout)
    return result


def liggghts(env, deck, variables, workdir, ranks=1, log="log.liggghts", screen="none"):
    """Run LIGGGHTS on `deck` with -var NAME VALUE pairs; returns (returncode, log text).
    screen: a file for -screen where a deck reads a mesh (LIGGGHTS 3.8.0's mesh import writes
    to the screen unchecked: with -screen none, fix mesh/surface crashes)."""
    command = []
    if ranks > 1:
        command += shlex.split(env["LIGGGHTS_MPIRUN"]) + ["-np", str(ranks)]
    command += [env["LIGGGHTS_BINARY"], "-in", deck, "-log", log, "-screen", screen]
    for name, value in variables:
        command += ["-var", name, str(value)]
    result = run(command, workdir, deck)
    text = ""
    path = os.path.join(workdir, log)
    if os.path.exists(path):
        with open(path, encoding="utf-8", errors="replace") as f:
            text = f.read()
    return result.returncode, text + result.stdout + result.stderr


def thermo_rows(log_text):
    """The numeric rows of every thermo block: lists of strings (a warning printed inside a
    block does not end it)."""
    rows = []
    inside = False
    for line in log_text.splitlines():
        fields = line.split()
        if fields and fields[0] == "Step":
            inside = True
            continue
        if inside and fields and fields[0] == "WARNING:":
            continue
        if inside:
            if not fields or not fields[0].lstrip("-").isdigit():
                inside = False
                continue
            rows.append(fields)
    return rows


def error_line(log_text):
    for line in log_text.splitlines():
        if "ERROR" in line:
            return line.strip()
    return None


def write_plane_stl(path):
    """The square |x|, |y| <= 5 mm of z = 0 as two triangles sharing the diagonal x = y (an STL
    file for fix mesh/surface: the mesh wall of wall.py and wall_liquid.py)."""
    a = 5e-3
    with open(path, "w") as f:
        f.write("solid plane\n")
        for tri in (((-a, -a), (a, -a), (a, a)), ((-a, -a), (a, a), (-a, a))):
            f.write(" facet normal 0 0 1\n  outer loop\n")
            for x, y in tri:
                f.write("   vertex %r %r 0\n" % (x, y))
            f.write("  endloop\n endfacet\n")
        f.write("endsolid plane\n")
