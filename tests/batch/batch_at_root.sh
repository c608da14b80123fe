#!/bin/sh
# batch_at_root.sh ROOT FINAL START COMMAND...: runs COMMAND (a `heliostand batch ... --out ROOT`) and moves ROOT
# to FINAL. Every batch of the comparison runs at the same ROOT, because each run's run.json records the absolute
# path of the scenario it read (ROOT/inputs/...): at one path that field, too, must come out the same.
# START is "fresh" (ROOT starts absent) or a finished batch's folder to copy to ROOT first (a restart).
set -u
root=$1 final=$2 start=$3
shift 3
rm -rf "$root" "$final"
[ "$start" = fresh ] || cp -r "$start" "$root" || exit 1
"$@"
status=$?
mv "$root" "$final" || exit 1
exit $status
