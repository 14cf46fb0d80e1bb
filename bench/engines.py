"""Running the engines for bench.py: the env files scripts/configure.sh writes, one run of a
deck, and the loop time read from its log."""
import os
import re
import subprocess
import sys
import time

LOOP = re.compile(r"^Loop time of ([0-9.eE+-]+) on (\d+) procs for (\d+) steps with (\d+) atoms")
CPU_USE = re.compile(r"([0-9.]+)% CPU use")


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
    """One timed run: wall seconds of a `run`, steps, atoms, ranks, and the share of the wall
    time the process had a CPU (LAMMPS's "CPU use"; None where the log has none)."""

    def __init__(self, seconds, ranks, steps, atoms):
        self.seconds, self.ranks, self.steps, self.atoms = seconds, ranks, steps, atoms
        self.cpu_use = None

    def us_per_particle_step(self):
        """Wall time per particle and step [us] (not multiplied by the ranks)."""
        return 1e6 * self.seconds / (self.steps * self.atoms)

    def cpu_seconds(self):
        """CPU time of the run (one rank): its wall time times its CPU use."""
        if self.cpu_use is None:
            fail("a run's log has no 'CPU use' line")
        return self.seconds * self.cpu_use


def loops(log):
    """Every `run` of a LAMMPS or LIGGGHTS log, in order."""
    found = []
    with open(log) as f:
        for line in f:
            m = LOOP.match(line)
            if m:
                found.append(Loop(float(m.group(1)), int(m.group(2)), int(m.group(3)),
                                  int(m.group(4))))
            m = CPU_USE.search(line)
            if m and found and found[-1].cpu_use is None:
                found[-1].cpu_use = float(m.group(1)) / 100.0
    if not found:
        fail(f"{log} has no 'Loop time' line")
    return found


def start(engine, ranks, deck, workdir, log, variables, core=None, tool=None):
    """Starts one deck under mpirun -np ranks in workdir with -var NAME VALUE...; engine is
    (mpirun command, engine command as a list).  With core, one rank pinned to that core
    (the engine started without mpirun, under taskset); with tool (a command as a list, e.g.
    valgrind's), one rank run under it, without mpirun.  Returns (process, command, log
    path) for finish()."""
    mpirun, command = engine
    os.makedirs(workdir, exist_ok=True)
    if (core is not None or tool is not None) and ranks != 1:
        fail("a run pinned to one core or under a tool has one rank")
    if tool is not None:
        launcher = list(tool)
    elif core is not None:
        launcher = ["taskset", "-c", str(core)]
    else:
        launcher = mpirun.split() + ["-np", str(ranks)]
    cmd = launcher + command + ["-in", deck, "-log", log, "-screen", "none"]
    for name, value in variables.items():
        cmd += ["-var", name, str(value)]
    process = subprocess.Popen(cmd, cwd=workdir, stdout=subprocess.PIPE,
                               stderr=subprocess.STDOUT, text=True)
    return process, cmd, os.path.join(workdir, log)


def finish(started):
    """Waits for a run of start(); returns its log's path.  Stops the benchmark, showing the
    log's tail, if the engine failed."""
    process, cmd, path = started
    output = process.communicate()[0]
    if process.returncode != 0:
        tail = ""
        if os.path.isfile(path):
            with open(path) as f:
                tail = "".join(f.readlines()[-15:])
        fail(f"{' '.join(cmd)} failed with {process.returncode}:\n{output[-2000:]}\n{tail}")
    return path


def finish_together(runs):
    """Waits for runs of start() that run at the same time; returns their logs' paths.  If one
    fails, the others are stopped (a partner would otherwise wait for it) and it is
    reported."""
    while any(process.poll() is None for process, _, _ in runs):
        failed = [run for run in runs if run[0].returncode not in (None, 0)]
        if failed:
            for process, _, _ in runs:
                if process.poll() is None:
                    process.kill()
            finish(failed[0])
        time.sleep(0.2)
    return [finish(run) for run in runs]


def beside(engine, deck, workdir, runs, core=0):
    """Two runs of one deck at the same time, both pinned to `core`, each holding it until
    both timed runs are done (the deck's me/partner: a run that has finished its timed run
    touches <me>.done in workdir and keeps running, untimed, until <partner>.done exists), so
    that the two share the core, and the machine's state, for the whole of both timed runs.
    runs: [(label, log, variables), (label, log, variables)] in launch order.  Returns
    {label: the log's first Loop}."""
    labels = [label for label, _, _ in runs]
    if len(runs) != 2 or labels[0] == labels[1]:
        fail(f"beside() takes two runs with different labels, not {labels}")
    started = []
    for label, log, variables in runs:
        flag = os.path.join(workdir, f"{label}.done")
        if os.path.exists(flag):
            os.remove(flag)
        partner = labels[1] if label == labels[0] else labels[0]
        started.append(start(engine, 1, deck, workdir, log,
                             dict(variables, me=label, partner=partner), core=core))
    logs = finish_together(started)
    return {label: loops(log)[0] for label, log in zip(labels, logs)}


def run(engine, ranks, deck, workdir, log, variables):
    """One deck, start() to finish(): returns the log's path."""
    return finish(start(engine, ranks, deck, workdir, log, variables))
