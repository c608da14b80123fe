#!/bin/sh
# Render a heliostand output series to PNGs with ParaView, headless, then check the images.
#
#   validation/paraview/render.sh STAND_PVD OUT_DIR [AGE ...]
#
# Renders the first and last output year, or the listed stand ages (render_stand.py). pvbatch, xvfb
# and the exit statuses: run_pvbatch.sh (0 rendered and checked, 1 failed, 2 usage, 77 no ParaView).
set -eu

if [ $# -lt 2 ]; then
  echo "usage: $0 STAND_PVD OUT_DIR [AGE ...]" >&2
  exit 2
fi
pvd=$1
out_dir=$2
shift 2
here=$(cd "$(dirname "$0")" && pwd)
[ -f "$pvd" ] || { echo "error: $pvd: no such file" >&2; exit 2; }
exec sh "$here/run_pvbatch.sh" "$here/render_stand.py" "$out_dir" "$pvd" "$out_dir" "$@"
