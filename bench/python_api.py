"""Section 13 of docs/benchmarks.md (issue 32): the Python module `import eomgen` (python/, docs/python.md).
Called by bench.py (in the full run, and alone with --python-only); the page's part between the PYTHON markers is
written by render() from measure()'s results.

Measured, each in fresh python3 processes (the module as built, PYTHONPATH from bench_config.json):
- `import eomgen`, and `eomgen.load` of a model whose code is in the cache with its first `rhs` call (which loads
  the shared object): the best of several processes;
- the first `simulate` of a 2-coordinate model (the double pendulum, 10 s) with an empty cache (derive, compile,
  integrate), beside `eomgen run` of the same model with an empty cache of its own;
- `Model.rhs` over N random states of the double pendulum (one call, the loop in C++ without the GIL) against the
  same loop written in C++ on the same shared object (bench/time_table_rhs.cpp), best of 5 each; the two results
  must be equal to the bit;
- the n-link pendulum (n = 2, 8, 16) derived, compiled and integrated to 10 s from Python, start to finish, against
  SymPy + lambdify + SciPy (bench/sympy_python_pendulum.py; PyDy is not in Debian), each in a fresh process.
"""
import json
import os
import subprocess
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
DOUBLE = os.path.join(ROOT, "examples", "double_pendulum.toml")
DOOR = os.path.join(ROOT, "models", "door.toml")


def run_python(cfg, code, cache, *args):
    """Runs `code` in a fresh python3 with the built module and `cache` as XDG_CACHE_HOME; its stdout as JSON."""
    env = dict(os.environ, PYTHONPATH=cfg["python_path"], XDG_CACHE_HOME=cache, PYTHONDONTWRITEBYTECODE="1")
    p = subprocess.run([cfg["python3"], "-c", code, *args], env=env, capture_output=True, text=True, check=True)
    return json.loads(p.stdout.strip().splitlines()[-1])


IMPORT_AND_LOAD = """
import json, sys, time
t0 = time.perf_counter()
import eomgen
t1 = time.perf_counter()
m = eomgen.load(sys.argv[1])
t2 = time.perf_counter()
m.rhs(0.0, m.initial_state)
t3 = time.perf_counter()
print(json.dumps({"import": t1 - t0, "load": t2 - t1, "load_first_rhs": t3 - t1}))
"""

FIRST_SIMULATE = """
import json, sys, time
import eomgen
t0 = time.perf_counter()
m = eomgen.load(sys.argv[1])
sol = m.simulate(10.0)
t1 = time.perf_counter()
print(json.dumps({"first_simulate": t1 - t0, "samples": len(sol.t), "drift": sol.max_drift}))
"""

RHS = """
import json, sys, time
import numpy as np
import eomgen
m = eomgen.load(sys.argv[1])
n, repeats = int(sys.argv[2]), int(sys.argv[3])
x = np.random.default_rng(1).uniform(-2.0, 2.0, size=(n, 2 * len(m.coordinates)))
x.tofile(sys.argv[4])
timings = {}
for interpret in (False, True):
    m.rhs(0.0, x[:2], interpret=interpret)  # compiled, loaded or recorded before the clock starts
    best = float("inf")
    for _ in range(repeats):
        t0 = time.perf_counter()
        xdot = m.rhs(0.0, x, interpret=interpret)
        best = min(best, time.perf_counter() - t0)
    timings[interpret] = best
    if not interpret:
        xdot.tofile(sys.argv[5])
        compiled = xdot
print(json.dumps({"ns_per_state": timings[False] * 1e9 / n, "interpreted_ns_per_state": timings[True] * 1e9 / n,
                  "interpreted_difference": float(np.max(np.abs(xdot - compiled))), "shared_object": m.shared_object}))
"""


