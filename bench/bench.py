#!/usr/bin/env python3
"""The benchmark run behind bench/run.sh: eomgen against SymPy and Boost.Odeint, in one run.

Usage: bench.py --build-dir DIR [--smoke] [--no-build] [--peers-only] [--sympy-cap SECONDS] [--out-md FILE]
                [--out-png FILE]
       bench.py --build-dir DIR --only integrators [--smoke]   (section 5b on stdout, in a minute; docs/ untouched)

Items (issue 6): 1 generation time (eomgen CLI vs SymPy LagrangesMethod + cse + ccode; eomgen alone to n = 30),
2 operation counts (one counter, bench/op_count.py, for both), 3 right-hand-side time (bench/time_rhs),
4 compile time of each generated header at -O2, 5 work-precision against odeint (bench/time_integrators),
5b DOP853 against Dormand–Prince 5(4) (issue 15; the same program), 6 peak memory of generation at n = 30; 8 (issue 15,
bench/peers.py) MuJoCo's mj_forward and an O(n) recursion on the n-link chain, and CVODE, ARKODE and odeint in
work-precision (--peers-only: only this part). Writes the measured part of docs/benchmarks.md (between the
MEASURED markers; the rest of the file is kept) and docs/benchmarks.png. --smoke: tiny sizes, output to
DIR/bench_smoke/, nothing asserted about times. Needs python3 only; SymPy is optional (its parts are
skipped with a message when it is missing).
"""
import argparse
import datetime
import json
import os
import platform
import re
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
import op_count  # noqa: E402
import animation  # noqa: E402
import python_api  # noqa: E402
import interpreter  # noqa: E402
import bicycle  # noqa: E402
import fit  # noqa: E402
import peers  # noqa: E402
import scale  # noqa: E402

BEGIN = "<!-- BEGIN MEASURED (bench/run.sh rewrites this part) -->"
END = "<!-- END MEASURED -->"
BEGIN_PEERS = "<!-- BEGIN MEASURED PEERS (bench/run.sh, or bench/run.sh --peers-only, rewrites this part) -->"
END_PEERS = "<!-- END MEASURED PEERS -->"
BEGIN_SCALE = "<!-- BEGIN MEASURED SCALE (bench/run.sh, or bench/run.sh --scale-only, rewrites this part) -->"
END_SCALE = "<!-- END MEASURED SCALE -->"
BEGIN_FIT = "<!-- BEGIN MEASURED FIT (bench/run.sh, or bench/run.sh --fit-only, rewrites this part) -->"
END_FIT = "<!-- END MEASURED FIT -->"
BEGIN_BICYCLE = "<!-- BEGIN MEASURED BICYCLE (bench/run.sh, or bench/run.sh --bicycle-only, rewrites this part) -->"
END_BICYCLE = "<!-- END MEASURED BICYCLE -->"
BEGIN_ANIMATION = "<!-- BEGIN MEASURED ANIMATION (bench/run.sh, or bench/run.sh --animation-only, rewrites this part) -->"
END_ANIMATION = "<!-- END MEASURED ANIMATION -->"
BEGIN_PYTHON = "<!-- BEGIN MEASURED PYTHON (bench/run.sh, or bench/run.sh --python-only, rewrites this part) -->"
END_PYTHON = "<!-- END MEASURED PYTHON -->"
BEGIN_INTERPRETER = "<!-- BEGIN MEASURED INTERPRETER (bench/run.sh, or bench/run.sh --interpreter-only, rewrites this part) -->"
END_INTERPRETER = "<!-- END MEASURED INTERPRETER -->"


def log(msg):
    print(f"[bench] {msg}", flush=True)


def children_cpu():
    import resource
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def timed(cmd, **kw):
    """Runs cmd; returns (wall seconds, CPU seconds of the child, completed process)."""
    c0 = children_cpu()
    t0 = time.perf_counter()
    p = subprocess.run(cmd, check=True, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, **kw)
    return time.perf_counter() - t0, children_cpu() - c0, p


def peak_rss_kb(cmd):
    """Peak resident set size of one run of cmd (getrusage of a fresh parent, so only that child counts)."""
    probe = ("import resource, subprocess, sys\n"
             "subprocess.run(sys.argv[1:], check=True, stdout=subprocess.DEVNULL)\n"
             "print(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)\n")
    out = subprocess.run([sys.executable, "-c", probe] + cmd, check=True, stdout=subprocess.PIPE, text=True)
    return int(out.stdout.strip().splitlines()[-1])


def sh(cmd):
    try:
        return subprocess.run(cmd, shell=True, check=True, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                              text=True).stdout.strip()
    except subprocess.CalledProcessError:
        return "?"


def machine(cfg):
    cpu = sh("lscpu | sed -n 's/^Model name: *//p' | head -1")
    mem = sh("awk '/MemTotal/ {printf \"%.1f GiB\", $2/1048576}' /proc/meminfo")
    osname = sh(". /etc/os-release && echo $PRETTY_NAME")
    return {
        "date": utc_now(),
        "cpu": cpu, "cores": os.cpu_count(), "memory": mem, "os": osname, "kernel": platform.release(),
        "compiler": sh(f"{cfg['cxx']} --version | head -1"),
        "ginac": sh("pkg-config --modversion ginac"), "eigen": sh("pkg-config --modversion eigen3"),
        "boost": sh("grep -m1 'define BOOST_LIB_VERSION' /usr/include/boost/version.hpp | cut -d'\"' -f2"),
        "benchmark": sh("dpkg-query -W -f='${Version}' libbenchmark-dev"),
        "python": platform.python_version(),
        "sympy": sh(f"{sys.executable} -c 'import sympy; print(sympy.__version__)'"),
        "load": os.getloadavg(),
        "commit": sh(f"git -C {ROOT} rev-parse --short HEAD")
        + (" (with uncommitted changes)" if sh(f"git -C {ROOT} status --porcelain --untracked-files=no -- generator runtime") not in ("", "?") else ""),
    }


def have_sympy():
    return subprocess.run([sys.executable, "-c", "import sympy"], stdout=subprocess.DEVNULL,
                          stderr=subprocess.DEVNULL).returncode == 0


# ---- 1. generation --------------------------------------------------------------------------------------------

def generation(cfg, work, family, sizes, reps):
    """eomgen CLI wall/CPU time per n (best of reps), and time_generate's phases and OpCount."""
    out = {}
    gen_dir = os.path.join(work, "generated", "eomgen", "models")
    os.makedirs(gen_dir, exist_ok=True)
    for n in sizes:
        best = None
        for _ in range(reps(n)):
            # A fresh output each time, so every run writes its header.
            path = os.path.join(gen_dir, f"{family}_{n}.hpp")
            if os.path.exists(path):
                os.remove(path)
            w, c, _ = timed([cfg["eomgen"], "generate", "--family", f"{family}:n={n}", "-o", gen_dir])
            best = (w, c) if best is None or w < best[0] else best
        _, _, p = timed([cfg["time_generate"], family, str(n)])
        phases = json.loads(p.stdout.strip().splitlines()[-1])
        out[n] = {"wall_s": best[0], "cpu_s": best[1], "phases": phases,
                  "header": os.path.join(gen_dir, f"{family}_{n}.hpp")}
        log(f"eomgen {family}:n={n}: {best[0]:.3f} s wall, {best[1]:.3f} s CPU "
            f"(derive {phases['derive_s']:.3f} s, emit {phases['emit_s']:.3f} s)")
    return out


