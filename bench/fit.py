"""Section 10 of docs/benchmarks.md (issue 34): `eomgen fit` — are its standard errors calibrated, and what does the
exact Jacobian (the sensitivities) cost against Ceres' central differences of whole trajectories. Called by bench.py
(in the full run, and alone with --fit-only); the page's part between the FIT markers is written by render() from
measure()'s results, nothing by hand.

Measured:
- coverage: `trials` synthetic data sets per model, each the model's trajectory (`eomgen run` at rtol 1e-12) plus
  Gaussian noise of 1 % of the measured coordinate's scale (seeded by the trial), fitted from a start 20-30 % off;
  the share of trials in which the true value lies within the reported 2 standard errors (calibrated: about 95 %).
  The damped pendulum (l, c; 1,000 samples of phi over 10 s), the door (theta; 300 samples of psi until it shuts:
  the door's w and theta enter only as g sin(theta)/w, so one of them is fitted) and the door with friction in its
  hinges (theta and the friction torque tau_f, a switching surface sign(psi'); 300 samples until it shuts).
- time: the damped pendulum's fit to 1,000 samples, with the sensitivities' Jacobian and with central differences,
  best of 5: Ceres' time, iterations and integrations, and the time per iteration.
"""
import csv
import json
import os
import random
import statistics
import subprocess

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)

# Each model: its file, the measured coordinate, the noise (1 % of the coordinate's scale), the run's options, the
# free values with the truth (the file's values) and the starts' factors.
MODELS = [
    {"name": "damped_pendulum", "file": "models/damped_pendulum.toml", "column": "phi", "sigma": 0.01,
     "run": ["--t-end", "10", "--samples", "999"],
     "free": [("l", 1.0, 1.3, "0.1:10"), ("c", 0.2, 0.75, "0:2")]},
    {"name": "door", "file": "models/door.toml", "column": "psi", "sigma": 0.0157,
     "run": ["--t-end", "2.99", "--samples", "299"],
     "free": [("theta", 0.0234, 1.2, "0.001:0.5")]},
    {"name": "friction_door", "file": "examples/friction_door.toml", "column": "psi", "sigma": 0.0157,
     "run": ["--t-end", "4.4", "--samples", "299"],
     "free": [("theta", 0.0234, 1.2, "0.001:0.5"), ("tau_f", 1.5, 0.75, "0:10")]},
    # The damped pendulum's data with 5 % of the samples thrown off by 0.2-0.5 rad (outliers), fitted by least
    # squares and by Huber's loss at 3 times the noise (--loss).
    {"name": "damped_pendulum_outliers", "file": "models/damped_pendulum.toml", "column": "phi", "sigma": 0.01,
     "run": ["--t-end", "10", "--samples", "999"], "outliers": 0.05,
     "label": "damped_pendulum, 5 % outliers, least squares",
     "free": [("l", 1.0, 1.3, "0.1:10"), ("c", 0.2, 0.75, "0:2")]},
    {"name": "damped_pendulum_huber", "file": "models/damped_pendulum.toml", "column": "phi", "sigma": 0.01,
     "run": ["--t-end", "10", "--samples", "999"], "outliers": 0.05, "loss": "huber:0.03",
     "label": "damped_pendulum, 5 % outliers, `--loss huber:0.03`",
     "free": [("l", 1.0, 1.3, "0.1:10"), ("c", 0.2, 0.75, "0:2")]},
]


def truth(eomgen, model, work):
    path = os.path.join(work, f"truth_{model['name']}.csv")
    subprocess.run([eomgen, "run", os.path.join(ROOT, model["file"]), "--rtol", "1e-12", "--atol", "1e-14", "--csv",
                    path, "--quiet"] + model["run"], check=True, stdout=subprocess.DEVNULL)
    rows = list(csv.reader(open(path)))
    header = [h.split(" [")[0] for h in rows[0]]
    t, q = header.index("t"), header.index(model["column"])
    return rows[0][q], [(float(r[t]), float(r[q])) for r in rows[1:]]