PENDULUM = """
import json, sys, time
start = time.perf_counter()
import eomgen
n, t_end, rtol, atol = int(sys.argv[1]), float(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4])
interpret = len(sys.argv) > 5 and sys.argv[5] == "interpret"
m = eomgen.family(f"pendulum:n={n}")
init = {f"theta{i}": (0.1 if i == 1 else 0.0) for i in range(1, n + 1)}
sol = m.simulate(t_end, rtol=rtol, atol=atol, samples=1, init=init, interpret=interpret)
print(json.dumps({"total_s": time.perf_counter() - start, "x_end": [float(v) for v in sol.x[-1]]}))
"""


def against_sympy(cfg, work, sizes, cap, log):
    """The n-link pendulum derived, compiled and integrated to 10 s from Python: eomgen (an empty cache, so that the
    compiler runs) against SymPy + lambdify + SciPy (bench/sympy_python_pendulum.py), each in a fresh process."""
    rows = {}
    for n in sizes:
        cache = tempfile.mkdtemp(prefix=f"cache-n{n}-", dir=work)
        e = run_python(cfg, PENDULUM, cache, str(n), "10", "1e-8", "1e-10")
        again = run_python(cfg, PENDULUM, cache, str(n), "10", "1e-8", "1e-10")  # the compiled model from the cache
        # The interpreter (simulate(interpret=True)): derived and recorded as tapes, nothing compiled, no cache used.
        fresh = tempfile.mkdtemp(prefix=f"cache-n{n}-interpreted-", dir=work)
        i = run_python(cfg, PENDULUM, fresh, str(n), "10", "1e-8", "1e-10", "interpret")
        row = {"eomgen_s": e["total_s"], "eomgen_cached_s": again["total_s"], "eomgen_interpreted_s": i["total_s"],
               "interpreted_difference": max(abs(a - b) for a, b in zip(i["x_end"], e["x_end"]))}
        log(f"13. Python module: n = {n}: eomgen {e['total_s']:.2f} s; SymPy (capped at {cap:.0f} s) ...")
        try:
            p = subprocess.run([cfg["python3"], os.path.join(HERE, "sympy_python_pendulum.py"), str(n), "10", "1e-8",
                                "1e-10"], capture_output=True, text=True, timeout=cap, check=True,
                               env=dict(os.environ, PYTHONDONTWRITEBYTECODE="1"))
            s = json.loads(p.stdout.strip().splitlines()[-1])
            row.update(sympy_s=s["total_s"], sympy_derive_s=s["derive_s"], sympy_lambdify_s=s["lambdify_s"],
                       sympy_integrate_s=s["integrate_s"], sympy_version=s["sympy"], ratio=s["total_s"] / e["total_s"],
                       ratio_cached=s["total_s"] / again["total_s"], ratio_interpreted=s["total_s"] / i["total_s"],
                       max_difference=max(abs(a - b) for a, b in zip(s["x_end"], e["x_end"])))
        except subprocess.TimeoutExpired:
            row.update(sympy_capped=cap)
        except subprocess.CalledProcessError as err:
            row.update(sympy_failed=(err.stderr or "").strip().splitlines()[-1:] or ["?"])
        rows[str(n)] = row
    return rows


