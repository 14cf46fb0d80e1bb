"""Running the engines for bench.py: the env files scripts/configure.sh writes, one run of a
deck, and the loop time read from its log."""
import os
import re
import subprocess
import sys

LOOP = re.compile(r"^Loop time of ([0-9.eE+-]+) on (\d+) procs for (\d+) steps with (\d+) atoms")


def fail(msg):
    sys.exit("bench: " + msg)


def read_env(path):
    """KEY=VALUE lines of an env file (values may be double-quoted)."""
    if not os.path.isfile(path):
        fail(f"no {path}: run scripts/configure.sh first (it builds the engines)")
    env = {}
    with open(path) as f:
        for line in f:
            m = re.match(r'^([A-Z_]+)="?([^"]*)"?$', line.strip())
            if m:
                env[m.group(1)] = m.group(2)
    return env


def engines(cache):
    lammps = read_env(os.path.join(cache, "lammps-20250204", "lammps.env"))
    liggghts = read_env(os.path.join(cache, "liggghts-3.8.0", "liggghts.env"))
    return lammps, liggghts


class Loop:
    """One timed run: wall seconds of a `run`, steps, atoms, ranks."""

    def __init__(self, seconds, ranks, steps, atoms):
        self.seconds, self.ranks, self.steps, self.atoms = seconds, ranks, steps, atoms

    def us_per_particle_step(self):
        """Wall time per particle and step [us] (not multiplied by the ranks)."""
        return 1e6 * self.seconds / (self.steps * self.atoms)


def loops(log):
    """Every `run` of a LAMMPS or LIGGGHTS log, in order."""
    found = []
    with open(log) as f:
        for line in f:
            m = LOOP.match(line)
            if m:
                found.append(Loop(float(m.group(1)), int(m.group(2)), int(m.group(3)),
                                  int(m.group(4))))
    if not found:
        fail(f"{log} has no 'Loop time' line")
    return found


def run(engine, ranks, deck, workdir, log, variables):
    """Runs one deck under mpirun -np ranks in workdir with -var NAME VALUE...; engine is
    (mpirun command, engine command as a list); returns the log's path. Stops the benchmark,
    showing the log's tail, if the engine fails."""
    mpirun, command = engine
    os.makedirs(workdir, exist_ok=True)
    cmd = mpirun.split() + ["-np", str(ranks)] + command + ["-in", deck, "-log", log,
                                                           "-screen", "none"]
    for name, value in variables.items():
        cmd += ["-var", name, str(value)]
    done = subprocess.run(cmd, cwd=workdir, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, text=True)
    path = os.path.join(workdir, log)
    if done.returncode != 0:
        tail = ""
        if os.path.isfile(path):
            with open(path) as f:
                tail = "".join(f.readlines()[-15:])
        fail(f"{' '.join(cmd)} (in {workdir}) failed with {done.returncode}:\n{done.stdout[-2000:]}"
             f"\n{tail}")
    return path
