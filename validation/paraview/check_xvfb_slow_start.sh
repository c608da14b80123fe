#!/bin/sh
# Checks that xvfb.sh waits for an X server whose process is slow to become Xvfb.
#
#   validation/paraview/check_xvfb_slow_start.sh WORK_DIR
#
# xvfb.sh starts Xvfb in the background and waits for its display number. Between the fork and the exec the
# background process is still the shell; xvfb.sh once took that for a server that had died ("error: Xvfb did not
# start", a CI run of 2026-11-24). The window is microseconds there; here a stand-in named Xvfb, first in PATH,
# sleeps a second before it becomes the real Xvfb, so the window is always hit. Passes when xvfb.sh starts it,
# writes its display, and stops it again.
#
# Exit status: 0 passed, 1 failed, 77 Xvfb not installed (CTest: skipped; with CI=true this is an error).
set -eu

[ $# -eq 1 ] || { echo "usage: $0 WORK_DIR" >&2; exit 2; }
work=$1
here=$(cd "$(dirname "$0")" && pwd)

if ! command -v Xvfb >/dev/null 2>&1; then
  if [ "${CI:-}" = true ]; then echo "error: Xvfb not found (apt-get install xvfb)" >&2; exit 1; fi
  echo "skipped: Xvfb not found (apt-get install xvfb)" >&2
  exit 77
fi

rm -rf "$work"
mkdir -p "$work/bin"
# The stand-in execs the real server under the name Xvfb, so that its command line is the one xvfb.sh looks for.
cat > "$work/bin/Xvfb" <<EOF
#!/bin/sh
sleep 1
PATH='$PATH' exec Xvfb "\$@"
EOF
chmod +x "$work/bin/Xvfb"

. "$here/xvfb_stand_in.sh"
start_stand_in "$work" "a server that takes a second to exec"
server=$work/server
display=$(cat "$server/display")
pid=$(cat "$server/pid")
sh "$here/xvfb.sh" stop "$server"
case $display in
  :[0-9]*) ;;
  *) echo "FAIL: display '$display' is not :N" >&2; exit 1 ;;
esac
expect_gone "$pid" Xvfb
echo "passed: Xvfb started on $display after a 1 s exec delay and stopped"
