"""Section 14 of docs/benchmarks.md: `eomgen run --interpret` against the compiled run (docs/interpreter.md).

For each model: the whole `eomgen run` of the model's own t_end three ways, each in a fresh process with a cache of
its own — compiled with the cache empty (derive, emit, compile, integrate), compiled from the cache (integrate only),
and interpreted (derive, record the tapes, integrate). Then the cost of one right-hand side both ways, from Python
(`Model.rhs` over the states of a compiled run, repeated to 10^5 rows; best of 3): how much slower each step is
interpreted, and how many right-hand sides a run needs before the compiler's seconds are paid back.
"""

import json
import os
import re
import subprocess
import tempfile
import time

MODELS = ["pendulum", "damped_pendulum", "door", "pendulum_cartesian", "rolling_disc", "heavy_symmetric_top",
          "pendulum_5_20", "whipple_bicycle"]
SMOKE_MODELS = ["pendulum", "pendulum_cartesian"]


def timed_run(cfg, cache, model, *options):
    """Wall seconds of one `eomgen run MODEL --quiet OPTIONS` with XDG_CACHE_HOME=cache, and its right-hand sides."""
    env = dict(os.environ, XDG_CACHE_HOME=cache)
    t0 = time.perf_counter()
    p = subprocess.run([cfg["eomgen"], "run", model, "--quiet", *options], env=env, capture_output=True, text=True,
                       check=True)
    seconds = time.perf_counter() - t0
    m = re.search(r"(\d+) right-hand sides", p.stdout)
    final = re.findall(r"^  (\S+) = (\S+)", p.stdout, re.M)
    return seconds, int(m.group(1)) if m else 0, {k: float(v.split()[0]) for k, v in final}


def t_end_of(path):
    """The model file's own t_end ([simulation] t_end), else eomgen run's default of 10 s."""
    text = open(path).read()
    m = re.search(r"^\s*t_end\s*=\s*([0-9.eE+-]+)", text, re.M)
    return float(m.group(1)) if m else 10.0


RHS_COST = """
import json, sys, time
import numpy as np
import eomgen
m = eomgen.load(sys.argv[1])
sol = m.simulate(float(sys.argv[2]), samples=2000)
rows = int(sys.argv[3])
reps = -(-rows // len(sol.t))
x = np.tile(sol.x, (reps, 1))[:rows]
t = np.tile(sol.t, reps)[:rows]
best, out = {}, {}
for interpret in (False, True):
    m.rhs(t[:2], x[:2], interpret=interpret)
    best[interpret] = float("inf")
    for _ in range(3):
        t0 = time.perf_counter()
        out[interpret] = m.rhs(t, x, interpret=interpret)
        best[interpret] = min(best[interpret], time.perf_counter() - t0)
scale = np.maximum(1.0, np.abs(out[False]))
print(json.dumps({"compiled_ns": best[False] * 1e9 / rows, "interpreted_ns": best[True] * 1e9 / rows,
                  "rhs_difference": float(np.max(np.abs(out[True] - out[False]) / scale))}))
"""


def rhs_costs(cfg, cache, path, t_end, rows):
    """ns per right-hand side compiled and interpreted, from Python over the states of a compiled run."""
    env = dict(os.environ, PYTHONPATH=cfg["python_path"], XDG_CACHE_HOME=cache, PYTHONDONTWRITEBYTECODE="1")
    p = subprocess.run([cfg["python3"], "-c", RHS_COST, path, f"{t_end:g}", str(rows)], env=env, capture_output=True,
                       text=True, check=True)
    return json.loads(p.stdout.strip().splitlines()[-1])


def measure(cfg, work, smoke, log):
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    rows = {}
    for name in SMOKE_MODELS if smoke else MODELS:
        path = os.path.join(root, "models", name + ".toml")
        t_end = t_end_of(path)
        log(f"14. interpreter: {name}")
        cache = tempfile.mkdtemp(prefix=f"cache-{name}-", dir=work)
        first, rhs, x_compiled = timed_run(cfg, cache, path, "--t-end", f"{t_end:g}")
        cached, _, _ = timed_run(cfg, cache, path, "--t-end", f"{t_end:g}")
        empty = tempfile.mkdtemp(prefix=f"cache-{name}-interpreted-", dir=work)
        interpreted, rhs_i, x_interpreted = timed_run(cfg, empty, path, "--t-end", f"{t_end:g}", "--interpret")
        row = {"t_end": t_end, "first": first, "cached": cached, "interpreted": interpreted, "rhs": rhs,
               "same_rhs": rhs == rhs_i,
               "difference": max((abs(x_compiled[k] - x_interpreted.get(k, float("nan"))) for k in x_compiled),
                                 default=0.0)}
        if "python_path" in cfg:
            row.update(rhs_costs(cfg, cache, path, t_end, 10_000 if smoke else 100_000))
        rows[name] = row
    return {"models": rows}


def render(r, command, date, machine_line):
    lines = ["## 14. `eomgen run --interpret`: no compiler, against the compiled run (docs/interpreter.md)", "",
             f"Measured by `{command}` on {date}. {machine_line}", "",
             "bench/interpreter.py: the first columns are each one `eomgen run MODEL --quiet` of the model's own t_end in "
             "a fresh process (wall time, process start included) with a cache of its own: compiled with the cache "
             "empty (derive, emit, compile, integrate), compiled from the cache (integrate only), interpreted (derive, "
             "record the tapes, integrate; no compiler). The right-hand side's cost is `Model.rhs` from Python over the "
             "states of that run repeated to 10⁵ rows, best of 3, compiled and interpreted; the break-even is the "
             "first run's difference (compiled − interpreted) over the interpreter's extra cost per right-hand side: "
             "the right-hand sides a run needs before compiling pays. The last columns are the largest differences, "
             "of the final states printed (15 digits) and of the right-hand sides (relative to max(1, |value|)).", "",
             "| model | compiled, empty cache [s] | compiled, cached [s] | interpreted [s] | first run: compiled / "
             "interpreted | right-hand sides in the run | one right-hand side, compiled / interpreted [ns] | "
             "interpreted / compiled | break-even [right-hand sides] | final states differ by | right-hand sides "
             "differ by |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for name, m in r["models"].items():
        cost = "–"
        ratio = "–"
        even = "–"
        rhs_diff = "–"
        if "compiled_ns" in m:
            extra = (m["interpreted_ns"] - m["compiled_ns"]) * 1e-9
            cost = f"{m['compiled_ns']:.0f} / {m['interpreted_ns']:.0f}"
            ratio = f"{m['interpreted_ns'] / m['compiled_ns']:.1f}×"
            even = f"{(m['first'] - m['interpreted']) / extra:,.0f}" if extra > 0 else "∞"
            rhs_diff = f"{m['rhs_difference']:.1e}"
        lines.append(f"| {name} | {m['first']:.2f} | {m['cached']:.2f} | {m['interpreted']:.2f} | "
                     f"**{m['first'] / m['interpreted']:.1f}×** | {m['rhs']:,} | {cost} | {ratio} | {even} | "
                     f"{m['difference']:.1e} | {rhs_diff} |")
    lines.append("")
    return "\n".join(lines) + "\n"
