"""Section 9 of docs/benchmarks.md (issue 37): generation at scale, the default header against every optional
function, beside SymPy. Called by bench.py (in the full run, and alone with --scale-only); the page's part
between the SCALE markers is written by render() from measure()'s results, nothing by hand.

Measured, per size of the n-link pendulum (`eomgen generate --family pendulum:n=N`) and for a 3-D chain of
rigid bodies (thin cylinders on spherical joints, two angles each, written by chain3d_model() below):
- the default header, and the header with `--with all` (analytic Jacobians and K, C, G about rest);
- CPU time (user + system) and peak resident memory of the one process (os.wait4), best of `reps` runs;
- the phases that `eomgen generate --timings` prints (derive, jacobians, stiffness, the rest);
- SymPy's LagrangesMethod + cse + ccode of the same pendulum (bench/sympy_pendulum.py) where it finishes
  within its cap; after one size is capped the larger ones are not tried.
"""
import json
import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))

# Targets of issue 37, in CPU seconds and MB.
TARGETS = {"default": {30: 1.5, 60: 8.0}, "all": {30: 5.0, 60: 40.0}, "memory_mb": 300.0, "chain3d": 10.0,
           "sympy_ratio": 100.0}


def chain3d_model(n):
    """Model-file text of a 3-D chain of n thin cylinders (mass m, length l, radius r) hung from a fixed point by
    spherical joints: body i's axis is its z axis, turned by z-x-z Euler angles (phi_i, theta_i, 0), so its
    direction in space is u_i = (sin theta_i sin phi_i, -sin theta_i cos phi_i, cos theta_i); its centre is
    sum_{j<i} l u_j + l/2 u_i."""
    def u(i):
        return [f"sin(theta{i})*sin(phi{i})", f"-sin(theta{i})*cos(phi{i})", f"cos(theta{i})"]

    lines = [f'name = "chain3d_{n}"', f'title = "3-D chain of {n} rigid cylinders on spherical joints"', ""]
    for i in range(1, n + 1):
        lines += ["[[coordinates]]", f'name = "phi{i}"', "initial = 0.3", "",
                  "[[coordinates]]", f'name = "theta{i}"', "initial = 2.5", ""]
    for name, value in (("m", 1.0), ("l", 0.5), ("r", 0.05), ("g", 9.81)):
        lines += ["[[parameters]]", f'name = "{name}"', f"value = {value}", ""]
    for i in range(1, n + 1):
        centre = []
        for axis in range(3):
            terms = [f"l*{u(j)[axis]}" for j in range(1, i)] + [f"l/2*{u(i)[axis]}"]
            centre.append(" + ".join(terms))
        lines += ["[[bodies]]", f'name = "link{i}"', 'mass = "m"', 'shape = "cylinder"', 'dimensions = ["r", "l"]',
                  "position = [" + ", ".join(f'"{c}"' for c in centre) + "]",
                  f'orientation = ["phi{i}", "theta{i}", "0"]', ""]
    lines += ["[gravity]", 'vector = ["0", "0", "-g"]', ""]
    return "\n".join(lines)


def run_measured(cmd):
    """Runs cmd once; returns (CPU seconds, wall seconds, peak RSS in MB, stderr) of that one process."""
    t0 = time.perf_counter()
    p = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    err = p.stderr.read()
    _, status, usage = os.wait4(p.pid, 0)
    wall = time.perf_counter() - t0
    p.returncode = os.waitstatus_to_exitcode(status)
    if p.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)} failed ({p.returncode}):\n{err}")
    return usage.ru_utime + usage.ru_stime, wall, usage.ru_maxrss / 1024.0, err


