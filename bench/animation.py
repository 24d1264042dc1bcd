"""Section 12 of docs/benchmarks.md (issue 33): `eomgen run --animate` on a 20-link chain for 10 s at 60 frames per
second (the issue's target: the file at most 2 MB, drawn at the full frame rate in Chromium), beside the shipped
bicycle and heavy top. Called by bench.py (in the full run, and alone with --animation-only); the page's part
between the ANIMATION markers is written by render() from measure()'s results.

Measured, per model:
- the page's size in bytes, and the frames it holds;
- the time to draw each frame in headless Chromium (the page's own #bench: every frame drawn once and a pixel read
  back, which makes the canvas rasterize it, timed with performance.now(); software rendering, no GPU), its mean,
  95th percentile and largest, against the 16.7 ms a frame has at 60 frames per second;
- the wall time of the cached `eomgen run --animate` (the model compiled before, as a second run finds it).
"""
import json
import os
import re
import shutil
import subprocess
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


def chain_model(n):
    """An n-link planar chain of point masses with its drawing: the links through every joint, a dot at each mass."""
    lines = [f'name = "chain_{n}"', f'title = "{n}-link planar chain (bench/animation.py)"']
    for i in range(1, n + 1):
        lines += ["", "[[coordinates]]", f'name = "theta{i}"', f"initial = {0.3 + 0.5 * i / n}", "rate = 0.0"]
    for i in range(1, n + 1):
        lines += ["", "[[parameters]]", f'name = "m{i}"', "value = 1.0", "", "[[parameters]]", f'name = "l{i}"',
                  f"value = {1.0 / n}"]
    lines += ["", "[[parameters]]", 'name = "g"', "value = 9.81"]
    x = [" + ".join(f"l{k}*sin(theta{k})" for k in range(1, i + 1)) for i in range(1, n + 1)]
    y = [" + ".join(f"-l{k}*cos(theta{k})" for k in range(1, i + 1)) for i in range(1, n + 1)]
    xd = [" + ".join(f"l{k}*cos(theta{k})*theta{k}'" for k in range(1, i + 1)) for i in range(1, n + 1)]
    yd = [" + ".join(f"l{k}*sin(theta{k})*theta{k}'" for k in range(1, i + 1)) for i in range(1, n + 1)]
    T = " + ".join(f"1/2*m{i + 1}*(({xd[i]})^2 + ({yd[i]})^2)" for i in range(n))
    V = " + ".join(f"m{i + 1}*g*({y[i]})" for i in range(n))
    lines += ["", "[lagrangian]", f'T = "{T}"', f'V = "{V}"']
    points = ", ".join(['["0", "0"]'] + [f'["{x[i]}", "{y[i]}"]' for i in range(n)])
    lines += ["", "[[draw]]", f"link = [{points}]", 'colour = "#555555"']
    for i in range(n):
        lines += ["", "[[draw]]", f'point = ["{x[i]}", "{y[i]}"]', 'colour = "#d62728"']
    return "\n".join(lines) + "\n"


def chromium():
    for name in ("chromium", "chromium-browser"):
        if shutil.which(name):
            return shutil.which(name)
    return None


def draw_times(page, work):
    exe = chromium()
    if not exe:
        return None
    url = "file://" + os.path.abspath(page) + "#bench&size=960x640&probe"
    p = subprocess.run([exe, "--headless", "--no-sandbox", "--disable-gpu", "--window-size=1300,900",
                        "--virtual-time-budget=60000", "--user-data-dir=" + os.path.join(work, "chromium-profile"),
                        "--dump-dom", url], capture_output=True, text=True, timeout=600)
    m = re.search(r'<pre id="probe">([^<]*)</pre>', p.stdout)
    if not m:
        raise RuntimeError("the page wrote no probe: " + p.stderr[-2000:])
    probe = json.loads(m.group(1).replace("&quot;", '"').replace("&amp;", "&"))
    if probe["errors"]:
        raise RuntimeError(f"errors in {page}: {probe['errors']}")
    return probe["bench"]


def measure(cfg, work, smoke, log):
    eomgen = cfg["eomgen"]
    n = 5 if smoke else 20
    chain = os.path.join(work, f"chain_{n}.toml")
    with open(chain, "w") as fh:
        fh.write(chain_model(n))
    cases = [(f"{n}-link chain", chain, 10.0),
             ("Whipple bicycle", os.path.join(ROOT, "models", "whipple_bicycle.toml"), 10.0),
             ("heavy symmetric top", os.path.join(ROOT, "models", "heavy_symmetric_top.toml"), 10.0)]
    if smoke:
        # The bicycle's first run compiles its model (about 40 s of the smoke run on 2 cores); the chain and the top
        # take the same path through the page, and tests/animation draws the pages themselves.
        cases = [c for c in cases if c[0] != "Whipple bicycle"]
    out = []
    for name, model, t_end in cases:
        log(f"12. animation: {name}")
        page = os.path.join(work, os.path.basename(model).replace(".toml", ".html"))
        args = [eomgen, "run", model, "--t-end", str(t_end), "--fps", "60", "--animate", page, "--quiet"]
        subprocess.run(args, check=True, capture_output=True)  # compiled into the cache
        start = time.perf_counter()
        subprocess.run(args, check=True, capture_output=True)
        seconds = time.perf_counter() - start
        out.append({"model": name, "t_end": t_end, "bytes": os.path.getsize(page), "run_seconds": seconds,
                    "draw": draw_times(page, work)})
    return {"cases": out}


def render(r, command, date, machine_line):
    lines = ["## 12. Animation: the page's size and the time to draw a frame (issue 33)", "",
             f"Measured by `{command}` on {date}. {machine_line}", "",
             "Each model run for its t_end at 60 frames per second (`eomgen run MODEL --t-end T --fps 60 --animate "
             "P.html`, the model already compiled); every frame of the page then drawn once in headless Chromium "
             "(its own `#bench`: drawn and one pixel read back, so that the canvas rasterizes it; software rendering) "
             "at a 960 x 640 canvas. At 60 frames per second a frame has "
             "16.7 ms. The issue's targets for the 20-link chain: the file at most 2 MB, drawn at the full frame rate.",
             "", "| model | frames | page | run --animate (cached) | draw: mean | 95th percentile | largest |",
             "|---|---|---|---|---|---|---|"]
    for c in r["cases"]:
        d = c["draw"]
        draw = (f"{d['mean_ms']:.2f} ms | {d['p95_ms']:.2f} ms | {d['max_ms']:.2f} ms" if d else
                "no Chromium | | ")
        frames = d["frames"] if d else round(c["t_end"] * 60) + 1
        lines.append(f"| {c['model']} | {frames} | {c['bytes'] / 1e6:.2f} MB | {c['run_seconds']:.2f} s | {draw} |")
    return "\n".join(lines) + "\n"
