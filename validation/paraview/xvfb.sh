#!/bin/sh
# Start or stop a headless X server (Xvfb) for pvbatch.
#
#   validation/paraview/xvfb.sh start DIR   start one; its display (":N") goes to DIR/display, its pid to DIR/pid
#   validation/paraview/xvfb.sh stop DIR    stop the server DIR/pid names and wait until it is gone
#
# The render tests share one server per test run (the CTest fixture in cmake/PvbatchRenderTests.cmake);
# run_pvbatch.sh, used by hand, starts and stops its own.
#
# Why not `xvfb-run -a` (issue 15's "bad X server connection" flake):
# - By default an X server resets when its last client disconnects, and closes every connection that arrives
#   while it resets. pvbatch opens and closes the display six times while it starts (display and OpenGL
#   checks), so under load one of its connections can land in a reset. Measured on a 2-core machine: a loop
#   that opens and closes a display 3,000 times fails 70 times against `Xvfb`, 0 times against `Xvfb -noreset`.
#   Neither xvfb-run nor the per-render -displayfd attempt that was reverted passed -noreset.
# - -displayfd: Xvfb picks a free display itself and writes its number only once it accepts connections,
#   so no number is guessed and no client meets a server that is not up yet.
#
# Exit status: 0 done, 1 failed, 2 usage, 77 Xvfb not installed (CTest: skipped; with CI=true this is an error).
set -eu

usage() { echo "usage: $0 start|stop DIR" >&2; exit 2; }
[ $# -eq 2 ] || usage
action=$1
dir=$2

# True while process PID exists and has not exited. One that has exited but was not yet reaped by its parent
# (a zombie) counts as gone: an Xvfb in that state has already removed its socket.
alive() {
  state=$(sed 's/^.*) //' "/proc/$1/stat" 2>/dev/null | cut -c1)
  [ -n "$state" ] && [ "$state" != Z ]
}

# True while PID is an Xvfb started by this script (not a reused pid) that has not exited yet.
running_xvfb() {
  [ -r "/proc/$1/cmdline" ] || return 1
  tr '\0' ' ' < "/proc/$1/cmdline" | grep -q '^Xvfb -displayfd ' || return 1
  alive "$1"
}

# When PID's process started (field 22 of /proc/PID/stat, counted after the command name): with the pid it names one
# process, also once that process has lost its command line.
started_at() { sed 's/^.*) //' "/proc/$1/stat" 2>/dev/null | cut -d' ' -f20; }

stop_server() {
  [ -f "$dir/pid" ] || return 0
  pid=$(cat "$dir/pid")
  if running_xvfb "$pid"; then
    born=$(started_at "$pid")
    kill "$pid" 2>/dev/null || true
    waited=0
    # Waits until the process is gone or a zombie, not until it stops looking like Xvfb: an exiting process loses its
    # command line before it becomes a zombie, and a stop that returned then left Xvfb running (a CI run of
    # 2026-11-26: check_xvfb_slow_start.sh; 13 of 600 start-stop pairs under load). The start time tells a reused pid.
    while alive "$pid" && [ "$(started_at "$pid")" = "$born" ]; do
      waited=$((waited + 1))
      if [ "$waited" -eq 100 ]; then
        echo "warning: Xvfb $pid still running 10 s after SIGTERM; killing it" >&2
        kill -9 "$pid" 2>/dev/null || true
      fi
      [ "$waited" -le 200 ] || { echo "error: Xvfb $pid would not stop" >&2; exit 1; }
      sleep 0.1
    done
  fi
  rm -f "$dir/pid" "$dir/display"
}

start_server() {
  if ! command -v Xvfb >/dev/null 2>&1; then
    if [ "${CI:-}" = true ]; then
      echo "error: Xvfb not found (apt-get install xvfb) (CI=true: rendering is required)" >&2
      exit 1
    fi
    echo "skipped: Xvfb not found (apt-get install xvfb)" >&2
    exit 77
  fi
  mkdir -p "$dir"
  stop_server  # one left over from an interrupted test run
  number_file=$dir/display.number
  : > "$number_file"
  # Xvfb's output goes to a file, not to our stdout: CTest would otherwise wait for the server to exit.
  Xvfb -displayfd 3 -noreset -nolisten tcp -screen 0 1600x1200x24 \
    3>"$number_file" </dev/null >"$dir/xvfb.log" 2>&1 &
  echo $! > "$dir/pid"
  waited=0
  # Xvfb writes the number, then a newline, once it accepts connections. Until then the process is only asked
  # to be alive, not to be Xvfb yet: between the fork and the exec it is still this shell (its command line is
  # this script's), and asking for Xvfb's there failed a CI run (2026-11-24; check_xvfb_slow_start.sh
  # makes that window a second long).
  until [ "$(wc -l < "$number_file")" -ge 1 ]; do
    alive "$(cat "$dir/pid")" || { cat "$dir/xvfb.log" >&2; echo "error: Xvfb did not start" >&2; exit 1; }
    waited=$((waited + 1))
    [ "$waited" -le 600 ] || { stop_server; echo "error: Xvfb gave no display within 60 s" >&2; exit 1; }
    sleep 0.1
  done
  echo ":$(tr -d '[:space:]' < "$number_file")" > "$dir/display"
  rm -f "$number_file"
  echo "Xvfb $(cat "$dir/pid") on display $(cat "$dir/display") (-noreset)"
}

case $action in
  start) start_server ;;
  stop) stop_server ;;
  *) usage ;;
esac
