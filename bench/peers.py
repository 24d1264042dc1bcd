"""Section 8 of the benchmark (issue 15): eomgen against MuJoCo and SUNDIALS, measured and rendered for bench.py.

measure() runs bench/time_chain (eomgen's rhs vs mj_forward and the O(n) recursion on the n-link chain, each checked
against eomgen before it is timed) and bench/time_ode_peers (work-precision of eomgen's integrators, Boost.Odeint,
CVODE Adams and BDF, and ARKODE's highest-order explicit table whose order checks out); render() writes the section
from the results (with the ratio of every target of issue 15, met or not). Methods are rows of the work-precision
tables, so an integrator added to time_ode_peers' kEomgenMethods adds a line each without a change here.
"""
import json
import os
import re
import subprocess

CHAIN_SIZES = [2, 4, 8, 12, 16, 20, 30]
ACCURACIES = [1e-8, 1e-10, 1e-12]
PROBLEMS = [("door", "door's closing time"), ("pendulum", "5-20 pendulum"), ("chain20", "20-link chain")]


def median(xs):
    xs = sorted(xs)
    k = len(xs) // 2
    return xs[k] if len(xs) % 2 else (xs[k - 1] + xs[k]) / 2


def to_reach(rows, target):
    """The cheapest run from which on every tighter tolerance also reaches `target` (bench.py's rule)."""
    rows = sorted(rows, key=lambda r: -r["rtol"])
    for i, r in enumerate(rows):
        if all(x["error"] <= target for x in rows[i:]):
            return r
    return None