def sympy_runs(work, sizes, cap):
    out = {}
    sym_dir = os.path.join(work, "sympy")
    os.makedirs(sym_dir, exist_ok=True)
    capped_at = None
    for n in sizes:
        if capped_at is not None:
            out[n] = {"capped": True, "cap_s": cap, "skipped": True}
            continue
        log(f"SymPy n={n} (cap {cap:.0f} s) ...")
        try:
            p = subprocess.run([sys.executable, os.path.join(HERE, "sympy_pendulum.py"), str(n), sym_dir],
                               check=True, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=cap)
            r = json.loads(p.stdout.strip().splitlines()[-1])
            r["header"] = os.path.join(sym_dir, f"sympy_pendulum_{n}.hpp")
            out[n] = r
            log(f"SymPy n={n}: {r['total_s']:.2f} s wall, {r['cpu_s']:.2f} s CPU")
        except subprocess.TimeoutExpired:
            out[n] = {"capped": True, "cap_s": cap}
            capped_at = n
            log(f"SymPy n={n}: stopped at the cap of {cap:.0f} s")
    return out


# ---- 3. right-hand side ---------------------------------------------------------------------------------------

def rhs_times(cfg, args, work, sizes, sym):
    exe = cfg["time_rhs"]
    # The full run compiles SymPy's code of this run into time_rhs; the smoke run uses time_rhs as built.
    if not args.smoke:
        sym_dir = os.path.join(work, "sympy")
        subprocess.run(["cmake", "-S", ROOT, "-B", args.build_dir, f"-DEOMGEN_BENCH_SIZES={';'.join(map(str, sizes))}",
                        f"-DEOMGEN_BENCH_SYMPY_DIR={sym_dir}"], check=True, stdout=subprocess.DEVNULL)
        log("building time_rhs ...")
        subprocess.run(["cmake", "--build", args.build_dir, "--target", "time_rhs", "-j", "2"], check=True,
                       stdout=subprocess.DEVNULL)
    # Repetitions in random order, so that load from other processes (a shared core) hits both sides alike.
    min_time = "0.01" if args.smoke else "0.1"
    reps = "1" if args.smoke else "10"
    p = subprocess.run([exe, "--benchmark_format=json", f"--benchmark_min_time={min_time}",
                        f"--benchmark_repetitions={reps}", "--benchmark_enable_random_interleaving=true"],
                       check=True, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    agree = p.stderr.strip()
    data = json.loads(p.stdout)
    runs = {}
    for b in data["benchmarks"]:
        if b.get("run_type") == "aggregate":
            continue
        kind, who, n = b["run_name"].split("/")
        runs.setdefault((kind, who, int(n)), []).append(
            b["cpu_time"] * {"ns": 1, "us": 1e3, "ms": 1e6}[b["time_unit"]])
    median = {k: sorted(v)[len(v) // 2] if len(v) % 2 else sum(sorted(v)[len(v) // 2 - 1:len(v) // 2 + 1]) / 2
              for k, v in runs.items()}
    return median, agree


# ---- 4. compile time ------------------------------------------------------------------------------------------

def compile_times(cfg, work, gen, sym, sizes):
    cdir = os.path.join(work, "compile")
    os.makedirs(cdir, exist_ok=True)
    flags = cfg["flags"].split(";")
    includes = []
    for inc in cfg["includes"]:
        includes += [f"-I{i}" for i in inc.split(";") if i]
    out = {}
    for n in sizes:
        r = {}
        if n in gen:
            tu = os.path.join(cdir, f"eomgen_{n}.cpp")
            with open(tu, "w") as fh:
                fh.write(f'#include "eomgen/models/pendulum_{n}.hpp"\n'
                         f"template struct eomgen::models::pendulum_{n}::Model<double>;\n")
            cmd = [cfg["cxx"], "-std=c++17"] + flags + includes + [
                f"-I{os.path.dirname(os.path.dirname(os.path.dirname(gen[n]['header'])))}", "-c", tu, "-o", tu + ".o"]
            w, c, _ = timed(cmd)
            r["eomgen"] = {"wall_s": w, "cpu_s": c, "bytes": os.path.getsize(gen[n]["header"])}
        if n in sym and "header" in sym[n]:
            tu = os.path.join(cdir, f"sympy_{n}.cpp")
            with open(tu, "w") as fh:
                fh.write(f'#include "sympy_pendulum_{n}.hpp"\n'
                         "void bench_dynamics(const double* q, const double* qd, const double* p, double* M, "
                         f"double* f) {{ sympy_pendulum_{n}::dynamics(q, qd, p, M, f); }}\n")
            cmd = [cfg["cxx"], "-std=c++17"] + flags + [f"-I{os.path.dirname(sym[n]['header'])}", "-c", tu, "-o",
                                                        tu + ".o"]
            w, c, _ = timed(cmd)
            r["sympy"] = {"wall_s": w, "cpu_s": c, "bytes": os.path.getsize(sym[n]["header"])}
        out[n] = r
        log(f"compile n={n}: " + ", ".join(f"{k} {v['wall_s']:.2f} s" for k, v in r.items()))
    return out


# ---- 5. work-precision ----------------------------------------------------------------------------------------

TARGET_ERRORS = [1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12]


def to_reach(rows, target):
    """The cheapest run from which on every tighter tolerance also reaches `target` (a lucky cancellation at
    a loose tolerance does not count)."""
    rows = sorted(rows, key=lambda r: -r["rtol"])
    for i, r in enumerate(rows):
        if all(x["error"] <= target for x in rows[i:]):
            return r
    return None


def integrators(cfg, smoke):
    p = subprocess.run([cfg["time_integrators"]] + (["--quick"] if smoke else []), check=True,
                       stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    rows = [json.loads(line) for line in p.stdout.splitlines() if line.startswith("{")]
    by = {}
    for r in rows:
        by.setdefault((r["problem"], r["method"]), []).append(r)
    return by, p.stderr.strip()


HIGH_ORDER_ERRORS = [1e-6, 1e-8, 1e-10, 1e-12, 1e-13, 1e-14]


def high_order_md(by):
    """Section 5b: DOP853 against Dormand–Prince 5(4) on the same problems and driver (issue 15), as lines."""
    L = []
    a = L.append
    a("## 5b. High order: DOP853 against Dormand–Prince 5(4) (issue 15)")
    a("")
    a("`bench/time_integrators` as in section 5, eomgen's two adaptive steppers through the same driver "
      "(`eomgen::integrate_with<Dopri5>` and `<Dop853>`: Hairer's defaults each, atol = rtol; the door's tolerances "
      "go down to 1e-16). DOP853's dense output costs three more evaluations on the step where the door's event "
      "falls, counted. A cell: the cheapest run from which on every tighter tolerance also reaches the error, "
      "RHS evaluations (µs); the ratios are Dormand–Prince 5(4) over DOP853, of evaluations and of time.")
    a("")
    a("| error reached | door: dopri5 | door: dop853 | evals ratio | time ratio | pendulum: dopri5 | pendulum: dop853 "
      "| evals ratio | time ratio |")
    a("|---|---|---|---|---|---|---|---|---|")

    def cells(problem, t):
        r5 = to_reach(by.get((problem, "eomgen_dopri5"), []), t)
        r8 = to_reach(by.get((problem, "eomgen_dop853"), []), t)
        c = [f"{r['rhs_evals']} ({r['seconds'] * 1e6:.0f})" if r else "not reached" for r in (r5, r8)]
        if r5 and r8:
            c += [f"{r5['rhs_evals'] / r8['rhs_evals']:.2f}", f"{r5['seconds'] / r8['seconds']:.2f}"]
        else:
            c += ["–", "–"]
        return c

    for t in HIGH_ORDER_ERRORS:
        a(f"| {t:.0e} | " + " | ".join(cells("door", t) + cells("pendulum", t)) + " |")
    a("")
    r5 = to_reach(by.get(("door", "eomgen_dopri5"), []), 1e-14)
    r8 = to_reach(by.get(("door", "eomgen_dop853"), []), 1e-14)
    if r5 and r8:
        ev, tm = r5["rhs_evals"] / r8["rhs_evals"], r5["seconds"] / r8["seconds"]
        a(f"Target (issue 15): the door's closing time to 1e-14 relative in double at least 3× cheaper than "
          f"Dormand–Prince 5(4): {r5['rhs_evals']} / {r8['rhs_evals']} = **{ev:.2f}×** fewer evaluations, "
          f"{r5['seconds'] * 1e6:.1f} / {r8['seconds'] * 1e6:.1f} µs = **{tm:.2f}×** less time: "
          f"{verdict(min(ev, tm) >= 3)}.")
    else:
        a("Target (issue 15): the door's closing time to 1e-14 at least 3× cheaper than Dormand–Prince 5(4): "
          "not reached by both in this run.")
    return L


# ---- 7. eomgen run: first run, cached re-run, integration through the table ---------------------------------

RUN_MODELS = [("examples/bead_on_hoop.toml", None), ("models/pendulum_5_20.toml", "pendulum_5_20"),
              ("models/pendulum_cartesian.toml", "pendulum_cartesian")]


def run_times(cfg, work, smoke):
    """`eomgen run MODEL --t-end 5 --quiet` with a fresh cache (first run: derive, compile, integrate), then again
    (cached), and eomgen-sim on the same model (built in: the integration and a process start) where it has
    it; then a long integration through the shared object's table against eomgen-sim. Since 2026-11-26 eomgen-sim
    also runs its models through tables, with the driver eomgen run uses (simulator/table_driver.cpp), so the
    ratio is that of a loaded shared object against a table linked into the program."""
    reps = 1 if smoke else 3
    out = {"models": []}
    sim = cfg.get("eomgen_sim")
    for rel, sim_name in (RUN_MODELS[1:2] if smoke else RUN_MODELS):
        model = os.path.join(ROOT, rel)
        row = {"model": rel, "first": [], "cached": [], "sim": []}
        for k in range(reps):
            env = dict(os.environ, XDG_CACHE_HOME=os.path.join(work, "run_cache", f"{os.path.basename(rel)}.{k}"))
            w, c, _ = timed([cfg["eomgen"], "run", model, "--t-end", "5", "--quiet"], env=env)
            row["first"].append({"wall_s": w, "cpu_s": c})
            w, c, _ = timed([cfg["eomgen"], "run", model, "--t-end", "5", "--quiet"], env=env)
            row["cached"].append({"wall_s": w, "cpu_s": c})
            if sim and sim_name:
                w, c, _ = timed([sim, sim_name, "--t-end", "5"])
                row["sim"].append({"wall_s": w, "cpu_s": c})
        out["models"].append(row)
    if sim:
        t_end = "50" if smoke else "2000"
        env = dict(os.environ, XDG_CACHE_HOME=os.path.join(work, "run_cache", "pendulum_5_20.toml.0"))
        model = os.path.join(ROOT, "models/pendulum_5_20.toml")
        long = {"t_end": float(t_end), "table": [], "compiled_in": []}
        for _ in range(reps):  # interleaved
            w, c, p = timed([cfg["eomgen"], "run", model, "--t-end", t_end, "--quiet"], env=env)
            long["table"].append(c)
            w, c, q = timed([sim, "pendulum_5_20", "--t-end", t_end])
            long["compiled_in"].append(c)
            long["rhs"] = next((l for l in p.stdout.splitlines() if l.startswith("steps:")), "")
            long["same_result"] = p.stdout == q.stdout
        out["long"] = long
    return out


# ---- report ---------------------------------------------------------------------------------------------------

def fmt_s(x):
    if x is None:
        return "–"
    if x >= 100:
        return f"{x:.0f}"
    if x >= 10:
        return f"{x:.1f}"
    if x >= 1:
        return f"{x:.2f}"
    if x >= 0.01:
        return f"{x:.3f}"
    return f"{x:.4f}"


def verdict(ok):
    return "**met**" if ok else "**not met**"


def write_plot(work, out_png, gen, sym, ops, rhs, by):
    if not shutil.which("gnuplot"):
        log("gnuplot not found: no plot")
        return False
    d = os.path.join(work, "plot")
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, "gen.dat"), "w") as fh:
        for n in sorted(gen):
            s = sym.get(n, {})
            ph = gen[n]["phases"]
            fh.write(f"{n} {gen[n]['cpu_s']} {ph['derive_s']} {ph['derive_s'] + ph['dynamics_emit_s']} "
                     f"{s.get('cpu_s', 'NaN')}\n")
    with open(os.path.join(d, "ops.dat"), "w") as fh:
        for n in sorted(ops):
            fh.write(f"{n} {ops[n]['eomgen']['total']} {ops[n].get('sympy', {}).get('total', 'NaN')}\n")
    with open(os.path.join(d, "rhs.dat"), "w") as fh:
        for n in sorted({k[2] for k in rhs}):
            fh.write(f"{n} {rhs.get(('rhs', 'eomgen', n), 'NaN')} {rhs.get(('rhs', 'sympy', n), 'NaN')} "
                     f"{rhs.get(('dynamics', 'eomgen', n), 'NaN')} {rhs.get(('dynamics', 'sympy', n), 'NaN')}\n")
    for (problem, method), rows in by.items():
        with open(os.path.join(d, f"wp_{problem}_{method}.dat"), "w") as fh:
            for r in sorted(rows, key=lambda r: r["rhs_evals"]):
                fh.write(f"{r['rhs_evals']} {max(r['error'], 1e-17)}\n")
    gp = f"""set terminal pngcairo size 1400,1000 font "Sans,11"
set output "{out_png}"
set termoption noenhanced
set multiplot layout 2,2 title "eomgen vs SymPy 1.14 and Boost.Odeint (n-link planar pendulum; bench/run.sh)"
set key bottom right
set grid
set logscale y
set xlabel "n (links)"
set ylabel "seconds"
set title "1. Generation time"
plot "{d}/gen.dat" u 1:2 w lp pt 7 t "eomgen generate (CPU, whole header)", \\
     "{d}/gen.dat" u 1:4 w lp pt 6 t "eomgen derive + emit of M and f only", \\
     "{d}/gen.dat" u 1:3 w lp pt 1 t "  of which derive (GiNaC)", \\
     "{d}/gen.dat" u 1:5 w lp pt 5 t "SymPy LagrangesMethod + cse + ccode (CPU)"
set key top left
set ylabel "operations"
set title "2. Operations in M and f (bench/op_count.py)"
plot "{d}/ops.dat" u 1:2 w lp pt 7 t "eomgen", "{d}/ops.dat" u 1:3 w lp pt 5 t "SymPy cse"
set ylabel "ns per call"
set title "3. Right-hand side: M, f and Cholesky solve (same harness, -O2)"
plot "{d}/rhs.dat" u 1:2 w lp pt 7 t "eomgen rhs", "{d}/rhs.dat" u 1:3 w lp pt 5 t "SymPy C rhs", \\
     "{d}/rhs.dat" u 1:4 w lp pt 6 dt 2 t "eomgen M, f only", "{d}/rhs.dat" u 1:5 w lp pt 4 dt 2 t "SymPy M, f only"
set logscale xy
set format y "%.0e"
set key top right
set xlabel "RHS evaluations"
set ylabel "relative error of the closing time"
set title "5. Work-precision: door closing time"
plot "{d}/wp_door_eomgen_dopri5.dat" u 1:2 w lp pt 7 t "eomgen Dopri5 (+ event on dense output)", \\
     "{d}/wp_door_eomgen_dop853.dat" u 1:2 w lp pt 9 t "eomgen Dop853 (+ event on dense output)", \\
     "{d}/wp_door_odeint_dense.dat" u 1:2 w lp pt 5 t "odeint runge_kutta_dopri5 (dense output)"
unset multiplot
"""
    with open(os.path.join(d, "plot.gp"), "w") as fh:
        fh.write(gp)
    subprocess.run(["gnuplot", os.path.join(d, "plot.gp")], check=True)
    return True


def report(command, mach, gen, rods, sym, ops, rhs, agree, comp, by, ref_check, mem, sympy_ok, runs, png_rel):
    L = []
    a = L.append
    load0, load1 = mach["load"], mach["load_end"]
    a(f"Measured by `{command}` on {mach['date']}, one run (every figure below is from it).")
    a("")
    a(f"Machine: {mach['cpu']}, {mach['cores']} cores, {mach['memory']}, {mach['os']} (Linux {mach['kernel']}); "
      f"{mach['compiler']}; GiNaC {mach['ginac']}, Eigen {mach['eigen']}, Boost {mach['boost']}, "
      f"Google Benchmark {mach['benchmark']}, Python {mach['python']}, SymPy {mach['sympy']}. "
      f"Load average (1 min) {load0[0]:.2f} at the start and {load1[0]:.2f} at the end: the machine was shared and "
      "wall times carry that noise (a process waiting for a core keeps its wall clock running), so the generation "
      "targets are judged on CPU time (user + system of the process; both sides single-threaded) with wall time "
      "beside it; each `eomgen generate` is the best of 3 runs (2 above n = 20), compile times are single runs, "
      "and right-hand-side times are the median of 10 repetitions of Google Benchmark's CPU time, the "
      "repetitions of all benchmarks in random order.")
    a("")
    a(f"![benchmarks]({png_rel})")
    a("")

    # Targets
    a("## Targets (issue 6), as ratios from this run")
    a("")
    a("| target | measured | met? |")
    a("|---|---|---|")
    for n in (8, 16):
        if n in gen and sympy_ok and n in sym and "total_s" in sym[n]:
            r = sym[n]["cpu_s"] / gen[n]["cpu_s"]
            rw = sym[n]["total_s"] / gen[n]["wall_s"]
            mf = gen[n]["phases"]["derive_s"] + gen[n]["phases"]["dynamics_emit_s"]
            a(f"| generation ≥ 100× faster than SymPy at n = {n} | CPU time: SymPy {fmt_s(sym[n]['cpu_s'])} s / "
              f"`eomgen generate` {fmt_s(gen[n]['cpu_s'])} s = **{r:.0f}×** (wall: {fmt_s(sym[n]['total_s'])} s / "
              f"{fmt_s(gen[n]['wall_s'])} s = {rw:.0f}×; eomgen's derive + emit of M and f only: {fmt_s(mf)} s, "
              f"{sym[n]['total_s'] / mf:.0f}×) | {verdict(r >= 100)} |")
        elif n in gen and sympy_ok and n in sym and sym[n].get("capped") and not sym[n].get("skipped"):
            # SymPy was stopped at the cap (wall clock): cap / eomgen's wall time is a lower bound of the ratio.
            r = sym[n]["cap_s"] / gen[n]["wall_s"]
            a(f"| generation ≥ 100× faster than SymPy at n = {n} | SymPy stopped at the cap of "
              f"{sym[n]['cap_s']:.0f} s wall; `eomgen generate` {fmt_s(gen[n]['wall_s'])} s wall "
              f"({fmt_s(gen[n]['cpu_s'])} s CPU): **> {r:.0f}×** wall to wall, a lower bound | "
              f"{verdict(r >= 100) + ' (lower bound)' if r >= 100 else '– (lower bound below 100×: raise --sympy-cap)'} |")
        else:
            a(f"| generation ≥ 100× faster than SymPy at n = {n} | not measured in this run | – |")
    big = max(gen)
    a(f"| n = 30 generated in under 10 s | n = {big}: {fmt_s(gen[big]['cpu_s'])} s CPU "
      f"({fmt_s(gen[big]['wall_s'])} s wall; derive {fmt_s(gen[big]['phases']['derive_s'])} s) | "
      f"{verdict(gen[big]['cpu_s'] < 10) if big >= 30 else '– (smoke)'} |")
    both = [n for n in sorted(ops) if "sympy" in ops[n]]
    if both:
        worst = max(ops[n]["eomgen"]["total"] / ops[n]["sympy"]["total"] for n in both)
        parts = ", ".join(f"n = {n}: {ops[n]['eomgen']['total']}/{ops[n]['sympy']['total']} = "
                          f"{ops[n]['eomgen']['total'] / ops[n]['sympy']['total']:.2f}" for n in both)
        a(f"| emitted operations ≤ SymPy's after cse | eomgen/SymPy {parts} | {verdict(worst <= 1)} |")
    else:
        a("| emitted operations ≤ SymPy's after cse | not measured in this run | – |")
    rhs_n = sorted(n for (k, w, n) in rhs if k == "rhs" and w == "sympy")
    if rhs_n:
        ratios = {n: rhs[("rhs", "eomgen", n)] / rhs[("rhs", "sympy", n)] for n in rhs_n}
        parts = ", ".join(f"n = {n}: {ratios[n]:.2f}" for n in rhs_n)
        met = [n for n in rhs_n if ratios[n] <= 0.5]
        v = verdict(len(met) == len(rhs_n)) if len(met) in (0, len(rhs_n)) else \
            f"**met** for n ≥ {min(met)}, **not met** for n = {', '.join(str(n) for n in rhs_n if n not in met)}"
        a(f"| right-hand side ≤ 0.5× SymPy-C's time | eomgen/SymPy {parts} | {v} |")
    else:
        a("| right-hand side ≤ 0.5× SymPy-C's time | not measured in this run | – |")
    if 20 in comp and "eomgen" in comp[20]:
        c = comp[20]["eomgen"]
        a(f"| n = 20 header compiles in ≤ 10 s at -O2 | {fmt_s(c['wall_s'])} s wall ({fmt_s(c['cpu_s'])} s CPU) | "
          f"{verdict(c['wall_s'] <= 10)} |")
    else:
        a("| n = 20 header compiles in ≤ 10 s at -O2 | not measured in this run (smoke) | – |")
    e = to_reach(by.get(("door", "eomgen_dopri5"), []), 1e-10)
    o = to_reach(by.get(("door", "odeint_dense"), []), 1e-10)
    if e and o:
        a(f"| RHS evaluations to reach 1e-10 on the door's closing time ≤ odeint's | eomgen {e['rhs_evals']} / "
          f"odeint {o['rhs_evals']} = {e['rhs_evals'] / o['rhs_evals']:.2f} | {verdict(e['rhs_evals'] <= o['rhs_evals'])} |")
    else:
        a("| RHS evaluations to reach 1e-10 on the door's closing time ≤ odeint's | not reached in this run | – |")
    a(f"| peak memory of generation at n = {mem['n']} (reported, no target) | {mem['kb'] / 1024:.0f} MiB "
      f"(SymPy at n = {mem.get('sympy_n', '–')}: {mem['sympy_kb'] / 1024:.0f} MiB) | – |" if mem.get("sympy_kb") else
      f"| peak memory of generation at n = {mem['n']} (reported, no target) | {mem['kb'] / 1024:.0f} MiB | – |")
    a("")

    # 1. generation
    a("## 1. Generation time")
    a("")
    a("The model is the n-link planar pendulum of point masses with absolute angles (`eomgen generate --family "
      "pendulum:n=N`; T written as Σ m_i/2 (ẋ_i² + ẏ_i²) with x_i, y_i sums of l_k sin/cos θ_k), the same in "
      "`bench/sympy_pendulum.py`. eomgen: wall time of the whole `eomgen generate` process, which writes the "
      "complete header (M, f, dynamics, energies, momenta, ∂L/∂q, conserved quantities, rhs, and the equations "
      "printed in its opening comment); derive, emit of the whole header, and emit of M and f alone (the "
      "`dynamics` function: what the SymPy side produces) from `bench/time_generate`, in-process; \"the equations "
      "comment\" is the part of the header's emit spent expanding and printing the Euler–Lagrange equations for its "
      "opening comment (kept only when under 4000 characters). SymPy: `LagrangesMethod(L, q).form_lagranges_equations()`, "
      "`mass_matrix`, `forcing`, dynamic symbols replaced by plain ones, `cse` over M and f together, `ccode` of "
      "every statement; the clock starts after `import sympy`.")
    a("")
    a("| n | eomgen generate wall [s] | CPU [s] | derive [s] | emit, whole header [s] | of which the equations "
      "comment [s] | emit, M and f only [s] | header [kB] | SymPy wall [s] | SymPy CPU [s] | of which "
      "LagrangesMethod [s] | cse [s] | ccode [s] | SymPy / eomgen generate, CPU | wall | "
      "SymPy / (derive + emit M, f) |")
    a("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for n in sorted(gen):
        g = gen[n]
        ph = g["phases"]
        mf = ph["derive_s"] + ph["dynamics_emit_s"]
        s = sym.get(n)
        row = f"| {n} | {fmt_s(g['wall_s'])} | {fmt_s(g['cpu_s'])} | {fmt_s(ph['derive_s'])} | " \
              f"{fmt_s(ph['emit_s'])} | {fmt_s(ph['comment_s'])} | {fmt_s(ph['dynamics_emit_s'])} | " \
              f"{ph['header_bytes'] / 1000:.0f} | "
        if s and "total_s" in s:
            row += f"{fmt_s(s['total_s'])} | {fmt_s(s['cpu_s'])} | {fmt_s(s['lagrange_s'])} | {fmt_s(s['cse_s'])} | " \
                   f"{fmt_s(s['ccode_s'])} | **{s['cpu_s'] / g['cpu_s']:.0f}×** | {s['total_s'] / g['wall_s']:.0f}× | " \
                   f"{s['total_s'] / mf:.0f}× |"
        elif s and s.get("capped"):
            row += f"> {s['cap_s']:.0f} (capped{', not run' if s.get('skipped') else ''}) | | | | | | > " \
                   f"{s['cap_s'] / g['wall_s']:.0f}× | > {s['cap_s'] / mf:.0f}× |"
        else:
            row += "not run | | | | | | | |"
        a(row)
    if rods:
        a("")
        a("Chain of uniform rods (`--family rods:n=N`), eomgen alone: " + "; ".join(
            f"n = {n}: {fmt_s(r['wall_s'])} s wall (derive {fmt_s(r['phases']['derive_s'])} s, emit "
            f"{fmt_s(r['phases']['emit_s'])} s), {r['phases']['dynamics_ops']['total']} operations in M and f"
            for n, r in sorted(rods.items())) + ".")
    if not sympy_ok:
        a("")
        a("SymPy was not found (`python3 -c 'import sympy'` failed), so its columns were not run; install SymPy "
          "1.14 (`pip install sympy==1.14`) and rerun.")
    a("")

    # 2. ops
    a("## 2. Operation counts in M and f")
    a("")
    a("Counted by one tokenizer, `bench/op_count.py`, over eomgen's `dynamics` body and over SymPy's cse'd "
      "statements alike: binary + and −, and unary −, are additions; `pow(x, k)` with an integer k counts k−1 "
      "multiplications (as eomgen writes powers); every other call (sin, cos, sqrt) is one call; divisions "
      "include constant ones such as SymPy's `(1.0/2.0)` and eomgen's `Scalar(1)/Scalar(2)`. "
      "The last column is eomgen's own OpCount (generator/codegen/cpp_emitter.hpp) for the same body: the "
      "tokenizer agrees with it.")
    a("")
    a("| n | eomgen + | × | ÷ | calls | **total** | SymPy + | × | ÷ | calls | **total** | eomgen / SymPy | "
      "eomgen OpCount |")
    a("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for n in sorted(ops):
        e = ops[n]["eomgen"]
        s = ops[n].get("sympy")
        srow = f"{s['add']} | {s['mul']} | {s['div']} | {s['call']} | **{s['total']}** | " \
               f"**{e['total'] / s['total']:.2f}** |" if s else "| | | | | |"
        a(f"| {n} | {e['add']} | {e['mul']} | {e['div']} | {e['call']} | **{e['total']}** | {srow} "
          f"{ops[n]['opcount']} |")
    a("")

    # 3. rhs
    a("## 3. Right-hand side time")
    a("")
    found = re.findall(r"n = (\d+): eomgen and SymPy right-hand sides agree to ([0-9.e+-]+)", agree or "")
    agree = ("they agree to " + ", ".join(f"{float(v):.0e} at n = {n}" for n, v in found) +
             " (largest relative difference over the 64 states)") if found else "no SymPy code compiled in"
    a("`bench/time_rhs` (Google Benchmark), one harness for both: fill M and f, then the same solve, the one "
      "the generated `rhs` uses (the header's unrolled L D Lᵀ up to n = 12, `eomgen::solve_mass_matrix` above; "
      "with its singularity check), q̈ into x'; "
      "SymPy's cse'd C is pasted into an inline function in the same translation unit, same compiler and flags "
      "(-O2 -DNDEBUG); 64 random states are cycled; median of 10 interleaved repetitions. Before timing, the two right-hand sides are compared at those "
      f"states: {agree}.")
    a("")
    a("| n | eomgen rhs [ns] | SymPy rhs [ns] | eomgen / SymPy | eomgen M, f only [ns] | SymPy M, f only [ns] | "
      "eomgen / SymPy (M, f) |")
    a("|---|---|---|---|---|---|---|")
    for n in sorted({k[2] for k in rhs}):
        er, sr = rhs.get(("rhs", "eomgen", n)), rhs.get(("rhs", "sympy", n))
        ed, sd = rhs.get(("dynamics", "eomgen", n)), rhs.get(("dynamics", "sympy", n))
        a(f"| {n} | {er:.0f} | {f'{sr:.0f}' if sr else '–'} | {f'**{er / sr:.2f}**' if sr else '–'} | {ed:.0f} | "
          f"{f'{sd:.0f}' if sd else '–'} | {f'{ed / sd:.2f}' if sd else '–'} |")
    a("")

    # 4. compile
    a("## 4. Compile time at -O2")
    a("")
    a("One translation unit per header, `g++ -std=c++17 -O2 -DNDEBUG -c`, with the whole class explicitly "
      "instantiated for double (eomgen: all ten functions and rhs; SymPy: its one dynamics function).")
    a("")
    a("| n | eomgen header [kB] | wall [s] | CPU [s] | SymPy header [kB] | wall [s] | CPU [s] |")
    a("|---|---|---|---|---|---|---|")
    for n in sorted(comp):
        e, s = comp[n].get("eomgen"), comp[n].get("sympy")
        a(f"| {n} | {e['bytes'] / 1000:.0f} | {fmt_s(e['wall_s'])} | {fmt_s(e['cpu_s'])} | " +
          (f"{s['bytes'] / 1000:.0f} | {fmt_s(s['wall_s'])} | {fmt_s(s['cpu_s'])} |" if s else "– | – | – |"))
    a("")

    # 5. work-precision
    a("## 5. Work-precision against Boost.Odeint")
    a("")
    a("`bench/time_integrators`: both integrators call the same generated `rhs`, atol = rtol, tolerances "
      "10^-4 … 10^-14 in steps of 10^(1/4); RHS evaluations counted by a wrapper around f. Door: released at "
      "rest at ψ = 0 with the model's defaults (θ = 0.0234 rad, w = 0.9 m), stopped where ψ falls through −π/2; "
      "error = relative error of the closing time against the closed form √(w/(3 g sin θ)) (√π/2) Γ(1/4)/Γ(3/4). "
      "eomgen: `eomgen::integrate` with a terminal event (located on the dense output); odeint: "
      "`make_dense_output(atol, rtol, runge_kutta_dopri5)` stepped until ψ crosses, the crossing located on "
      "`calc_state` with the same Brent root finder; odeint's first step 1e-3 (eomgen chooses its own). "
      "Pendulum (models/pendulum_5_20.toml, θ = 0.5, φ = −0.3, θ̇ = 0.5, φ̇ = 2, t = 0 … 10): error = max-norm "
      f"of the final state against Runge–Kutta–Fehlberg 7(8) in long double at 1e-19 ({ref_check}). "
      "A cell is the cheapest run from which on every tighter tolerance also reaches the error (a lucky "
      "cancellation at a loose tolerance does not count): RHS evaluations, and the time of that run.")
    a("")
    methods = [("door", "eomgen_dopri5"), ("door", "odeint_dense"), ("pendulum", "eomgen_dopri5"),
               ("pendulum", "odeint_dense"), ("pendulum", "odeint_controlled")]
    a("| error reached | " + " | ".join(f"{p}: {m} evals (µs)" for p, m in methods) + " | door: eomgen / odeint evals |")
    a("|---|" + "---|" * (len(methods) + 1))
    for t in TARGET_ERRORS:
        cells = []
        for key in methods:
            r = to_reach(by.get(key, []), t)
            cells.append(f"{r['rhs_evals']} ({r['seconds'] * 1e6:.0f})" if r else "not reached")
        e, o = to_reach(by.get(methods[0], []), t), to_reach(by.get(methods[1], []), t)
        ratio = f"{e['rhs_evals'] / o['rhs_evals']:.2f}" if e and o else "–"
        a(f"| {t:.0e} | " + " | ".join(cells) + f" | {ratio} |")
    a("")

    L.extend(high_order_md(by))
    a("")

    # 6. memory
    a("## 6. Peak memory of generation")
    a("")
    a(f"Peak resident set size of `eomgen generate --family pendulum:n={mem['n']}` (getrusage of the process): "
      f"**{mem['kb'] / 1024:.0f} MiB**." + (f" SymPy's script at n = {mem['sympy_n']}: {mem['sympy_kb'] / 1024:.0f} MiB."
                                              if mem.get("sympy_kb") else ""))

    # 7. eomgen run
    if runs:
        med = lambda xs: sorted(xs)[len(xs) // 2]  # noqa: E731
        a("")
        a("## 7. `eomgen run`: first run, cached re-run (issue 10)")
        a("")
        a("`eomgen run MODEL --t-end 5 --quiet` with an empty `XDG_CACHE_HOME` (the first run derives the model, "
          "compiles its functions with `c++ -O2` into a shared object and integrates it with the driver compiled into "
          "eomgen), then the same command again (cached: no derivation, no compiler), and `eomgen-sim` on the same "
          "model built in (the integration and a process start; its models are tables too, with eomgen run's driver). Medians of "
          f"{len(runs['models'][0]['first'])} (each first run with its own empty cache). Targets: first run of a "
          "2-coordinate model ≤ 5 s; a cached re-run ≤ 0.1 s beyond the integration.")
        a("")
        a("| model | first run wall [s] | CPU [s] | cached re-run wall [s] | eomgen-sim wall [s] | cached − eomgen-sim [s] |")
        a("|---|---|---|---|---|---|")
        for r in runs["models"]:
            fw, fc = med([x["wall_s"] for x in r["first"]]), med([x["cpu_s"] for x in r["first"]])
            cw = med([x["wall_s"] for x in r["cached"]])
            sw = med([x["wall_s"] for x in r["sim"]]) if r["sim"] else None
            a(f"| {r['model']} | **{fw:.2f}** | {fc:.2f} | {cw:.3f} | " +
              (f"{sw:.3f} | **{cw - sw:+.3f}** |" if sw is not None else "– | – |"))
        lg = runs.get("long")
        if lg:
            t, c = med(lg["table"]), med(lg["compiled_in"])
            a("")
            a(f"A long integration, models/pendulum_5_20.toml to t = {lg['t_end']:g} ({lg['rhs'].replace('steps:', '').strip()}), "
              f"CPU medians: through the shared object's table (`eomgen run`, cached) {t:.3f} s, through the table linked into `eomgen-sim` {c:.3f} s: "
              f"**{t / c:.2f}×**; " + ("the same printed result." if lg["same_result"] else "the printed results differ."))
    return "\n".join(L) + "\n"


NOTES_TEMPLATE = """# Benchmarks: eomgen against SymPy and Boost.Odeint

`bash bench/run.sh` measures everything below in one run and rewrites the part between the MEASURED markers
(and `docs/benchmarks.png`); `bash bench/run.sh --smoke` runs the same pipeline at tiny sizes in seconds.

{begin}
{end}
"""


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build-dir", required=True)
    ap.add_argument("--smoke", action="store_true")
    ap.add_argument("--no-build", action="store_true")
    ap.add_argument("--sympy-cap", type=float, default=900.0)
    ap.add_argument("--peers-only", action="store_true",
                    help="measure only section 8 (MuJoCo, SUNDIALS) and rewrite only its part of the page")
    ap.add_argument("--scale-only", action="store_true",
                    help="measure only section 9 (generation at scale, issue 37) and rewrite only its part of the page")
    ap.add_argument("--fit-only", action="store_true",
                    help="measure only section 10 (eomgen fit's coverage and time, issue 34) and rewrite only its part")
    ap.add_argument("--bicycle-only", action="store_true",
                    help="measure only section 11 (the Whipple bicycle, issue 35) and rewrite only its part")
    ap.add_argument("--animation-only", action="store_true",
                    help="measure only section 12 (eomgen run --animate, issue 33) and rewrite only its part")
    ap.add_argument("--python-only", action="store_true",
                    help="measure only section 13 (the Python module, issue 32) and rewrite only its part")
    ap.add_argument("--interpreter-only", action="store_true",
                    help="measure only section 14 (eomgen run --interpret against the compiled run) and rewrite only its part")
    ap.add_argument("--out-md")
    ap.add_argument("--out-png")
    ap.add_argument("--render-only", metavar="RESULTS_JSON",
                    help="rewrite the report and plot from a finished run's results.json, measuring nothing")
    ap.add_argument("--only", choices=["integrators"],
                    help="run only bench/time_integrators and print its sections (5, 5b) on stdout; docs/ untouched")
    args = ap.parse_args()
    args.build_dir = os.path.abspath(args.build_dir)
    if args.only == "integrators":
        with open(os.path.join(args.build_dir, "bench", "bench_config.json")) as fh:
            cfg = json.load(fh)
        mach = machine(cfg)
        by, ref_check = integrators(cfg, args.smoke)
        print(f"Measured by `python3 bench/bench.py --only integrators{' --smoke' if args.smoke else ''}` on "
              f"{mach['date']}: {mach['cpu']}, {mach['cores']} cores, {mach['compiler']}; load average (1 min) "
              f"{mach['load'][0]:.2f} at the start, {os.getloadavg()[0]:.2f} at the end.\n")
        print("\n".join(high_order_md(by)))
        return
    if args.render_only:
        with open(args.render_only) as fh:
            results = json.load(fh)
        work = os.path.dirname(os.path.abspath(args.render_only))
        out_md = args.out_md or os.path.join(ROOT, "docs", "benchmarks.md")
        if "generation" in results:
            render(results, work, out_md, args.out_png or os.path.join(os.path.dirname(out_md), "benchmarks.png"))
        elif "scale" in results:
            render_scale(results, out_md)
        elif "fit" in results:
            render_fit(results, out_md)
        elif "bicycle" in results:
            render_bicycle(results, out_md)
        elif "animation" in results:
            render_animation(results, out_md)
        elif "python" in results:
            render_python(results, out_md)
        elif "interpreter" in results:
            render_interpreter(results, out_md)
        else:
            render_peers(results, out_md)
        return
    with open(os.path.join(args.build_dir, "bench", "bench_config.json")) as fh:
        cfg = json.load(fh)
    work = os.path.join(args.build_dir, "bench_smoke" if args.smoke else
                        "bench_peers" if args.peers_only else "bench_scale" if args.scale_only else
                        "bench_fit" if args.fit_only else "bench_bicycle" if args.bicycle_only else
                        "bench_animation" if args.animation_only else "bench_python" if args.python_only else
                        "bench_interpreter" if args.interpreter_only else
                        "bench_work")
    if os.path.isdir(work):
        shutil.rmtree(work)
    os.makedirs(work)
    out_md = args.out_md or (os.path.join(work, "benchmarks.md") if args.smoke else os.path.join(ROOT, "docs",
                                                                                                  "benchmarks.md"))
    out_png = args.out_png or os.path.join(os.path.dirname(out_md), "benchmarks.png")

    command = "bash bench/run.sh" + (" --smoke" if args.smoke else "") + (" --no-build" if args.no_build else "") + \
        (" --peers-only" if args.peers_only else "") + (" --scale-only" if args.scale_only else "") + \
        (" --fit-only" if args.fit_only else "") + (" --bicycle-only" if args.bicycle_only else "") + (" --animation-only" if args.animation_only else "") + (" --python-only" if args.python_only else "") + (" --interpreter-only" if args.interpreter_only else "") + (f" --sympy-cap {args.sympy_cap:g}" if args.sympy_cap != 900 else "")
    if args.peers_only:
        results = {"command": command, "date": utc_now(), "peers": peers.measure(cfg, args.build_dir, args.smoke, log)}
        with open(os.path.join(work, "results_peers.json"), "w") as fh:
            json.dump(results, fh, indent=1)
        render_peers(results, out_md)
        return

    # One section alone: measured, kept as results_<key>.json, and only its part of the page rewritten.
    alone = {"fit": (args.fit_only, lambda: fit.measure(cfg, work, args.smoke, log), render_fit),
             "bicycle": (args.bicycle_only, lambda: bicycle.measure(cfg, work, args.smoke, log, args.sympy_cap),
                         render_bicycle),
             "animation": (args.animation_only, lambda: animation.measure(cfg, work, args.smoke, log),
                           render_animation),
             "python": (args.python_only, lambda: python_api.measure(cfg, work, args.smoke, log), render_python),
             "interpreter": (args.interpreter_only, lambda: interpreter.measure(cfg, work, args.smoke, log),
                             render_interpreter)}
    for key, (selected, measure, render_section) in alone.items():
        if not selected:
            continue
        mach = machine(cfg)
        results = {"command": command, "date": mach["date"], "machine": mach, key: measure()}
        results["machine"]["load_end"] = os.getloadavg()
        with open(os.path.join(work, f"results_{key}.json"), "w") as fh:
            json.dump(results, fh, indent=1)
        render_section(results, out_md)
        return

    if args.scale_only:
        mach = machine(cfg)
        sym = sympy_runs if have_sympy() else None
        results = {"command": command, "date": mach["date"], "machine": mach,
                   "scale": scale.measure(cfg, work, args.smoke, log, sym, min(args.sympy_cap, 300.0))}
        results["machine"]["load_end"] = os.getloadavg()
        with open(os.path.join(work, "results_scale.json"), "w") as fh:
            json.dump(results, fh, indent=1)
        render_scale(results, out_md)
        return

    if args.smoke:
        gen_sizes, sym_sizes, rhs_sizes, comp_sizes, rod_sizes, mem_n = [2, 3], [2], [2], [2], [2], 3
        reps = lambda n: 1  # noqa: E731
    else:
        gen_sizes, sym_sizes = [2, 4, 8, 12, 16, 20, 24, 30], [2, 4, 8, 12, 16, 20]
        rhs_sizes, comp_sizes, rod_sizes, mem_n = [2, 4, 8, 12, 16, 20], [2, 4, 8, 12, 16, 20], [8, 16, 30], 30
        reps = lambda n: 3 if n <= 20 else 2  # noqa: E731

    mach = machine(cfg)
    sympy_ok = have_sympy()
    if not sympy_ok:
        log("SymPy not found (python3 -c 'import sympy' failed): skipping the SymPy parts")

    log("1. generation")
    gen = generation(cfg, work, "pendulum", gen_sizes, reps)
    rods = generation(cfg, work, "rods", rod_sizes, lambda n: 1)
    sym = sympy_runs(work, sym_sizes, args.sympy_cap) if sympy_ok else {}

    log("2. operation counts")
    ops = {}
    for n in gen_sizes:
        e = op_count.count_file(gen[n]["header"], "dynamics")
        ops[n] = {"eomgen": e, "opcount": gen[n]["phases"]["dynamics_ops"]["total"]}
        if e["total"] != ops[n]["opcount"]:
            log(f"warning: op_count.py ({e['total']}) and OpCount ({ops[n]['opcount']}) differ at n={n}")
        if n in sym and "header" in sym[n]:
            ops[n]["sympy"] = op_count.count_file(sym[n]["header"])

    log("3. right-hand side")
    sizes = [n for n in rhs_sizes if n in gen]
    rhs, agree = rhs_times(cfg, args, work, sizes, sym)

    log("4. compile time")
    comp = compile_times(cfg, work, gen, sym, comp_sizes)

    log("5. work-precision")
    by, ref_check = integrators(cfg, args.smoke)

    log("6. peak memory")
    mem = {"n": mem_n, "kb": peak_rss_kb([cfg["eomgen"], "generate", "--family", f"pendulum:n={mem_n}", "-o",
                                          os.path.join(work, "memory")])}
    sym_done = [n for n in sym if "peak_rss_kb" in sym[n]]
    if sym_done:
        mem["sympy_n"] = max(sym_done)
        mem["sympy_kb"] = sym[max(sym_done)]["peak_rss_kb"]
    log("7. eomgen run")
    runs = run_times(cfg, work, args.smoke)
    mach["load_end"] = os.getloadavg()
    peer_results = peers.measure(cfg, args.build_dir, args.smoke, log)
    log("9. generation at scale")
    scale_results = scale.measure(cfg, work, args.smoke, log, sympy_runs if sympy_ok else None,
                                  min(args.sympy_cap, 300.0))
    log("10. fitting")
    fit_results = fit.measure(cfg, work, args.smoke, log)
    log("11. bicycle")
    bicycle_results = bicycle.measure(cfg, work, args.smoke, log, args.sympy_cap)
    log("12. animation")
    animation_results = animation.measure(cfg, work, args.smoke, log)
    log("13. Python module")
    python_results = python_api.measure(cfg, work, args.smoke, log)
    log("14. interpreter")
    interpreter_results = interpreter.measure(cfg, work, args.smoke, log)
    results = {"command": command, "machine": mach, "sympy_ok": sympy_ok, "agree": agree, "ref_check": ref_check,
               "generation": {str(k): v for k, v in gen.items()}, "rods": {str(k): v for k, v in rods.items()},
               "sympy": {str(k): v for k, v in sym.items()}, "ops": {str(k): v for k, v in ops.items()},
               "rhs": {"/".join(map(str, k)): v for k, v in rhs.items()},
               "compile": {str(k): v for k, v in comp.items()},
               "integrators": {"/".join(k): v for k, v in by.items()}, "memory": mem, "run": runs,
               "date": mach["date"], "peers": peer_results, "scale": scale_results, "fit": fit_results,
               "bicycle": bicycle_results, "animation": animation_results, "python": python_results,
               "interpreter": interpreter_results}
    with open(os.path.join(work, "results.json"), "w") as fh:
        json.dump(results, fh, indent=1)
    render(results, work, out_md, out_png)


def render(results, work, out_md, out_png):
    """Writes the measured part of out_md and the plot from one run's results (results.json)."""
    ints = lambda d: {int(k): v for k, v in d.items()}  # noqa: E731
    gen, rods, sym = ints(results["generation"]), ints(results["rods"]), ints(results["sympy"])
    ops, comp = ints(results["ops"]), ints(results["compile"])
    rhs = {}
    for k, v in results["rhs"].items():
        kind, who, n = k.split("/")
        rhs[(kind, who, int(n))] = v
    by = {tuple(k.split("/")): v for k, v in results["integrators"].items()}
    os.makedirs(os.path.dirname(out_md), exist_ok=True)
    have_png = write_plot(work, out_png, gen, sym, ops, rhs, by)
    text = report(results.get("command", "bash bench/run.sh"), results["machine"], gen, rods, sym, ops, rhs, results["agree"], comp, by, results["ref_check"],
                  results["memory"], results["sympy_ok"], results.get("run"),
                  os.path.relpath(out_png, os.path.dirname(out_md)) if have_png else "(no plot: gnuplot missing)")
    splice(out_md, BEGIN, END, text)
    log(f"wrote {out_md}" + (f" and {out_png}" if have_png else ""))
    if "peers" in results:
        render_peers(results, out_md)
    if "scale" in results:
        render_scale(results, out_md)
    if "fit" in results:
        render_fit(results, out_md)
    if "bicycle" in results:
        render_bicycle(results, out_md)
    if "animation" in results:
        render_animation(results, out_md)
    if "python" in results:
        render_python(results, out_md)
    if "interpreter" in results:
        render_interpreter(results, out_md)


def render_scale(results, out_md):
    """Writes section 9 (generation at scale) between its own markers."""
    m = results["machine"]
    line = (f"eomgen at commit {m.get('commit', '?')}. "
            f"Machine: {m['cpu']}, {m['cores']} cores; {m['compiler']}; GiNaC {m['ginac']}; SymPy {m['sympy']}. "
            f"Load average (1 min) {m['load'][0]:.2f} at the start, {m.get('load_end', m['load'])[0]:.2f} at the end.")
    splice(out_md, BEGIN_SCALE, END_SCALE, scale.render(results["scale"], results["command"], results["date"], line))
    log(f"wrote section 9 of {out_md}")


def render_fit(results, out_md):
    """Writes section 10 (eomgen fit) between its own markers."""
    m = results["machine"]
    line = (f"eomgen at commit {m.get('commit', '?')}. Machine: {m['cpu']}, {m['cores']} cores; {m['compiler']}. "
            f"Load average (1 min) {m['load'][0]:.2f} at the start, {m.get('load_end', m['load'])[0]:.2f} at the end.")
    splice(out_md, BEGIN_FIT, END_FIT, fit.render(results["fit"], results["command"], results["date"], line))
    log(f"wrote section 10 of {out_md}")


def render_bicycle(results, out_md):
    """Writes section 11 (the Whipple bicycle) between its own markers."""
    m = results["machine"]
    line = (f"eomgen at commit {m.get('commit', '?')}. Machine: {m['cpu']}, {m['cores']} cores; {m['compiler']}; "
            f"SymPy {m.get('sympy', '?')}. "
            f"Load average (1 min) {m['load'][0]:.2f} at the start, {m.get('load_end', m['load'])[0]:.2f} at the end.")
    splice(out_md, BEGIN_BICYCLE, END_BICYCLE, bicycle.render(results["bicycle"], results["command"], results["date"], line))
    log(f"wrote section 11 of {out_md}")


def machine_line(results):
    """The commit, the machine and its load during a section's run, as one sentence of its heading."""
    m = results["machine"]
    return (f"eomgen at commit {m.get('commit', '?')}. Machine: {m['cpu']}, {m['cores']} cores; {m['compiler']}. "
            f"Load average (1 min) {m['load'][0]:.2f} at the start, {m.get('load_end', m['load'])[0]:.2f} at the end.")


def render_animation(results, out_md):
    """Writes section 12 (eomgen run --animate) between its own markers."""
    splice(out_md, BEGIN_ANIMATION, END_ANIMATION,
           animation.render(results["animation"], results["command"], results["date"], machine_line(results)))
    log(f"wrote section 12 of {out_md}")


def render_python(results, out_md):
    """Writes section 13 (the Python module) between its own markers."""
    splice(out_md, BEGIN_PYTHON, END_PYTHON,
           python_api.render(results["python"], results["command"], results["date"], machine_line(results)))
    log(f"wrote section 13 of {out_md}")


def render_interpreter(results, out_md):
    """Writes section 14 (eomgen run --interpret) between its own markers."""
    splice(out_md, BEGIN_INTERPRETER, END_INTERPRETER,
           interpreter.render(results["interpreter"], results["command"], results["date"], machine_line(results)))
    log(f"wrote section 14 of {out_md}")


def render_peers(results, out_md):
    """Writes section 8 (MuJoCo and SUNDIALS) between its own markers, after the main measured part."""
    splice(out_md, BEGIN_PEERS, END_PEERS,
           peers.render(results["peers"], results.get("command", "bash bench/run.sh"), results.get("date", "?")))
    log(f"wrote section 8 of {out_md}")


def splice(out_md, begin, end, text):
    """Replaces what lies between the markers begin and end in out_md (adding them, after the main measured part
    or at the end, where they are missing), keeping the rest of the file; atomically."""
    os.makedirs(os.path.dirname(os.path.abspath(out_md)), exist_ok=True)
    old = open(out_md).read() if os.path.exists(out_md) else NOTES_TEMPLATE.format(begin=BEGIN, end=END)
    if begin not in old or end not in old:
        block = begin + "\n" + end + "\n"
        if begin != BEGIN and END in old:
            head, tail = old.split(END, 1)
            old = head + END + "\n\n" + block + tail.lstrip("\n")
        else:
            old = old.rstrip("\n") + "\n\n" + block
    head, rest = old.split(begin, 1)
    tail = rest.split(end, 1)[1]
    with open(out_md + ".tmp", "w") as fh:
        fh.write(head + begin + "\n" + text + end + tail)
    os.replace(out_md + ".tmp", out_md)


def utc_now():
    return datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")

if __name__ == "__main__":
    main()