def fit(eomgen, model, data_path, jacobian="sensitivities", extra=()):
    args = [eomgen, "fit", os.path.join(ROOT, model["file"]), data_path, "--format", "json", "--quiet",
            "--jacobian", jacobian, "--loss", model.get("loss", "squared")]
    for name, value, start, bounds in model["free"]:
        args += ["--free", f"{name}={value * start:.6g}:{bounds}"]
    for spec in extra:
        args += ["--free", spec]
    p = subprocess.run(args, capture_output=True, text=True)
    if p.returncode not in (0, 5):
        raise RuntimeError(f"eomgen fit failed ({p.returncode}): {p.stdout}{p.stderr}")
    return json.loads(p.stdout)


def measure(cfg, work, smoke, log):
    eomgen = cfg["eomgen"]
    trials = 3 if smoke else 100
    out = {"trials": trials, "models": {}, "timing": {}}
    for model in MODELS:
        log(f"10. fit coverage: {model['name']}, {trials} trials")
        header, series = truth(eomgen, model, work)
        inside = {name: 0 for name, *_ in model["free"]}
        values = {name: [] for name, *_ in model["free"]}
        errors = {name: [] for name, *_ in model["free"]}
        both, converged, iterations = 0, 0, []
        for trial in range(trials):
            rng = random.Random(trial)
            path = os.path.join(work, f"fit_{model['name']}_{trial}.csv")
            with open(path, "w") as fh:
                fh.write(f"t [s],{header}\n")
                for t, q in series:
                    y = q + rng.gauss(0.0, model["sigma"])
                    if model.get("outliers") and rng.random() < model["outliers"]:
                        y += rng.choice((-1.0, 1.0)) * rng.uniform(0.2, 0.5)
                    fh.write(f"{t!r},{y:.9g}\n")
            r = fit(eomgen, model, path)
            converged += bool(r["converged"])
            iterations.append(r["iterations"])
            all_in = True
            for e, (name, value, *_rest) in zip(r["estimates"], model["free"]):
                ok = e["standard_error"] is not None and abs(e["value"] - value) <= 2 * e["standard_error"]
                values[name].append(e["value"])
                if e["standard_error"] is not None:
                    errors[name].append(e["standard_error"])
                inside[name] += ok
                all_in = all_in and ok
            both += all_in
            os.remove(path)
        # How far the estimates scatter against the errors reported for them (calibrated: a ratio near 1), and
        # their mean offset from the truth in reported errors.
        spread = {}
        for name, value, *_rest in model["free"]:
            sd = statistics.stdev(values[name]) if len(values[name]) > 1 else float("nan")
            se = statistics.mean(errors[name]) if errors[name] else float("nan")
            spread[name] = {"scatter": sd, "reported": se,
                            "bias": (statistics.mean(values[name]) - value) / se if errors[name] else float("nan")}
        out["models"][model["name"]] = {"inside": inside, "all_inside": both, "converged": converged, "spread": spread,
                                        "samples": len(series), "sigma": model["sigma"],
                                        "mean_iterations": sum(iterations) / len(iterations)}
    log("10. fit time: sensitivities against central differences")
    model = MODELS[0]
    data = os.path.join(ROOT, "examples", "fit", "damped_pendulum_data.csv")
    # Two unknowns (l, c), then four (the initial angle and rate as well).
    for unknowns, extra in ((2, ()), (4, ("x0:phi=0.9", "x0:phi_dot=0.1"))):
        for jacobian in ("sensitivities", "differences"):
            best = None
            for _ in range(1 if smoke else 5):
                r = fit(eomgen, model, data, jacobian, extra)
                if best is None or r["solve_seconds"] < best["solve_seconds"]:
                    best = r
            out["timing"][f"{jacobian}/{unknowns}"] = {
                "seconds": best["solve_seconds"], "iterations": best["iterations"],
                "integrations": best["integrations"], "estimates": [e["value"] for e in best["estimates"]]}
    return out


