#!/usr/bin/env python3
"""Ensemble benchmarks of issue 16, as ratios measured in one run; prints the section of docs/benchmarks.md.

Usage: python3 bench/ensemble.py [--build-dir DIR] [--quick] [--members N] [--repeats R]

DIR (default build/) must be configured with -DEOMGEN_BUILD_BENCH=ON and hold eomgen and bench/time_ensemble.
Measured: N door closings (--until psi=-pi/2, rtol 1e-10) over a theta grid
  1. bench/time_ensemble: eomgen::ensemble on 1 thread against a hand-written loop over the generated header
     (per-member overhead), and 2 threads against 1 (wall and CPU time);
  2. `eomgen run --sweep` on 1 and 2 threads (the model through its table, the CSV written);
  3. where mpirun is found and eomgen has MPI: `mpirun -n 2 eomgen run ... --threads 1` against `-n 1`.
Each timing is the median of R interleaved repeats, of the whole command and of the ensemble alone (the time
the command reports, without start-up, compilation check and MPI launch); the tables of every variant are
compared byte for byte.
The load average before and after is printed, since the machine may be shared. --quick: 1000 members,
1 repeat (seconds; what the ctest bench_ensemble_smoke runs, asserting nothing about times).
"""
import argparse
import json
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def load():
    with open("/proc/loadavg") as f:
        return f.read().split()[0]


def timed(cmd, env):
    start = time.perf_counter()
    r = subprocess.run(cmd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    seconds = time.perf_counter() - start
    if r.returncode != 0:
        sys.exit("bench/ensemble.py: %s failed (%d):\n%s" % (" ".join(cmd), r.returncode, r.stdout))
    return seconds, r.stdout


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build-dir", default=os.path.join(ROOT, "build"))
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--members", type=int)
    ap.add_argument("--repeats", type=int)
    args = ap.parse_args()
    n = args.members or (1000 if args.quick else 10000)
    repeats = args.repeats or (1 if args.quick else 5)
    eomgen = os.path.join(args.build_dir, "generator", "eomgen")
    bench = os.path.join(args.build_dir, "bench", "time_ensemble")
    for exe in (eomgen, bench):
        if not os.access(exe, os.X_OK):
            sys.exit("bench/ensemble.py: %s is not built (configure with -DEOMGEN_BUILD_BENCH=ON)" % exe)
    load_before = load()

    # 1. The library: overhead against a hand-written loop, 2 threads against 1.
    _, out = timed([bench, str(n), str(repeats)], os.environ.copy())
    lib = json.loads(out)

    # 2. and 3. The command, its cache and tables in a private directory.
    work = tempfile.mkdtemp(prefix="eomgen-bench-ensemble.")
    try:
        env = dict(os.environ, XDG_CACHE_HOME=os.path.join(work, "cache"))
        base = [eomgen, "run", os.path.join(ROOT, "models", "door.toml"), "--until", "psi=-pi/2", "--t-end", "100",
                "--rtol", "1e-10", "--sweep", "theta=0.02:pi/2:%d" % n, "--quiet"]
        timed(base + ["--sweep", "w=0.9", "--out", os.path.join(work, "warm.csv")], env)  # compiles into the cache
        variants = {"cli_1_thread": base + ["--threads", "1"], "cli_2_threads": base + ["--threads", "2"]}
        mpirun = shutil.which("mpirun")
        have_mpi = mpirun and "MPI ranks" in timed(
            [mpirun, "-n", "2", "--oversubscribe", "--allow-run-as-root"] + base[:-1] +
            ["--sweep", "w=0.9", "--threads", "1", "--out", os.path.join(work, "probe.csv")], env)[1]
        if have_mpi:
            for ranks in (1, 2):
                variants["mpi_%d_ranks" % ranks] = [mpirun, "-n", str(ranks), "--oversubscribe",
                                                    "--allow-run-as-root"] + base + ["--threads", "1"]
        times = {k: [] for k in variants}
        inner = {k: [] for k in variants}  # the ensemble's own time, as the command reports it (no start-up)
        tables = {}
        for _ in range(repeats):
            for name, cmd in variants.items():
                path = os.path.join(work, name + ".csv")
                seconds, out = timed(cmd + ["--out", path], env)
                times[name].append(seconds)
                inner[name].append(float(re.search(r"failed, on .*, ([0-9.e+-]+) s\n", out).group(1)))
                with open(path, "rb") as f:
                    tables[name] = f.read()
        if len(set(tables.values())) != 1:
            sys.exit("bench/ensemble.py: the tables differ between " + ", ".join(tables))
    finally:
        shutil.rmtree(work, ignore_errors=True)
    med = {k: statistics.median(v) for k, v in times.items()}
    ens = {k: statistics.median(v) for k, v in inner.items()}
    load_after = load()

    lines = [
        "Measured by `python3 bench/ensemble.py` (%d door closings, --until psi=-pi/2, rtol 1e-10, theta from 0.02 "
        "to pi/2; medians of %d interleaved repeats; %d cores; load average %s before, %s after)." %
        (n, repeats, lib["cores"], load_before, load_after), "",
        "| what | time [s] | ratio |", "|---|---|---|",
        "| hand-written loop over `generated/door.hpp` (1 thread) | %.3f (CPU %.3f) | 1 |" %
        (lib["hand_loop_s"], lib["hand_loop_cpu_s"]),
        "| `eomgen::ensemble`, 1 thread | %.3f (CPU %.3f) | overhead %+.1f %% wall, %+.1f %% CPU |" %
        (lib["ensemble_1_thread_s"], lib["ensemble_1_thread_cpu_s"], 100 * lib["overhead_1_thread"],
         100 * lib["overhead_1_thread_cpu"]),
        "| `eomgen::ensemble`, 2 threads | %.3f (CPU %.3f) | speed-up %.2fx; CPU %.2fx of 1 thread's |" %
        (lib["ensemble_2_threads_s"], lib["ensemble_2_threads_cpu_s"], lib["speedup_2_threads"],
         lib["cpu_2_threads_over_1"]),
        "| `eomgen run --sweep`, 1 thread | %.3f (ensemble %.3f) | |" % (med["cli_1_thread"], ens["cli_1_thread"]),
        "| `eomgen run --sweep`, 2 threads | %.3f (ensemble %.3f) | speed-up %.2fx (ensemble %.2fx) |" %
        (med["cli_2_threads"], ens["cli_2_threads"], med["cli_1_thread"] / med["cli_2_threads"],
         ens["cli_1_thread"] / ens["cli_2_threads"]),
    ]
    if have_mpi:
        lines += [
            "| `mpirun -n 1 eomgen run --sweep --threads 1` | %.3f (ensemble %.3f) | |" %
            (med["mpi_1_ranks"], ens["mpi_1_ranks"]),
            "| `mpirun -n 2 eomgen run --sweep --threads 1` | %.3f (ensemble %.3f) | speed-up %.2fx (ensemble %.2fx) |" %
            (med["mpi_2_ranks"], ens["mpi_2_ranks"], med["mpi_1_ranks"] / med["mpi_2_ranks"],
             ens["mpi_1_ranks"] / ens["mpi_2_ranks"]),
        ]
    else:
        lines.append("| MPI | not measured: mpirun or eomgen's MPI not found | |")
    lines += ["", "Members per CPU second (1 thread): %.0f. Every variant's table was the same, byte for byte." %
              lib["members_per_cpu_s"]]
    print("\n".join(lines))


if __name__ == "__main__":
    main()