def measure(cfg, work, smoke, log):
    if "python3" not in cfg:
        log("13. Python module: not built (no python3-dev or pybind11-dev at configure time); skipped")
        return {"skipped": "the Python module is not built"}
    n = 10_000 if smoke else 1_000_000
    processes = 1 if smoke else 5
    repeats = 1 if smoke else 5
    out = {"n_states": n, "processes": processes, "repeats": repeats}
    cache = tempfile.mkdtemp(prefix="cache-", dir=work)

    log("13. Python module: first simulate of the double pendulum with an empty cache")
    out["first_simulate"] = run_python(cfg, FIRST_SIMULATE, cache, DOUBLE)
    run_cache = tempfile.mkdtemp(prefix="cache-run-", dir=work)
    t0 = time.perf_counter()
    subprocess.run([cfg["eomgen"], "run", DOUBLE, "--quiet", "--t-end", "10"], check=True, stdout=subprocess.DEVNULL,
                   env=dict(os.environ, XDG_CACHE_HOME=run_cache))
    out["eomgen_run_first"] = time.perf_counter() - t0

    log("13. Python module: import and load of a cached model")
    run_python(cfg, IMPORT_AND_LOAD, cache, DOOR)  # fills the cache for the door
    loads = [run_python(cfg, IMPORT_AND_LOAD, cache, DOOR) for _ in range(processes)]
    out["import"] = min(r["import"] for r in loads)
    out["load"] = min(r["load"] for r in loads)
    out["load_first_rhs"] = min(r["load_first_rhs"] for r in loads)

    log(f"13. Python module: Model.rhs over {n} states against the loop in C++")
    states, py_out, cpp_out = (os.path.join(work, f) for f in ("states.bin", "rhs_python.bin", "rhs_cpp.bin"))
    py = run_python(cfg, RHS, cache, DOUBLE, str(n), str(repeats), states, py_out)
    p = subprocess.run([cfg["time_table_rhs"], py["shared_object"], states, str(n), str(repeats), cpp_out],
                       check=True, capture_output=True, text=True)
    cpp_ns = float(p.stdout.split()[0])
    out["sympy"] = against_sympy(cfg, work, [2] if smoke else [2, 8, 16], 60 if smoke else 900, log)
    out["rhs_python_ns"] = py["ns_per_state"]
    out["rhs_cpp_ns"] = cpp_ns
    out["rhs_ratio"] = py["ns_per_state"] / cpp_ns
    out["rhs_interpreted_ns"] = py["interpreted_ns_per_state"]
    out["rhs_interpreted_difference"] = py["interpreted_difference"]
    with open(py_out, "rb") as a, open(cpp_out, "rb") as b:
        out["results_equal"] = a.read() == b.read()
    if not out["results_equal"]:
        raise RuntimeError("Model.rhs and the C++ loop give different results (" + py_out + ", " + cpp_out + ")")
    return out