def chain(cfg, build_dir, smoke, log):
    """Google Benchmark medians of chain/<who>/<n> (ns, CPU time), and the agreement lines checked before timing."""
    if not smoke:
        subprocess.run(["cmake", "-S", os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "-B", build_dir,
                        f"-DEOMGEN_BENCH_CHAIN_SIZES={';'.join(map(str, CHAIN_SIZES))}"], check=True,
                       stdout=subprocess.DEVNULL)
        log("building time_chain and time_ode_peers ...")
        subprocess.run(["cmake", "--build", build_dir, "--target", "time_chain", "time_ode_peers", "-j", "2"],
                       check=True, stdout=subprocess.DEVNULL)
    p = subprocess.run([cfg["time_chain"], "--benchmark_format=json",
                        f"--benchmark_min_time={'0.01' if smoke else '0.1'}",
                        f"--benchmark_repetitions={'1' if smoke else '10'}",
                        "--benchmark_enable_random_interleaving=true"],
                       check=True, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    runs = {}
    for b in json.loads(p.stdout)["benchmarks"]:
        if b.get("run_type") == "aggregate":
            continue
        _, who, n = b["run_name"].split("/")
        runs.setdefault(f"{who}/{n}", []).append(b["cpu_time"] * {"ns": 1, "us": 1e3, "ms": 1e6}[b["time_unit"]])
    return {"median_ns": {k: median(v) for k, v in runs.items()}, "agree": p.stderr.strip(),
            "repetitions": 1 if smoke else 10}


def ode(cfg, smoke):
    p = subprocess.run([cfg["time_ode_peers"]] + (["--quick"] if smoke else []), check=True,
                       stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    rows = [json.loads(line) for line in p.stdout.splitlines() if line.startswith("{")]
    return {"orders": [r for r in rows if r["kind"] == "order"], "runs": [r for r in rows if r["kind"] == "run"],
            "checks": p.stderr.strip()}


def measure(cfg, build_dir, smoke, log):
    load0 = os.getloadavg()
    log("8. peers: the n-link chain against MuJoCo and the O(n) recursion")
    ch = chain(cfg, build_dir, smoke, log)
    log("8. peers: work-precision against odeint, CVODE and ARKODE")
    od = ode(cfg, smoke)
    cpu = subprocess.run("lscpu | sed -n 's/^Model name: *//p' | head -1", shell=True, stdout=subprocess.PIPE,
                         text=True).stdout.strip() or "?"
    return {"chain": ch, "ode": od, "load": [load0[0], os.getloadavg()[0]], "cpu": f"{cpu}, {os.cpu_count()} cores",
            "mujoco": cfg.get("mujoco", ""), "sundials": cfg.get("sundials", "")}


# ---- rendering ------------------------------------------------------------------------------------------------

def verdict(ok):
    return "**met**" if ok else "**not met**"


def render(res, command, date):
    L = []
    a = L.append
    ch, od = res["chain"], res["ode"]
    med = ch["median_ns"]
    sizes = sorted({int(k.split("/")[1]) for k in med})
    have_mj = any(k.startswith("mujoco/") for k in med)
    a("## 8. Against MuJoCo and SUNDIALS (issue 15)")
    a("")
    a(f"Measured by `{command}` on {date}, one run, on {res.get('cpu', '?')}; load average (1 min) {res['load'][0]:.2f} at the start of this "
      f"section and {res['load'][1]:.2f} at its end (the machine is shared: times carry that noise). MuJoCo "
      f"{res['mujoco'] or '(not installed)'} and SUNDIALS {res['sundials'] or '(not installed)'}, both Debian's "
      "(`bench/setup_peers.sh`), the same compiler and flags (-O2 -DNDEBUG) for every program of ours.")
    a("")

    # Targets
    a("### Targets (issue 15), as ratios from this run")
    a("")
    a("| target | measured | met? |")
    a("|---|---|---|")
    if have_mj:
        r = {n: med[f"eomgen/{n}"] / med[f"mujoco/{n}"] for n in sizes}
        a("| `rhs` ≤ 0.2× `mj_forward` at every n | " + ", ".join(f"n = {n}: {r[n]:.2f}" for n in sizes) + " | " +
          verdict(all(v <= 0.2 for v in r.values())) +
          (f" (above 0.2 at n = {', '.join(str(n) for n in sizes if r[n] > 0.2)})" if any(
              v > 0.2 for v in r.values()) else "") + " |")
    else:
        a("| `rhs` ≤ 0.2× `mj_forward` at every n | MuJoCo not installed in this run | – |")
    rr = {n: med[f"eomgen/{n}"] / med[f"recursion/{n}"] for n in sizes}
    small = [n for n in sizes if n <= 8]
    a("| `rhs` ≤ 1.5× the O(n) recursion at n ≤ 8 | " + ", ".join(f"n = {n}: {rr[n]:.2f}" for n in small) + " | " +
      verdict(all(rr[n] <= 1.5 for n in small)) + " |")
    if 30 in rr:
        a(f"| `rhs` ≤ 2× the O(n) recursion at n = 30 | {rr[30]:.2f} | {verdict(rr[30] <= 2)} |")
    else:
        a("| `rhs` ≤ 2× the O(n) recursion at n = 30 | n = 30 not in this run (smoke) | – |")
    runs = od["runs"]
    by = {}
    for r in runs:
        by.setdefault((r["problem"], r["method"]), []).append(r)
    methods = []
    for r in runs:
        if r["method"] not in methods:
            methods.append(r["method"])
    ours = [m for m in methods if m.startswith("eomgen_")]
    peers = [m for m in methods if not m.startswith("eomgen_")]
    evals_ok, wall_ok, parts_e, parts_w = True, True, [], []
    for prob, _ in PROBLEMS:
        for acc in ACCURACIES:
            best_ours = min((to_reach(by.get((prob, m), []), acc) for m in ours),
                            key=lambda r: r["rhs_evals"] if r else float("inf"), default=None)
            reached = [to_reach(by.get((prob, m), []), acc) for m in peers]
            reached = [r for r in reached if r]
            if not best_ours and not reached:
                parts_e.append(f"{prob} {acc:.0e}: reached by none")
                continue
            if not best_ours:  # a peer reaches what eomgen does not: not met
                evals_ok = wall_ok = False
                parts_e.append(f"{prob} {acc:.0e}: not reached by eomgen")
                continue
            if not reached:  # eomgen reaches what no peer does: ahead of every peer there
                parts_e.append(f"{prob} {acc:.0e}: no peer reached it (eomgen did)")
                continue
            be = min(r["rhs_evals"] for r in reached)
            bw = min(r["seconds"] for r in reached)
            ours_w = min(to_reach(by.get((prob, m), []), acc)["seconds"] for m in ours
                         if to_reach(by.get((prob, m), []), acc))
            evals_ok = evals_ok and best_ours["rhs_evals"] <= be
            wall_ok = wall_ok and ours_w <= 0.5 * bw
            parts_e.append(f"{prob} {acc:.0e}: {best_ours['rhs_evals'] / be:.2f}")
            parts_w.append(f"{prob} {acc:.0e}: {ours_w / bw:.2f}")
    a("| right-hand-side evaluations to each accuracy ≤ the best peer's (best eomgen method / best of odeint, CVODE, "
      "ARKODE) | " + "; ".join(parts_e) + f" | {verdict(evals_ok)} |")
    a("| wall time to each accuracy ≤ 0.5× the best peer's (fastest eomgen run / fastest peer run) | " +
      ("; ".join(parts_w) or "–") + f" | {verdict(wall_ok)} |")
    d5 = to_reach(by.get(("door", "eomgen_dopri5"), []), 1e-14)
    best14 = [(m, to_reach(by.get(("door", m), []), 1e-14)) for m in ours]
    best14 = [(m, r) for m, r in best14 if r]
    if d5 and best14:
        m, r = min(best14, key=lambda x: x[1]["rhs_evals"])
        ratio = d5["rhs_evals"] / r["rhs_evals"]
        a(f"| the door's closing time to 1e-14 at least 3× cheaper than Dormand–Prince 5(4) | eomgen_dopri5 "
          f"{d5['rhs_evals']} evaluations / {m} {r['rhs_evals']} = {ratio:.2f}× | {verdict(ratio >= 3)} |")
    else:
        a("| the door's closing time to 1e-14 at least 3× cheaper than Dormand–Prince 5(4) | 1e-14 not reached in "
          "this run | – |")
    a("")

    # Chain
    a("### The n-link chain: `rhs` against `mj_forward` and the O(n) recursion")
    a("")
    found = re.findall(r"n = (\d+): eomgen and MuJoCo mj_forward agree to ([0-9.e+-]+)", ch["agree"])
    rec = re.findall(r"n = (\d+): eomgen and the O\(n\) recursion agree to ([0-9.e+-]+)", ch["agree"])
    worst_mj = max((float(v) for _, v in found), default=None)
    worst_rec = max((float(v) for _, v in rec), default=None)
    a("`bench/time_chain` (Google Benchmark): `--family pendulum:n=N` (unit masses and lengths, g = 9.81), 64 random "
      "states cycled (angles in (−1.5, 1.5), rates in (−2, 2)); the median of "
      f"{ch.get('repetitions', 10)} repetition(s) of CPU time, all benchmarks' repetitions in random order. eomgen: the generated `Model<double>::rhs` (M and f, the solve, x'). "
      "MuJoCo: `mj_forward` on an MJCF chain the program writes (`chain_mjcf` in bench/chain_harness.hpp: hinges "
      "about −y so a joint angle is θ_i − θ_{i−1}, each point mass an `<inertial>` of 1e-12 kg m² rotational "
      "inertia at the link's end with a tiny non-colliding sphere, contacts disabled, no damping, armature or "
      "limits), the state converted to joint coordinates before the loop and copied into `qpos`/`qvel` in it. "
      "The floor: bench/chain_recursion.hpp, θ̈ through the link tensions (a tridiagonal solve), O(n). Before "
      "timing, each is compared with eomgen's q̈ at the 64 states and the run refuses to time a peer that "
      "disagrees (tolerances: 1e-6 relative for MuJoCo, whose point masses need that tiny inertia; 1e-10 for the "
      "recursion): " +
      (f"MuJoCo agrees to {worst_mj:.0e} at worst" if worst_mj is not None else "MuJoCo not installed") +
      (f", the recursion to {worst_rec:.0e}" if worst_rec is not None else "") + " (largest relative difference of "
      "q̈ over the states, every n).")
    a("")
    have_dense = any(k.startswith("dense/") for k in med)
    if have_dense:
        a("The last two columns: the same model through the dense M (the header's `dynamics`, then the runtime's "
          "`solve_mass_matrix`; `rhs_dense_solve` in bench/chain_harness.hpp, checked against `rhs` like the peers), "
          "and how much faster `rhs` is. From n = 13 on `rhs` is the tree of point masses' O(n) recursion "
          "(codegen/tree_emitter.hpp, runtime/eomgen/particle_tree.hpp); below, the header's unrolled L D Lᵀ of M.")
        a("")
    a("| n | eomgen `rhs` [ns] | MuJoCo `mj_forward` [ns] | O(n) recursion [ns] | rhs / mj_forward | "
      "rhs / recursion |" + (" rhs through the dense M [ns] | dense / rhs |" if have_dense else ""))
    a("|---|---|---|---|---|---|" + ("---|---|" if have_dense else ""))
    for n in sizes:
        e, m, r, p = med[f"eomgen/{n}"], med.get(f"mujoco/{n}"), med[f"recursion/{n}"], med.get(f"dense/{n}")
        a(f"| {n} | {e:.0f} | {f'{m:.0f}' if m else '–'} | {r:.0f} | {f'**{e / m:.2f}**' if m else '–'} | "
          f"**{e / r:.2f}** |" + (f" {p:.0f} | **{p / e:.2f}×** |" if p else ""))
    a("")

    # Orders
    a("### ARKODE's explicit tables: the order they show")
    a("")
    a("Fixed steps h = T/4, T/8, … (`ERKStepSetFixedStep`) on the door (T = 2, before it shuts) and the 5-20 pendulum "
      "(T = 8), error of the end state against RKF 7(8) in long double at 1e-19; the slopes log₂(e(h)/e(h/2)) while "
      "the error stays above round-off (1e-13 and 1e-12 relative), the observed order the mean of the last two. A "
      "table counts with its observed order when both problems show the same whole number to within 0.3; the peer "
      "below is the table of the highest such order.")
    a("")
    if od["orders"]:
        a("| table | nominal order | door: slopes | observed | pendulum: slopes | observed | counted as order |")
        a("|---|---|---|---|---|---|---|")
        for o in od["orders"]:
            a(f"| {o['table']} | {o['nominal']} | {', '.join(f'{s:.2f}' for s in o['door_slopes'])} | {o['door']:.2f} | "
              f"{', '.join(f'{s:.2f}' for s in o['pendulum_slopes'])} | {o['pendulum']:.2f} | "
              f"{o['verified'] or 'none'} |")
    else:
        a("SUNDIALS not installed in this run.")
    a("")

    # Work-precision
    a("### Work-precision: evaluations and time to reach an accuracy")
    a("")
    checks = od["checks"].replace("\n", "; ")
    a("`bench/time_ode_peers`: every method calls the same generated `rhs` through a counting wrapper, atol = rtol, "
      "tolerances 10^-4 … 10^-14 in steps of 10^(1/2). Door: from rest at ψ = 0 until ψ falls through −π/2, error = "
      "relative error of the closing time against the closed form (eomgen: its event on the dense output; odeint: "
      "Brent on `calc_state`; CVODE and ARKODE: their own root finding). Pendulum (models/pendulum_5_20.toml, "
      "(0.5, −0.3, 0.5, 2) to t = 10) and the 20-link chain (`--family pendulum:n=20` from rest with every link at "
      "0.5 rad, to t = 2): error = max-norm of the end state relative to the reference's, the reference RKF 7(8) in "
      f"long double at 1e-19 ({checks}). CVODE Adams uses fixed-point iteration, BDF Newton with the dense direct "
      "solver and a difference-quotient Jacobian (its evaluations count). A cell: the cheapest run from which on every "
      "tighter tolerance also reaches the accuracy, its right-hand-side evaluations and its time (the fastest of at "
      "least 2 repetitions and 30 ms).")
    a("")
    for prob, title in PROBLEMS:
        a(f"**{title}** (`{prob}`)")
        a("")
        a("| method | " + " | ".join(f"{acc:.0e}: evals | µs" for acc in ACCURACIES) + " |")
        a("|---|" + "---|---|" * len(ACCURACIES))
        for m in methods:
            cells = []
            for acc in ACCURACIES:
                r = to_reach(by.get((prob, m), []), acc)
                cells.append(f"{r['rhs_evals']} | {r['seconds'] * 1e6:.0f}" if r else "not reached | –")
            a(f"| {m} | " + " | ".join(cells) + " |")
        a("")
    return "\n".join(L) + "\n"
