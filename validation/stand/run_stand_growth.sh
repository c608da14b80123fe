#!/bin/sh
# Grow a stand drawn from the silver-fir yield table three ways (thinned as the table, never thinned, thinned
# once heavily from below at 40) and judge them (check_stand_growth.py). CTest runs it at a small size.
#   run_stand_growth.sh HELIOSTAND OUT_DIR [TREES] [SEED] [extra make_yield_stand.py options...]
# The light numerics of the small size (8 x 16 sky patches, 2 m exact cut-off) are set here: the full-size
# figures in docs/model.md use the defaults of their day (16 x 32 sky, 4 m cut-off; 3 m since 2026-11-24) and
# more trees.
set -eu
heliostand=$1
out=$2
trees=${3:-100}
seed=${4:-1}
shift 2; [ $# -gt 0 ] && shift; [ $# -gt 0 ] && shift
here=$(cd "$(dirname "$0")" && pwd)
table=$here/yield_table.csv
mkdir -p "$out"
for run in thinned unthinned heavy; do
  case $run in
    thinned) how= ;;
    unthinned) how=--unthinned ;;
    heavy) how="--heavy-thinning 40 1600" ;;
  esac
  # shellcheck disable=SC2086
  python3 "$here/make_yield_stand.py" "$table" "$out/$run" $how --trees "$trees" --seed "$seed" \
    --species "$here/silver_fir.toml" --light "sky_bands = 8" --light "sky_sectors = 16" --light "cutoff_m = 2.0" "$@"
  "$heliostand" grow "$out/$run/scenario.toml" --out "$out/$run/out" --force --no-vtk -q
done
python3 "$here/check_stand_growth.py" "$table" "$out/thinned/out" "$out/unthinned/out" "$out/heavy/out" 40 \
  "$out/stand_growth.md"
