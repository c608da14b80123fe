#!/bin/sh
# Packs heliostand built here into a folder that runs on a machine without Debian's packages: a lent GPU machine
# brings its own OpenCL driver but not VTK, FLANN, Qhull or the rest. Beside each binary go the shared libraries
# it loads and this machine's dynamic loader, and `run` starts a binary through that loader with those libraries
# first, so nothing of the other machine's own libraries is mixed in (the loader and libc are of one glibc).
#
#   validation/bench/gpu/pack.sh BUILD_DIR BUNDLE_DIR [NAME=BINARY ...]
#   BUNDLE_DIR/run heliostand devices
#
# BUILD_DIR/heliostand goes in as `heliostand`, BUILD_DIR/tests/heliostand_tests (when built) as
# `heliostand_tests`, and each NAME=BINARY as NAME/heliostand (another commit's build, for runs side by side).
# The OpenCL driver is not packed: the ICD loader finds the other machine's (checks.sh names NVIDIA's).
set -eu
[ $# -ge 2 ] || { echo "usage: $0 BUILD_DIR BUNDLE_DIR [NAME=BINARY ...]" >&2; exit 2; }
build=$1; bundle=$2; shift 2
if [ ! -x "$build/heliostand" ]; then
  echo "error: $build/heliostand: no such program (build heliostand first)" >&2; exit 2
fi
if [ -e "$bundle" ] && [ -n "$(ls -A "$bundle")" ]; then
  echo "error: $bundle: not empty (packing never mixes two builds)" >&2; exit 2
fi
mkdir -p "$bundle/libs"

binaries="$build/heliostand"
programs="heliostand"
cp "$build/heliostand" "$bundle/heliostand"
if [ -x "$build/tests/heliostand_tests" ]; then
  cp "$build/tests/heliostand_tests" "$bundle/heliostand_tests"
  binaries="$binaries $build/tests/heliostand_tests"
  programs="$programs heliostand_tests"
fi
for named in "$@"; do
  name=${named%%=*}; binary=${named#*=}
  case $name in
    ''|*/*|*' '*|heliostand|heliostand_tests|libs|run)
      echo "error: $named: NAME must be a plain folder name, not one the bundle uses" >&2; exit 2;;
  esac
  [ -x "$binary" ] || { echo "error: $binary: no such program" >&2; exit 2; }
  mkdir -p "$bundle/$name" && cp "$binary" "$bundle/$name/heliostand"
  binaries="$binaries $binary"
  programs="$programs $name/heliostand"
done

# Every library the binaries load (ldd resolves the whole tree), and the loader they name.
for binary in $binaries; do
  if ldd "$binary" | grep -q 'not found'; then
    echo "error: $binary: a library it needs is not found here:" >&2; ldd "$binary" | grep 'not found' >&2; exit 1
  fi
done
for binary in $binaries; do ldd "$binary" | awk '$2 == "=>" && $3 ~ /^\// { print $3 }'; done |
  sort -u | while read -r library; do cp -L "$library" "$bundle/libs/"; done
loader=$(ldd "$build/heliostand" | awk '$1 ~ /^\/.*ld-linux/ { print $1 }')
[ -n "$loader" ] || { echo "error: the dynamic loader of $build/heliostand not found by ldd" >&2; exit 1; }
cp -L "$loader" "$bundle/libs/ld.so"

cat > "$bundle/run" <<'RUN'
#!/bin/sh
# run PROGRAM [ARGS...]: PROGRAM (heliostand, heliostand_tests, NAME/heliostand) through the packed loader.
here=$(cd "$(dirname "$0")" && pwd)
[ $# -ge 1 ] || { echo "usage: $0 PROGRAM [ARGS...]" >&2; exit 2; }
program=$1; shift
exec "$here/libs/ld.so" --library-path "$here/libs" "$here/$program" "$@"
RUN
chmod +x "$bundle/run"

# The bundle stands alone only if each program loads every library from it: the loader's own trace of a run that
# does nothing (the version; the tests' list) names each library it initialises, from the packed loader on.
libs=$(cd "$bundle/libs" && pwd)
for program in $programs; do
  case $program in *_tests) idle=--gtest_list_tests;; *) idle=--version;; esac
  trace=$(LD_DEBUG=libs "$bundle/run" "$program" "$idle" 2>&1 >/dev/null)
  outside=$(printf '%s\n' "$trace" | awk -v libs="$libs/" '
    /calling init: / && $NF == libs "ld.so" { on = 1 }
    on && /calling init: / { n++; if (index($NF, libs) != 1) print $NF }
    on && /initialize program: / { exit }
    END { if (n < 2) print "(no library initialised from the bundle)" }')
  if [ -n "$outside" ]; then
    echo "error: $bundle: $program loads libraries from outside the bundle:" >&2; echo "$outside" >&2; exit 1
  fi
done
echo "$bundle: $(find "$bundle/libs" -type f | wc -l) libraries, $(du -sh "$bundle" | cut -f1)"
