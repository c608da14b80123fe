#!/bin/sh
# Run a ParaView Python script with pvbatch, headless (Xvfb), then check the PNGs it wrote.
#
#   validation/paraview/run_pvbatch.sh SCRIPT.py LOG_DIR [ARG ...]
#
# The script gets the ARGs; it must print the path of every PNG it writes, one per line (those are
# checked by check_png.py). Its output goes to LOG_DIR/render.log.
#
# X server: with HELIOSTAND_XVFB_DIR set (the render tests: one server per test run, started by a CTest
# fixture), the display that xvfb.sh wrote to that folder; otherwise a server of this run's own, started by
# xvfb.sh in LOG_DIR/xvfb and stopped (and waited for) on exit. xvfb.sh says why not xvfb-run.
#
# Needs the Debian packages `paraview xvfb` (install paraview with --no-install-recommends:
# its recommended python3-paraview conflicts with libvtk9-dev, which the build needs). pvbatch's
# Python modules come from python3-paraview, which this script therefore fetches with
# `apt-get download` (same version as the installed paraview) and unpacks with `dpkg -x` into a
# private folder, once: $HELIOSTAND_PARAVIEW_PYTHON, default ~/.cache/heliostand/python3-paraview-VERSION.
#
# Exit status: 0 rendered and checked, 1 rendering or check failed, 2 usage,
# 77 ParaView not available here (CTest reports the test as skipped; with CI=true this is an error).
set -eu

if [ $# -lt 2 ]; then
  echo "usage: $0 SCRIPT.py LOG_DIR [ARG ...]" >&2
  exit 2
fi
script=$1
log_dir=$2
shift 2
here=$(cd "$(dirname "$0")" && pwd)

skip() {
  # In CI (CI=true) a missing ParaView is a broken set-up, not a reason to skip.
  if [ "${CI:-}" = true ]; then
    echo "error: $* (CI=true: rendering is required)" >&2
    exit 1
  fi
  echo "skipped: $*" >&2
  exit 77
}

[ -f "$script" ] || { echo "error: $script: no such file" >&2; exit 2; }
pvbatch=$(command -v "${HELIOSTAND_PVBATCH:-pvbatch}") ||
  skip "pvbatch not found (apt-get install --no-install-recommends paraview xvfb xauth)"
# Resolve symlinks (/bin -> /usr/bin): pvbatch derives its Python path from its own location, and from
# /bin it would pick up python3-vtk9's vtkmodules instead of ParaView's and crash.
pvbatch=$(readlink -f "$pvbatch")
command -v Xvfb >/dev/null 2>&1 || skip "Xvfb not found (apt-get install xvfb)"

# pvbatch's Python side: the system one if python3-paraview happens to be installed, else a private copy.
if [ -f /usr/lib/python3/dist-packages/paraview/simple.py ]; then
  paraview_python=/usr/lib/python3/dist-packages
else
  version=$(dpkg-query -W -f='${Version}' paraview 2>/dev/null) || skip "the paraview package is not installed"
  cache=${XDG_CACHE_HOME:-$HOME/.cache}/heliostand
  private=${HELIOSTAND_PARAVIEW_PYTHON:-$cache/python3-paraview-$version}
  if [ ! -f "$private/usr/lib/python3/dist-packages/paraview/simple.py" ]; then
    echo "setting up pvbatch's Python modules (python3-paraview $version) in $private" >&2
    work=$(mktemp -d)
    trap 'rm -rf "$work"' EXIT
    (cd "$work" && apt-get download -q "python3-paraview=$version" >&2) ||
      skip "apt-get download python3-paraview=$version failed (no network or apt source?)"
    dpkg -x "$work"/python3-paraview_*.deb "$work/root"
    mkdir -p "$(dirname "$private")"
    rm -rf "$private"
    mv "$work/root" "$private"  # only a complete folder ever appears under the final name
    rm -rf "$work"
    trap - EXIT
  fi
  paraview_python=$private/usr/lib/python3/dist-packages
fi

mkdir -p "$log_dir"
log=$log_dir/render.log
if [ -n "${HELIOSTAND_XVFB_DIR:-}" ]; then
  [ -s "$HELIOSTAND_XVFB_DIR/display" ] ||
    { echo "error: no X display in $HELIOSTAND_XVFB_DIR/display (the xvfb fixture did not start)" >&2; exit 1; }
else
  export HELIOSTAND_XVFB_DIR="$log_dir/xvfb"
  # Stop our server on any exit, and wait until it is gone.
  trap 'sh "$here/xvfb.sh" stop "$HELIOSTAND_XVFB_DIR"' EXIT
  sh "$here/xvfb.sh" start "$HELIOSTAND_XVFB_DIR" >&2 || exit $?
fi
DISPLAY=$(cat "$HELIOSTAND_XVFB_DIR/display")
export DISPLAY

# pvbatch runs in the background so that an interrupt reaches this shell at once (sh defers traps until a
# foreground child ends); the interrupt stops pvbatch, and the EXIT trap then the X server.
PYTHONPATH=$paraview_python${PYTHONPATH:+:$PYTHONPATH} "$pvbatch" "$script" "$@" > "$log" 2>&1 &
pvbatch_pid=$!
trap 'kill "$pvbatch_pid" 2>/dev/null; exit 1' INT TERM HUP
wait "$pvbatch_pid" || {
  cat "$log" >&2
  echo "error: pvbatch failed (log above, also in $log)" >&2
  exit 1
}
images=$(grep '\.png$' "$log" || true)
[ -n "$images" ] || { cat "$log" >&2; echo "error: pvbatch wrote no image" >&2; exit 1; }
# shellcheck disable=SC2086  # one image path per word; the paths are ours and have no spaces
python3 "$here/check_png.py" $images
