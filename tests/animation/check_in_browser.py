#!/usr/bin/env python3
"""The animation page in a real browser (issue 33): headless Chromium opens what `eomgen run --animate` wrote,
the player must load without errors, and at two times the drawn position of a point must match the trajectory.

The trajectory is the run's CSV; the point's position is computed here from the coordinates, by the formula the
test is given (a Python expression in the CSV's columns and the model's parameters), and taken to the screen by
the view the page reports (its scale and centre, docs/animation.md). Two checks per time:
  - the page's own record of where it drew the point (its probe) is within 1 pixel of that position;
  - in a screenshot, the centroid of the pixels of the point's colour is within 1 pixel of it.
The screenshots stay in the work directory for a person to look at.

Usage: check_in_browser.py EOMGEN MODEL WORKDIR LABEL COLOUR X_EXPR Y_EXPR [--z=Z_EXPR] [eomgen run options...]
Exit 77 (a skipped test for ctest) where no Chromium is installed."""
import json
import math
import os
import re
import shutil
import struct
import subprocess
import sys
import zlib

SKIP = 77


def chromium():
    for name in ("chromium", "chromium-browser", "google-chrome"):
        path = shutil.which(name)
        if path:
            return path
    return None


def browser(exe, url, extra, workdir):
    # --no-sandbox: the tests run as root in CI containers, where Chromium's sandbox cannot start.
    args = [exe, "--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars", "--window-size=1000,800",
            "--force-device-scale-factor=1", "--virtual-time-budget=3000", "--enable-logging=stderr", "--v=0",
            "--user-data-dir=" + os.path.join(workdir, "chromium-profile")] + extra + [url]
    r = subprocess.run(args, capture_output=True, text=True, timeout=120)
    return r


def console_errors(stderr):
    """Messages the page logged as errors or uncaught exceptions."""
    return [line for line in stderr.splitlines() if "CONSOLE" in line and ("rror" in line or "Uncaught" in line)]


def read_png(path):
    """(width, height, rows of (r, g, b) tuples) of an 8-bit RGB or RGBA, non-interlaced PNG."""
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    pos, idat = 8, b""
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            assert depth == 8 and colour in (2, 6) and interlace == 0, "unsupported PNG layout"
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    channels = 4 if colour == 6 else 3
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, prev = [], bytearray(stride)
    for y in range(height):
        f = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b = prev[i]
            c = prev[i - channels] if i >= channels else 0
            if f == 1:
                line[i] = (line[i] + a) & 255
            elif f == 2:
                line[i] = (line[i] + b) & 255
            elif f == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append([tuple(line[x * channels:x * channels + 3]) for x in range(width)])
        prev = line
    return width, height, rows


def main():
    if len(sys.argv) < 8:
        print(__doc__, file=sys.stderr)
        return 2
    eomgen, model, workdir, label, colour, x_expr, y_expr = sys.argv[1:8]
    run_options = sys.argv[8:]
    z_expr = "0"
    if run_options and run_options[0].startswith("--z="):
        z_expr = run_options.pop(0)[4:]
    exe = chromium()
    if not exe:
        print("skipped: no Chromium (apt-get install chromium) to open the animation in")
        return SKIP
    os.makedirs(workdir, exist_ok=True)
    page = os.path.join(workdir, "animation.html")
    csv = os.path.join(workdir, "samples.csv")
    subprocess.run([eomgen, "run", model, "--animate", page, "--csv", csv, "--quiet"] + run_options, check=True,
                   stdout=subprocess.DEVNULL)
    # The trajectory, and the parameters' default values as the model file gives them (plain numbers).
    lines = open(csv).read().splitlines()
    header = [re.sub(r" \[.*\]$", "", h) for h in lines[0].split(",")]
    rows = [[float(v) for v in line.split(",")] for line in lines[1:] if line]
    params = {}
    text = open(model).read()
    for name, value in re.findall(r'\[\[parameters\]\]\s*name\s*=\s*"(\w+)"\s*value\s*=\s*([-+0-9.eE]+)', text):
        params[name] = float(value)
    env = dict(vars(math))
    env.update(params)
    want_rgb = tuple(int(colour[i:i + 2], 16) for i in (1, 3, 5))
    failures = []
    for k in (len(rows) // 3, (2 * len(rows)) // 3):
        row = dict(zip(header, rows[k]))
        t = row["t"]
        scope = dict(env)
        scope.update(row)
        x, y, z = (eval(e, {"__builtins__": {}}, scope) for e in (x_expr, y_expr, z_expr))
        url = "file://" + os.path.abspath(page) + "#t=%.17g&size=720x480&probe" % t
        r = browser(exe, url, ["--dump-dom"], workdir)
        m = re.search(r'<pre id="probe">([^<]*)</pre>', r.stdout)
        if not m:
            failures.append("t = %g: the page wrote no probe (did the player load?)\n%s" % (t, r.stderr[-2000:]))
            continue
        probe = json.loads(m.group(1).replace("&quot;", '"').replace("&amp;", "&"))
        errors = probe["errors"] + console_errors(r.stderr)
        if errors:
            failures.append("t = %g: errors in the page: %s" % (t, errors))
        if abs(probe["t"] - t) > 1e-9:
            failures.append("t = %g: the page shows frame %d at t = %g" % (t, probe["frame"], probe["t"]))
        view, canvas = probe["view"], probe["canvas"]
        # The trajectory's point on the canvas, by the page's view (its right and up directions in space)
        c, s = view["centre"], view["scale"]
        d = [x - c[0], y - c[1], z - c[2]]
        sx = canvas["width"] / 2 + view["pan"][0] + s * sum(a * b for a, b in zip(d, view["right"]))
        sy = canvas["height"] / 2 + view["pan"][1] - s * sum(a * b for a, b in zip(d, view["up"]))
        drawn = [p for p in probe["points"] if p["label"] == label]
        if len(drawn) != 1:
            failures.append("t = %g: the page drew %d points labelled %s" % (t, len(drawn), label))
            continue
        gap = math.hypot(drawn[0]["x"] - sx, drawn[0]["y"] - sy)
        print("t = %.4f: point %s at (%.2f, %.2f) px by the trajectory, drawn at (%.2f, %.2f): %.3f px"
              % (t, label, sx, sy, drawn[0]["x"], drawn[0]["y"], gap))
        if gap > 1.0:
            failures.append("t = %g: drawn %.2f px away from the trajectory" % (t, gap))
        shot = os.path.join(workdir, "t%.3f.png" % t)
        browser(exe, url, ["--screenshot=" + shot], workdir)
        width, height, pixels = read_png(shot)
        hits = [(px, py) for py in range(height) for px in range(width) if pixels[py][px] == want_rgb]
        if not hits:
            failures.append("t = %g: no pixel of colour %s in the screenshot %s" % (t, colour, shot))
            continue
        cx = sum(p[0] for p in hits) / len(hits) + 0.5 - canvas["left"]
        cy = sum(p[1] for p in hits) / len(hits) + 0.5 - canvas["top"]
        gap = math.hypot(cx - sx, cy - sy)
        print("t = %.4f: in the screenshot (%s), %d pixels of %s centred at (%.2f, %.2f): %.3f px"
              % (t, shot, len(hits), colour, cx, cy, gap))
        if gap > 1.0:
            failures.append("t = %g: the screenshot's point is %.2f px away from the trajectory" % (t, gap))
    for f in failures:
        print("FAILED: " + f, file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