def phases_of(timings):
    """Seconds of derive, jacobians, stiffness and the rest, from `eomgen generate --timings`' table."""
    out = {"derive": 0.0, "jacobians": 0.0, "stiffness": 0.0, "rest": 0.0}
    for line in timings.splitlines():
        parts = line.split()
        if len(parts) < 3 or parts[0] in ("phase", "total") or line.endswith("generation phases"):
            continue
        try:
            seconds = float(parts[-2])
        except ValueError:
            continue
        name = " ".join(parts[:-2])
        key = ("derive" if name == "derive" else "jacobians" if name.startswith("jacobians") else
               "stiffness" if name.startswith("stiffness") or name in ("function stiffness()", "function damping()",
                                                                       "function gyroscopic()") else "rest")
        out[key] += seconds
    return out


def generate(eomgen, source, with_all, out_dir, reps):
    """Best of reps runs (by CPU time) of one `eomgen generate`; source is ["--family", spec] or [file]."""
    best = None
    for _ in range(reps):
        cmd = [eomgen, "generate", *source, "--timings", "-o", out_dir] + (["--with", "all"] if with_all else [])
        cpu, wall, mb, err = run_measured(cmd)
        if best is None or cpu < best["cpu_s"]:
            best = {"cpu_s": cpu, "wall_s": wall, "peak_mb": mb, "phases": phases_of(err)}
    return best


def measure(cfg, work, smoke, log, sympy_runs, sympy_cap):
    sizes = [2, 3] if smoke else [8, 16, 30, 60]
    chain_n = 2 if smoke else 10
    out_dir = os.path.join(work, "scale")
    os.makedirs(out_dir, exist_ok=True)
    results = {"sizes": sizes, "pendulum": {}, "chain3d": {"n": chain_n}}
    for n in sizes:
        row = {}
        for variant in ("default", "all"):
            # Best of 5 below n = 30 (a run of 0.05-0.2 s is mostly a process start on a shared machine), of 2 above;
            # the header with every optional function at n = 60 once (10 s).
            reps = 1 if smoke or (n >= 60 and variant == "all") else 5 if n < 30 else 2
            row[variant] = generate(cfg["eomgen"], ["--family", f"pendulum:n={n}"], variant == "all", out_dir, reps)
            log(f"9. pendulum n={n} {variant}: {row[variant]['cpu_s']:.2f} s CPU, {row[variant]['peak_mb']:.0f} MB")
        results["pendulum"][str(n)] = row
    model = os.path.join(out_dir, f"chain3d_{chain_n}.toml")
    with open(model, "w") as fh:
        fh.write(chain3d_model(chain_n))
    for variant in ("default", "all"):
        results["chain3d"][variant] = generate(cfg["eomgen"], [model], variant == "all", out_dir, 1)
        log(f"9. 3-D chain of {chain_n} bodies {variant}: {results['chain3d'][variant]['cpu_s']:.2f} s CPU")
    sym_sizes = [2] if smoke else [n for n in sizes if n <= 30]
    results["sympy"] = {str(k): v for k, v in sympy_runs(os.path.join(work, "scale_sympy"), sym_sizes,
                                                          sympy_cap).items()} if sympy_runs else {}
    return results


def fmt(x, digits=3):
    if x is None:
        return ""
    if x >= 100:
        return f"{x:.0f}"
    return f"{x:.{digits}g}"


def met(ok):
    return "**met**" if ok else "**not met**"


