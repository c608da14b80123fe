#!/bin/sh
# Checks that `xvfb.sh stop` waits until the server has exited, not only until it stops looking like Xvfb.
#
#   validation/paraview/check_xvfb_slow_exit.sh WORK_DIR
#
# An exiting process loses its command line before it becomes a zombie. xvfb.sh stop once returned in that window
# and left Xvfb running (a CI run of 2026-11-26; 13 of 600 start-stop pairs of the real Xvfb on a loaded 2-core
# machine). Here a stand-in named Xvfb, first in PATH, gives itself Xvfb's command line (Perl's $0), writes a
# display number, and on SIGTERM takes another name and lives one more second, so the window is always hit. Passes
# when xvfb.sh stop returns only once the stand-in is gone. Needs no X server (Perl is part of every Debian).
#
# Exit status: 0 passed, 1 failed.
set -eu

[ $# -eq 1 ] || { echo "usage: $0 WORK_DIR" >&2; exit 2; }
work=$1
here=$(cd "$(dirname "$0")" && pwd)

rm -rf "$work"
mkdir -p "$work/bin"
cat > "$work/bin/Xvfb" <<'EOF'
#!/usr/bin/perl
# Stand-in for `Xvfb -displayfd 3 ...`: the command line xvfb.sh looks for, display 99 on fd 3, a slow exit.
use strict;
use warnings;
$0 = "Xvfb @ARGV";
my $stopping = 0;
$SIG{TERM} = sub { $stopping = 1 };
open(my $display_fd, '>&=', 3) or die "no fd 3: $!";
print {$display_fd} "99\n";
close($display_fd);
sleep 1 until $stopping;
$0 = "exiting";  # no longer Xvfb's command line, as an exiting process has none
sleep 1;
exit 0;
EOF
chmod +x "$work/bin/Xvfb"

. "$here/xvfb_stand_in.sh"
start_stand_in "$work" "the stand-in"
pid=$(cat "$work/server/pid")
sh "$here/xvfb.sh" stop "$work/server"
expect_gone "$pid" "the stand-in"
echo "passed: xvfb.sh stop waited for a server that exits a second after it loses Xvfb's command line"