def render(r, command, date, machine_line):
    lines = ["## 13. The Python module (issue 32)", ""]
    if "skipped" in r:
        return "\n".join(lines + [f"Not measured: {r['skipped']}.", ""]) + "\n"
    f = r["first_simulate"]
    lines += [
        f"Measured by `{command}` on {date}. {machine_line}",
        "",
        "bench/python_api.py: each figure in fresh `python3` processes with the module as built (best of "
        f"{r['processes']} processes for import and load); `Model.rhs` over {r['n_states']:,} random states of the "
        f"double pendulum (examples/double_pendulum.toml) in one call, best of {r['repeats']}, against the same loop "
        "in C++ on the same shared object (bench/time_table_rhs.cpp); the two results are equal to the bit: "
        f"{'yes' if r['results_equal'] else 'NO'}.",
        "",
        "| measured | value | target (issue 32) | met? |",
        "|---|---|---|---|",
        f"| `import eomgen` | {r['import'] * 1e3:.0f} ms | – | – |",
        f"| `eomgen.load` of the door, parse only | {r['load'] * 1e3:.1f} ms | – | – |",
        f"| `eomgen.load` of the door + first `rhs` (the shared object loaded from the cache) | "
        f"{r['load_first_rhs'] * 1e3:.1f} ms | ≤ 50 ms | **{'met' if r['load_first_rhs'] <= 0.05 else 'not met'}** |",
        f"| first `simulate` of the double pendulum, empty cache (derive, compile, 10 s of motion) | "
        f"{f['first_simulate']:.2f} s (`eomgen run`, empty cache: {r['eomgen_run_first']:.2f} s) | ≤ 5 s | "
        f"**{'met' if f['first_simulate'] <= 5 else 'not met'}** |",
        f"| `Model.rhs` per state, against the loop in C++ | {r['rhs_python_ns']:.1f} ns against "
        f"{r['rhs_cpp_ns']:.1f} ns: {r['rhs_ratio']:.3f}× | ≤ 1.2× | "
        f"**{'met' if r['rhs_ratio'] <= 1.2 else 'not met'}** |",
        f"| `Model.rhs(..., interpret=True)` per state (the interpreter's tapes; largest difference from the compiled "
        f"rows {r['rhs_interpreted_difference']:.1e}) | {r['rhs_interpreted_ns']:.1f} ns: "
        f"{r['rhs_interpreted_ns'] / r['rhs_python_ns']:.2f}× the compiled | – | – |",
        "",
        "The n-link pendulum from Python, start to finish (derive, generate or lambdify, compile, integrate to 10 s "
        "from theta1 = 0.1 rad with rtol 1e-8 and atol 1e-10; wall time of a fresh process, imports included): "
        "`eomgen.family(\"pendulum:n=N\").simulate(...)` with an empty cache, against SymPy's LagrangesMethod, "
        "`lambdify` (PyDy's default backend; PyDy is not packaged in Debian) and SciPy's `solve_ivp` (RK45, "
        "Dormand–Prince as eomgen's dopri5), bench/sympy_python_pendulum.py. eomgen three ways: compiled on a first "
        "run (the C++ compiler runs), compiled from the cache (every run after the first), and interpreted "
        "(`simulate(..., interpret=True)`: derived and recorded as tapes, nothing compiled, docs/interpreter.md). "
        "The last columns are the largest differences of the final states: SymPy's and the interpreted run's against "
        "the compiled run's.",
        "",
        "| n | eomgen compiled, first run [s] | eomgen compiled, cached [s] | eomgen interpreted [s] | SymPy + lambdify + "
        "SciPy [s] (derive, lambdify, integrate) | SymPy / eomgen first compiled | SymPy / eomgen cached | "
        "SymPy / eomgen interpreted | SymPy's final state differs by | interpreted differs by |",
        "|---|---|---|---|---|---|---|---|---|---|"]
    for n, row in r["sympy"].items():
        head = f"| {n} | {row['eomgen_s']:.2f} | {row['eomgen_cached_s']:.2f} | {row['eomgen_interpreted_s']:.2f} | "
        tail = f"{row['interpreted_difference']:.1e} |"
        if "sympy_s" in row:
            sym = (f"{row['sympy_s']:.2f} ({row['sympy_derive_s']:.2f}, {row['sympy_lambdify_s']:.2f}, "
                   f"{row['sympy_integrate_s']:.2f})")
            lines.append(head + f"{sym} | **{row['ratio']:.1f}×** | **{row['ratio_cached']:.1f}×** | "
                         f"**{row['ratio_interpreted']:.1f}×** | {row['max_difference']:.1e} | " + tail)
        elif "sympy_capped" in row:
            cap = row["sympy_capped"]
            lines.append(head + f"> {cap:.0f} (stopped) | > {cap / row['eomgen_s']:.0f}× | > "
                         f"{cap / row['eomgen_cached_s']:.0f}× | > {cap / row['eomgen_interpreted_s']:.0f}× | | " + tail)
        else:
            lines.append(head + f"failed: {' '.join(row['sympy_failed'])} | | | | | " + tail)
    eight = r["sympy"].get("8", {})
    if "ratio" in eight or "sympy_capped" in eight:
        sympy = eight.get("sympy_s", eight.get("sympy_capped", 0))
        first, cached, interpreted = (sympy / eight[k] for k in ("eomgen_s", "eomgen_cached_s", "eomgen_interpreted_s"))
        met = lambda x: "met" if x >= 50 else "not met"
        lines += ["", f"Target (issue 32): the whole time ≥ 50× below SymPy's at n = 8: **{met(interpreted)}** on a "
                  f"first run with the interpreter ({interpreted:.1f}×), {met(first)} on a first run that compiles "
                  f"({first:.1f}×: the C++ compiler's seconds are most of that time), {met(cached)} on a cached run "
                  f"({cached:.1f}×)."]
    lines.append("")
    return "\n".join(lines) + "\n"