def render(results, command, date, machine_line):
    r = results
    lines = ["## 10. Fitting: calibrated standard errors, and the exact Jacobian's cost (issue 34)", "",
             f"Measured by `{command}` on {date} (bench/fit.py). {machine_line}", "",
             f"Coverage: {r['trials']} synthetic data sets per model (the model's trajectory plus Gaussian noise, a "
             "seed per trial), each fitted by `eomgen fit` from a start 20-30 % off; the share of trials whose true "
             "value lies within the reported 2 standard errors (calibrated errors give about 95 %; the issue's "
             "target is 90-98 %). 'Reported error / scatter' is the mean reported standard error over the standard "
             "deviation of the estimates across the trials (calibrated: near 1); 'mean offset' the estimates' mean "
             "distance from the truth in reported errors.", "",
             "| model | samples | noise | free | within 2 σ | all free within 2 σ | reported error / scatter | mean offset | converged | mean iterations |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for model in MODELS:
        m = r["models"].get(model["name"])
        if not m:
            continue
        free = ", ".join(name for name, *_ in model["free"])
        within = ", ".join(f"{name} {100.0 * m['inside'][name] / r['trials']:.0f} %" for name, *_ in model["free"])
        spread = m.get("spread", {})
        ratio = ", ".join(f"{name} {spread[name]['reported'] / spread[name]['scatter']:.2f}" for name, *_ in model["free"]
                          if name in spread)
        offset = ", ".join(f"{name} {spread[name]['bias']:+.2f} σ" for name, *_ in model["free"] if name in spread)
        lines.append(f"| {model.get('label', model['name'])} | {m['samples']} of {model['column']} | {m['sigma']:g} rad | {free} | "
                     f"{within} | {100.0 * m['all_inside'] / r['trials']:.0f} % | {ratio} | {offset} | "
                     f"{m['converged']}/{r['trials']} | {m['mean_iterations']:.1f} |")
    ls, hu = r["models"].get("damped_pendulum_outliers"), r["models"].get("damped_pendulum_huber")
    if ls and hu:
        sizes = "; ".join(f"{name} {ls['spread'][name]['reported']:.3g} by least squares, "
                          f"{hu['spread'][name]['reported']:.3g} with Huber's loss "
                          f"({ls['spread'][name]['reported'] / hu['spread'][name]['reported']:.1f}× smaller)"
                          for name in ("l", "c"))
        lines += ["", "With 5 % of the samples thrown off by 0.2-0.5 rad both are calibrated, least squares because "
                  "the outliers inflate its residuals' variance; the mean reported standard errors: " + sizes + "."]
    per = lambda t: t["seconds"] / max(t["iterations"], 1)  # noqa: E731
    lines += ["",
              "Time: the damped pendulum from examples/fit/damped_pendulum_data.csv (1,000 samples), with l and c "
              "free, then with the initial angle and rate as well; Ceres' own time (the integrations included, not "
              f"the process's start), best of {2 if r['trials'] <= 5 else 5}:", "",
              "| unknowns | Jacobian | seconds | iterations | integrations | seconds per iteration | l | c |",
              "|---|---|---|---|---|---|---|---|"]
    ratios = {}
    for k in (2, 4):
        s, d = r["timing"][f"sensitivities/{k}"], r["timing"][f"differences/{k}"]
        ratios[k] = per(d) / per(s)
        for name, t in (("sensitivities (exact)", s), ("central differences", d)):
            lines.append(f"| {k} | {name} | {t['seconds']:.3f} | {t['iterations']} | {t['integrations']} | "
                         f"{per(t):.4f} | {t['estimates'][0]:.10g} | {t['estimates'][1]:.10g} |")
    s2 = r["timing"]["sensitivities/2"]
    lines += ["",
              f"The fit of l and c takes {s2['seconds']:.3f} s (target: under 1 s). Per iteration the differences "
              f"cost {ratios[2]:.2f}× the sensitivities with 2 unknowns and {ratios[4]:.2f}× with 4: a Jacobian by "
              "differences is 2k + 1 plain integrations, one by sensitivities is one integration of the state with k "
              "columns of S (under the same error control, so with more steps).", ""]
    return "\n".join(lines)