def render(results, command, date, machine_line):
    sizes = [int(n) for n in results["pendulum"]]
    pend = {int(n): v for n, v in results["pendulum"].items()}
    sym = {int(n): v for n, v in results.get("sympy", {}).items()}
    lines = ["## 9. Generation at scale: what each header costs (issue 37)", "",
             f"Measured by `{command}` on {date}, one run (every figure of this section is from it). {machine_line}",
             "", "`eomgen generate --family pendulum:n=N` (the n-link pendulum of section 1), the default header and "
             "the header with `--with all` (analytic Jacobians, K, C and G about rest: docs/generated_code.md, "
             "\"Optional functions\"); CPU time (user + system) and peak resident memory of the one process "
             "(os.wait4), best of 5 runs below n = 30 and of 2 above (1 with `--with all` at n = 60); the phases from `--timings`. SymPy: bench/sympy_pendulum.py "
             "(LagrangesMethod, cse, ccode of M and f), stopped at its cap.", "",
             "| n | default: CPU [s] | of which derive [s] | peak [MB] | `--with all`: CPU [s] | of which Jacobians [s] "
             "| stiffness [s] | peak [MB] | SymPy CPU [s] | SymPy / default |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for n in sizes:
        d, a = pend[n]["default"], pend[n]["all"]
        s = sym.get(n, {})
        if "cpu_s" in s:
            scpu, ratio = fmt(s["cpu_s"]), f"**{s['cpu_s'] / d['cpu_s']:.0f}×**"
        elif s.get("capped"):
            scpu = f"> {s['cap_s']:.0f} (capped)" if not s.get("skipped") else "not run (smaller n capped)"
            ratio = f"> {s['cap_s'] / d['cpu_s']:.0f}×" if not s.get("skipped") else ""
        else:
            scpu, ratio = "not run", ""
        lines.append(f"| {n} | {fmt(d['cpu_s'])} | {fmt(d['phases']['derive'])} | {d['peak_mb']:.0f} | "
                     f"{fmt(a['cpu_s'])} | {fmt(a['phases']['jacobians'])} | {fmt(a['phases']['stiffness'])} | "
                     f"{a['peak_mb']:.0f} | {scpu} | {ratio} |")
    c = results["chain3d"]
    lines += ["", f"3-D chain of {c['n']} rigid cylinders on spherical joints ({2 * c['n']} coordinates, "
              "bench/scale.py's chain3d_model): default header "
              f"{fmt(c['default']['cpu_s'])} s CPU (derive {fmt(c['default']['phases']['derive'])} s), "
              f"{c['default']['peak_mb']:.0f} MB; `--with all` {fmt(c['all']['cpu_s'])} s CPU, "
              f"{c['all']['peak_mb']:.0f} MB.", ""]
    # Targets, as issue 37 states them.
    lines += ["| target (issue 37) | measured | met? |", "|---|---|---|"]
    for variant, label in (("default", "default header"), ("all", "every optional function")):
        for n, limit in TARGETS[variant].items():
            if n in pend:
                cpu = pend[n][variant]["cpu_s"]
                lines.append(f"| {label}, n = {n}: ≤ {limit:g} s CPU | {fmt(cpu)} s | {met(cpu <= limit)} |")
    for n in (30, 60):
        if n in pend:
            mb = pend[n]["default"]["peak_mb"]
            lines.append(f"| default header, n = {n}: ≤ {TARGETS['memory_mb']:.0f} MB | {mb:.0f} MB | "
                         f"{met(mb <= TARGETS['memory_mb'])} |")
    worst = max(c["default"]["cpu_s"], c["all"]["cpu_s"])
    lines.append(f"| 3-D chain of {c['n']} rigid bodies: ≤ {TARGETS['chain3d']:g} s | {fmt(worst)} s (`--with all`) | "
                 f"{met(worst <= TARGETS['chain3d'])} |")
    ratios = [(n, sym[n]["cpu_s"] / pend[n]["default"]["cpu_s"]) for n in sizes if "cpu_s" in sym.get(n, {})]
    if ratios:
        text = ", ".join(f"n = {n}: {r:.0f}×" for n, r in ratios)
        lines.append(f"| ahead of SymPy by ≥ {TARGETS['sympy_ratio']:.0f}× where it finishes | {text} | "
                     f"{met(all(r >= TARGETS['sympy_ratio'] for _, r in ratios))} |")
    lines.append("")
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    # Render again from a finished run: scale.py RESULTS_JSON
    with open(sys.argv[1]) as fh:
        r = json.load(fh)
    print(render(r["scale"], r.get("command", "bash bench/run.sh"), r.get("date", "?"), ""))
