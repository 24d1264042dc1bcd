"""Section 14 of docs/benchmarks.md: `eomgen run --interpret` against the compiled run (docs/interpreter.md).

For each model: the whole `eomgen run` of the model's own t_end three ways, each in a fresh process with a cache of
its own — compiled with the cache empty (derive, emit, compile, integrate), compiled from the cache (integrate only),
and interpreted (derive, record the tapes, integrate) — then the same model integrated 100× longer from the cache and
interpreted, whose difference divided by the right-hand sides counted is the interpreter's extra cost per right-hand
side; the first run's compile time divided by it is how many right-hand sides a run needs before compiling pays.
"""

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
        long_end = f"{t_end * (10 if smoke else 100):g}"
        long_cached, long_rhs, _ = timed_run(cfg, cache, path, "--t-end", long_end)
        long_interpreted, _, _ = timed_run(cfg, empty, path, "--t-end", long_end, "--interpret")
        extra = (long_interpreted - interpreted - (long_cached - cached)) / max(long_rhs - rhs, 1)
        rows[name] = {"t_end": t_end, "first": first, "cached": cached, "interpreted": interpreted, "rhs": rhs,
                      "same_rhs": rhs == rhs_i, "long_t_end": float(long_end), "long_rhs": long_rhs,
                      "long_cached": long_cached, "long_interpreted": long_interpreted, "extra_per_rhs": extra,
                      "difference": max((abs(x_compiled[k] - x_interpreted.get(k, float("nan"))) for k in x_compiled),
                                        default=0.0)}
    return {"models": rows}


def render(r, command, date, machine_line):
    lines = ["## 14. `eomgen run --interpret`: no compiler, against the compiled run (docs/interpreter.md)", "",
             f"Measured by `{command}` on {date}. {machine_line}", "",
             "bench/interpreter.py: each cell one `eomgen run MODEL --quiet` in a fresh process (wall time, process start "
             "included) with a cache of its own: compiled with the cache empty (derive, emit, compile, integrate), "
             "compiled from the cache (integrate only), interpreted (derive, record the tapes, integrate; no compiler, "
             "nothing written to the cache). Each model for its own t_end, then for 100× as long from the cache and "
             "interpreted: the interpreter's extra cost per right-hand side is the difference of the two long runs "
             "less that of the short ones, over the right-hand sides between them; the break-even is the first run's "
             "extra time over the cached one divided by that cost, the right-hand sides a run needs before compiling "
             "pays. The last column is the largest difference of the final states (the interpreted run against the "
             "compiled one, as printed: 15 digits).", "",
             "| model | t_end [s] | compiled, empty cache [s] | compiled, cached [s] | interpreted [s] | first run: "
             "compiled / interpreted | right-hand sides | extra per right-hand side interpreted [µs] | break-even "
             "[right-hand sides] | final states differ by |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for name, m in r["models"].items():
        extra = m["extra_per_rhs"]
        even = (m["first"] - m["cached"]) / extra if extra > 0 else float("inf")
        lines.append(f"| {name} | {m['t_end']:g} | {m['first']:.2f} | {m['cached']:.2f} | {m['interpreted']:.2f} | "
                     f"**{m['first'] / m['interpreted']:.1f}×** | {m['rhs']:,} | {extra * 1e6:.2f} | "
                     f"{'∞' if even == float('inf') else f'{even:,.0f}'} | {m['difference']:.1e} |")
    lines.append("")
    return "\n".join(lines) + "\n"
