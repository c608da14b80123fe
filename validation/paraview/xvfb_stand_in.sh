# Shared by the checks of xvfb.sh that put a stand-in named Xvfb first in PATH (check_xvfb_slow_start.sh,
# check_xvfb_slow_exit.sh). Sourced by them; `here` is the folder of xvfb.sh.

# start_stand_in WORK_DIR WHAT: xvfb.sh start with WORK_DIR/bin first in PATH, its server in WORK_DIR/server; WHAT
# names the stand-in in the message. A failed start leaves the stand-in running; it must not outlive the test
# (`|| true`: under set -e a kill of a process already gone would end the script here, before it says why it failed).
start_stand_in() {
  status=0
  PATH="$1/bin:$PATH" sh "$here/xvfb.sh" start "$1/server" || status=$?
  if [ "$status" -ne 0 ]; then
    if [ -f "$1/server/pid" ]; then kill "$(cat "$1/server/pid")" 2>/dev/null || true; fi
    echo "FAIL: xvfb.sh start exited $status on $2" >&2
    exit 1
  fi
}

# expect_gone PID WHAT: fails the check when process PID (WHAT, in the message) still runs, and is not a zombie, after
# xvfb.sh stop.
expect_gone() {
  if [ -d "/proc/$1" ] && ! grep -q '^[^)]*) Z' "/proc/$1/stat" 2>/dev/null; then
    echo "FAIL: $2 $1 still running after xvfb.sh stop" >&2
    kill -9 "$1" 2>/dev/null || true
    exit 1
  fi
}
