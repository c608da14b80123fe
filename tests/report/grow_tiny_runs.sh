#!/bin/sh
# Grows the two runs the report tests draw: the tiny stand as its scenario says (tree 4 thinned at age 23) into
# OUT/tiny-thinned, and an unthinned control into OUT/tiny-unthinned (the same scenario without its [[thinning]]
# block, which is the last one in the file; the survey is copied beside it because the scenario names it relatively).
#   grow_tiny_runs.sh HELIOSTAND SOURCE_DIR OUT
set -eu
heliostand=$1 tiny=$2/stands/tiny out=$3
unthinned=$out/unthinned-scenario
mkdir -p "$unthinned"
cp "$tiny/survey.csv" "$unthinned/"
sed '/^\[\[thinning\]\]/,$d' "$tiny/scenario.toml" > "$unthinned/scenario.toml"
if grep -q '^ *\[\[thinning' "$unthinned/scenario.toml"; then
  echo "error: $unthinned/scenario.toml still thins" >&2
  exit 1
fi
"$heliostand" grow "$tiny/scenario.toml" --out "$out/tiny-thinned" --force --no-vtk --device reference -q
"$heliostand" grow "$unthinned/scenario.toml" --out "$out/tiny-unthinned" --force --no-vtk --device reference -q
