#!/bin/sh
# Mutation harness: applies each documented break of the model (docs/model.md, docs/roots.md, docs/light.md:
# "broken once on purpose") to a copy of the committed sources, builds only the targets its checks need, runs the
# checks and reports whether they caught it (failed). Every break must be caught.
#   validation/mutations/run.sh [WORK_DIR] [NAME...]
# WORK_DIR (default build-mutations/ in the checkout) holds the copy (tree/) and its build (tree/build/, laid out
# like the checkout's build/ so ccache shares the compiled objects); NAMEs pick mutations from mutations.tsv (all
# by default). The unmutated checks run first: a break only counts as caught if they pass without it. Writes
# WORK_DIR/result.md and exits 1 when a check fails unmutated or a break is not caught. Too slow for CI on 2 cores
# (docs/model.md "Mutation harness" has the last result).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/../.." && pwd)
work=${1:-$repo/build-mutations}
[ $# -gt 0 ] && shift
mkdir -p "$work"
work=$(cd "$work" && pwd)
tree=$work/tree
# git apply inside WORK_DIR must not find the checkout's repository (it would patch paths relative to its top).
export GIT_CEILING_DIRECTORIES=$work
# ccache (when present) keeps its own settings: export CCACHE_BASEDIR=<a folder above both trees> to share objects
# between the checkout's build and the copy's. The copy's test program is built without the precompiled header:
# ccache does not cache a compile that uses one unless its settings allow it (docs/architecture.md), so the test
# program's objects are cached from one run of the harness to the next, not shared with a default build's.
launcher=
command -v ccache >/dev/null 2>&1 &&
  launcher="-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache -DHELIOSTAND_PRECOMPILED_HEADERS=OFF"

rm -rf "$tree" "$work/passed-unmutated"
mkdir -p "$tree"
(cd "$repo" && git archive HEAD) | tar -x -C "$tree"
echo "copy of $(cd "$repo" && git rev-parse --short HEAD) in $tree" >&2
# shellcheck disable=SC2086
cmake -S "$tree" -B "$tree/build" -DCMAKE_BUILD_TYPE=Release $launcher >"$work/configure.log" 2>&1 ||
  { echo "configure failed: $work/configure.log" >&2; exit 1; }

# The mutations asked for (all by default), as "name<TAB>targets<TAB>check" lines.
selected() {
  grep -v '^#' "$here/mutations.tsv" | while IFS='	' read -r name targets check; do
    if [ $# -eq 0 ]; then printf '%s\t%s\t%s\n' "$name" "$targets" "$check"; continue; fi
    # (an `if`, not `[ ] &&`: a last name that does not match would end the function, and under set -e the script)
    for want in "$@"; do if [ "$want" = "$name" ]; then printf '%s\t%s\t%s\n' "$name" "$targets" "$check"; fi; done
  done
}
list=$work/selected.tsv
selected "$@" >"$list"
[ -s "$list" ] || { echo "no such mutation: $*" >&2; exit 2; }

build() {  # targets..., log
  log=$1; shift
  # shellcheck disable=SC2086
  cmake --build "$tree/build" -j2 --target "$@" >"$log" 2>&1
}
# A check runs at most CHECK_TIMEOUT seconds (default 900, the findings test's CTest timeout): a break that makes
# the model run away fails its CTest by timing out, so a timeout counts as a failure here too (exit status 124).
check() {  # check command, log: exit status of the check
  (cd "$tree/build" && timeout "${CHECK_TIMEOUT:-900}" sh -c "$1") >"$2" 2>&1
}

result=$work/result.md
{
  echo "# Mutation harness, $(date -u '+%Y-%m-%d %H:%M UTC'), commit $(cd "$repo" && git rev-parse --short HEAD)"
  echo
  echo "| break | check | unmutated | with the break | caught |"
  echo "|---|---|---|---|---|"
} >"$result"
failures=0
while IFS='	' read -r name targets check; do
  start=$(date +%s)
  # shellcheck disable=SC2086
  if ! build "$work/$name.base-build.log" $targets; then
    echo "$name: unmutated build failed ($work/$name.base-build.log)" >&2; exit 1
  fi
  # The unmutated check, once per distinct check.
  if grep -qxF "$check" "$work/passed-unmutated" 2>/dev/null; then base=pass
  elif check "$check" "$work/$name.base.log"; then base=pass; echo "$check" >>"$work/passed-unmutated"
  else base=FAIL; failures=$((failures + 1)); fi
  (cd "$tree" && git apply "$here/$name.patch")
  # shellcheck disable=SC2086
  if build "$work/$name.build.log" $targets; then
    if check "$check" "$work/$name.log"; then mutated=pass; caught=NO; failures=$((failures + 1)); else mutated=fail; caught=yes; fi
  else
    mutated="does not build"; caught=yes
  fi
  (cd "$tree" && git apply -R "$here/$name.patch")
  echo "| $name | \`$(printf '%s' "$check" | sed 's/|/\\|/g')\` | $base | $mutated | $caught |" >>"$result"
  echo "$name: unmutated $base, with the break $mutated, caught: $caught ($(( $(date +%s) - start )) s)" >&2
done <"$list"
cat "$result"
[ "$failures" -eq 0 ]
