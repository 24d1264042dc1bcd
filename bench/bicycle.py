"""Section 11 of docs/benchmarks.md (issue 35): the Whipple bicycle from models/whipple_bicycle.toml, derived and
linearized about upright straight running by `eomgen modes --steady`, against the benchmark of Meijaard et al.
(2007) and against SymPy's Kane's method on the same bicycle (sympy/physics/mechanics/tests/test_kane3.py, which
derives it, linearizes it and checks its eigenvalues at 5 m/s). Called by bench.py (in the full run, and alone with
--bicycle-only); the page's part between the BICYCLE markers is written by render() from measure()'s results.

Measured:
- the whole process `eomgen modes models/whipple_bicycle.toml --steady thetaR_dot=-v/rR --format json` (reading,
  deriving, the steady state, the linearization at 5 m/s and the split of C and K by v), best of 3, wall clock;
- the same with `--sweep v=0:10:201` (201 linearizations and the stability boundaries to the last bit);
- the largest relative difference of M, C1, K0, K2 from the paper's 14-digit values, and of the weave and capsize
  speeds from its 4.2923825363 and 6.0242620154;
- SymPy's test_bicycle(), one run in a fresh interpreter (import included), capped.
"""
import json
import os
import subprocess
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
MODEL = os.path.join(ROOT, "models", "whipple_bicycle.toml")

# The paper's Table 2 (rounded to 14 digits) and its weave and capsize speeds (10 digits).
PAPER = {
    "M": [[80.81722, 2.31941332208709], [2.31941332208709, 0.29784188199686]],
    "C1": [[0, 33.86641391492494], [-0.85035641456978, 1.68540397397560]],
    "K0": [[-80.95, -2.59951685249872], [-2.59951685249872, -0.80329488458618]],
    "K2": [[0, 76.59734589573222], [0, 2.65431523794604]],
}
WEAVE, CAPSIZE = 4.2923825363, 6.0242620154


def relative(a, b):
    scale = max(1.0, max(abs(x) for row in b for x in row))
    return max(abs(x - y) for ra, rb in zip(a, b) for x, y in zip(ra, rb)) / scale


def timed(args):
    start = time.perf_counter()
    p = subprocess.run(args, capture_output=True, text=True)
    seconds = time.perf_counter() - start
    if p.returncode != 0:
        raise RuntimeError(f"{' '.join(args)} failed ({p.returncode}): {p.stdout}{p.stderr}")
    return seconds, p.stdout


def sympy_bicycle(cap):
    code = ("import time\nt = time.perf_counter()\n"
            "from sympy.physics.mechanics.tests.test_kane3 import test_bicycle\n"
            "test_bicycle()\nprint(time.perf_counter() - t)\n")
    try:
        p = subprocess.run(["python3", "-c", code], capture_output=True, text=True, timeout=cap)
    except subprocess.TimeoutExpired:
        return {"status": "capped", "cap": cap}
    if p.returncode != 0:
        return {"status": "unavailable", "why": (p.stderr.strip().splitlines() or ["?"])[-1]}
    return {"status": "ok", "seconds": float(p.stdout.strip().splitlines()[-1])}


def measure(cfg, work, smoke, log, sympy_cap=900.0):
    eomgen = cfg["eomgen"]
    base = [eomgen, "modes", MODEL, "--steady", "thetaR_dot=-v/rR", "--format", "json"]
    log("11. bicycle: eomgen modes --steady")
    # The smoke run derives the bicycle once, for the sweep, whose report holds the same M, C1, K0, K2 and eigenvalues
    # at 5 m/s as the run without it (each derivation is about 8 s on 2 cores); the full run times both.
    runs = []
    for _ in range(0 if smoke else 3):
        seconds, out = timed(base)
        runs.append(seconds)
    count = 21 if smoke else 201
    sweep_seconds, swept = timed(base + ["--sweep", f"v=0:10:{count}"])
    r = json.loads(out if runs else swept)
    agree = {"M": relative(r["M"], PAPER["M"])}
    for key in ("C1", "K0", "K2"):
        agree[key] = relative(r["split"][key], PAPER[key])
    changes = json.loads(swept)["sweep"]["changes"]
    speeds = [c["value"] for c in changes]
    result = {"seconds": runs, "agree": agree, "eigenvalues": r["eigenvalues"], "sweep_points": count,
              "sweep_seconds": sweep_seconds, "changes": changes}
    if len(speeds) == 2:
        result["weave_error"] = abs(speeds[0] / WEAVE - 1)
        result["capsize_error"] = abs(speeds[1] / CAPSIZE - 1)
    if smoke:
        result["sympy"] = {"status": "skipped (smoke)"}
    else:
        log("11. bicycle: SymPy's Kane's method (test_kane3.test_bicycle)")
        result["sympy"] = sympy_bicycle(sympy_cap)
    return result


def render(r, command, date, machine_line):
    timed_alone = bool(r["seconds"])
    best = min(r["seconds"]) if timed_alone else float("nan")
    lines = ["## 11. The Whipple bicycle: derivation and linearization about a steady motion (issue 35)", "",
             f"Measured by `{command}` on {date} (bench/bicycle.py). {machine_line}", "",
             "`eomgen modes models/whipple_bicycle.toml --steady thetaR_dot=-v/rR --format json`, the whole process "
             "(reading the model file, deriving the equations of four bodies and two rolling contacts, the steady "
             "state, the linearization on the constraint manifold at 5 m/s, and C and K split by v from three more "
             + (f"linearizations), wall clock, best of {len(r['seconds'])}:" if timed_alone else
                "linearizations); the smoke run times only the sweep:"), "",
             "| what | seconds |", "|---|---|",
             (f"| eomgen modes --steady (5 m/s, split by v) | {best:.2f} |" if timed_alone else
              "| eomgen modes --steady (5 m/s, split by v) | – (smoke: only the sweep is run) |"),
             f"| ... with --sweep v=0:10:{r['sweep_points']} (and the stability boundaries) | {r['sweep_seconds']:.1f} |"]
    s = r["sympy"]
    if s["status"] == "ok":
        lines.append(f"| SymPy: test_kane3.test_bicycle (Kane's method, linearize, eigenvalues at 5 m/s) | {s['seconds']:.1f} |")
    elif s["status"] == "capped":
        lines.append(f"| SymPy: test_kane3.test_bicycle | stopped at {s['cap']:.0f} |")
    else:
        lines.append(f"| SymPy: test_kane3.test_bicycle | not run: {s.get('why', s['status'])} |")
    a = r["agree"]
    lines += ["", "Agreement with the paper (largest difference over the entries, relative to the matrix's largest): "
              f"M {a['M']:.1e}, C1 {a['C1']:.1e}, K0 {a['K0']:.1e}, K2 {a['K2']:.1e} (target 1e-12)."]
    if "weave_error" in r:
        lines.append(f"Weave speed {r['changes'][0]['value']:.13g} m/s (paper 4.2923825363, relative difference "
                     f"{r['weave_error']:.1e}), capsize speed {r['changes'][1]['value']:.13g} m/s (paper 6.0242620154, "
                     f"{r['capsize_error']:.1e}); the paper's values have 10 decimals (target 1e-10).")
    if not timed_alone:
        pass
    elif s["status"] == "ok":
        lines.append(f"eomgen's derivation and linearization take {best:.2f} s (target: under 5 s), "
                     f"{s['seconds'] / best:.0f}× less than SymPy's.")
    else:
        lines.append(f"eomgen's derivation and linearization take {best:.2f} s (target: under 5 s).")
    return "\n".join(lines) + "\n"
