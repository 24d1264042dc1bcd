#!/bin/bash
# Regenerates the checker's part of the seed reports in docs/checks/ (what cli:check_report_* compares), keeping
# each report's first part, written by hand, up to its "## Check of" heading. The entries are those of
# tests/checker/CMakeLists.txt. Usage: scripts/regenerate_checks.sh [EOMGEN] (default build/generator/eomgen).
set -euo pipefail
cd "$(dirname "$0")/.."
eomgen=${1:-build/generator/eomgen}
seed=../shared/seed/000_e6b9f63eaa50a64e.txt
[ -f "$seed" ] || { echo "seed text $seed not found" >&2; exit 3; }
while IFS='|' read -r model section map report; do
  args=(check "models/$model.toml" "$seed" --section "$section" --format markdown)
  [ -n "$map" ] && args+=(--map-file "docs/checks/$map.map.toml")
  out="docs/checks/$report.md"
  hand=$(sed -n '/^## Check of/q;p' "$out")
  generated=$("$eomgen" "${args[@]}" | sed 's/^#/##/') || true
  printf '%s\n\n%s\n' "$hand" "$generated" > "$out.tmp" && mv "$out.tmp" "$out"
done <<'LIST'
door|Exercise 30|door|seed_door_ex30
pendulum_5_20|5-20|pendulum_5_20|seed_pendulum_5_20
torque_free_top|Derivation 5-6|torque_free_top|seed_torque_free_top_5_6
triangle_plate_5_15|Exercise 5-15||seed_triangle_plate_5_15
rolling_cone|5-17|rolling_cone|seed_rolling_cone_5_17
dumbbell_5_18|Exercise 5-18|dumbbell_5_18|seed_dumbbell_5_18
rolling_sphere|Exercise 25|rolling_sphere|seed_rolling_sphere_25
LIST
