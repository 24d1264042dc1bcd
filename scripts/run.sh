#!/usr/bin/env bash
# The main job: set up, regenerate every model into generated/, show what was derived, simulate the
# door (Ex. 30) and the plane pendulum (5-20), run a model file that is compiled into nothing
# (eomgen run, with its plot) and write its report (eomgen report), and print the results. CSV, PNG and
# Markdown output goes to out/.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/ccache_env.sh
# Only what the main job runs: eomgen, eomgen-sim (with the models) and the door's example. The test command
# (scripts/test.sh) builds the rest: the suite, the fuzz harnesses' standalone runs and the benchmarks.
bash scripts/setup.sh --no-build
build="${EOMGEN_BUILD_DIR:-build}"
cmake --build "$build" -j "$(nproc)" --target eomgen eomgen-sim door_closing
mkdir -p out

echo "== eomgen generate models/*.toml -o generated"
"$build/generator/eomgen" generate models/*.toml -o generated
git status --short generated 2>/dev/null | sed 's/^/   changed: /' || true

for model in models/door.toml models/pendulum_5_20.toml; do
  echo
  echo "== eomgen show $model"
  "$build/generator/eomgen" show "$model"
done

echo
echo "== the door closing: simulated with event location vs the closed form"
"$build/examples/door_closing"

echo
echo "== eomgen-sim door --until psi=-pi/2"
"$build/simulator/eomgen-sim" door --until psi=-pi/2 --t-end 100 --rtol 1e-12 --atol 1e-14 --csv out/door.csv

echo
echo "== eomgen-sim pendulum_5_20, 100 s, dopri5 at rtol 1e-12"
"$build/simulator/eomgen-sim" pendulum_5_20 --t-end 100 --rtol 1e-12 --atol 1e-14 --init theta_dot=0.5 \
  --init phi_dot=2 --csv out/pendulum_5_20.csv

echo
echo "== eomgen-sim pendulum_5_20, 1000 s, symplectic (variational midpoint) at dt = 0.01"
"$build/simulator/eomgen-sim" pendulum_5_20 --t-end 1000 --method symplectic --dt 0.01 --init theta_dot=0.5 \
  --init phi_dot=2 --csv out/pendulum_5_20_symplectic.csv

echo
echo "== eomgen show models/rolling_sphere.toml (constraints, multipliers, integrability)"
"$build/generator/eomgen" show models/rolling_sphere.toml | sed -n '/^Constraints/,/^Energy function/p'

echo
echo "== eomgen-sim rolling_sphere, 200 s: invariants and constraint residuals (CSV: out/rolling_sphere.csv)"
"$build/simulator/eomgen-sim" rolling_sphere --t-end 200 --samples 400 --rtol 1e-12 --atol 1e-14 \
  --csv out/rolling_sphere.csv

echo
echo "== eomgen-sim dumbbell_5_18: the drive's torque (multiplier of 'tilt') = -2 m l^2 omega^2 sin(theta) cos(theta)"
"$build/simulator/eomgen-sim" dumbbell_5_18 --t-end 5 | grep -E "multiplier|residuals"

echo
echo "== eomgen show models/dumbbell_5_18_bodies.toml: Euler's equations of the dumbbell as a rigid body"
"$build/generator/eomgen" show models/dumbbell_5_18_bodies.toml | sed -n "/^Euler's equations/,/^Energies/p"

echo
echo "== eomgen-sim torque_free_top, 40 s (Derivation 5-6): theta stays 0.5, phi' = I3 w3/(I cos theta) = 3/cos(0.5)"
"$build/simulator/eomgen-sim" torque_free_top --t-end 40 --rtol 1e-12 --atol 1e-14 --csv out/torque_free_top.csv \
  | grep -E "^  (theta|phi_dot|psi_dot) =|energy"

echo
echo "== eomgen-sim rolling_cone until the line of contact has gone half round (5-17)"
"$build/simulator/eomgen-sim" rolling_cone --until phi=pi --t-end 10 --rtol 1e-12 --atol 1e-14 \
  | grep -E "event|residuals|multiplier|energy"

echo
echo "== eomgen run examples/bead_on_hoop.toml: a model file compiled into nothing, derived, compiled (cached"
echo "   in \${XDG_CACHE_HOME:-~/.cache}/eomgen) and integrated; the plot is out/bead_on_hoop.png, the animation"
echo "   (open it in a browser: the hoop turning, the bead on it) out/bead_on_hoop.html"
"$build/generator/eomgen" run examples/bead_on_hoop.toml --t-end 10 --rtol 1e-12 --atol 1e-14 \
  --csv out/bead_on_hoop.csv --plot out/bead_on_hoop.png --plot-phase a --plot-xy rho,z \
  --animate out/bead_on_hoop.html

echo
echo "== eomgen report examples/bead_on_hoop.toml: the equations, the simulation with its plot and the drift of"
echo "   each invariant, in one Markdown file: out/bead_on_hoop-report/bead_on_hoop.md"
"$build/generator/eomgen" report examples/bead_on_hoop.toml -o out/bead_on_hoop-report --t-end 10 --quiet
sed -n '/^| invariant/,/^$/p' out/bead_on_hoop-report/bead_on_hoop.md
