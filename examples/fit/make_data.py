#!/usr/bin/env python3
"""The worked example of docs/sensitivities.md, "Fitting": measurements of the damped pendulum
(models/damped_pendulum.toml) with l = 1 m and c = 0.2 N m s, 1,000 samples of phi over 10 s with Gaussian noise of
0.01 rad (1 % of its first swing), seed 1. Made by `eomgen run`; run from the repository root:

    python3 examples/fit/make_data.py build/generator/eomgen > examples/fit/damped_pendulum_data.csv
"""
import csv
import os
import random
import subprocess
import sys
import tempfile


def main():
    eomgen = sys.argv[1] if len(sys.argv) > 1 else "eomgen"
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "truth.csv")
        subprocess.run([eomgen, "run", "models/damped_pendulum.toml", "--t-end", "10", "--samples", "999",
                        "--rtol", "1e-12", "--atol", "1e-14", "--csv", path, "--quiet"],
                       check=True, stdout=subprocess.DEVNULL)
        rows = list(csv.reader(open(path)))
    header = rows[0]
    t, phi = header.index("t [s]"), header.index("phi [rad]")
    rng = random.Random(1)
    out = csv.writer(sys.stdout, lineterminator="\n")
    out.writerow(["t [s]", "phi [rad]"])
    for row in rows[1:]:
        out.writerow([row[t], "%.6f" % (float(row[phi]) + rng.gauss(0.0, 0.01))])


if __name__ == "__main__":
    main()
