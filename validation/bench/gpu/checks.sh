#!/bin/sh
# Issue 16's checks on a GPU machine, from a bundle made by pack.sh: the light and roots solvers' tests on its
# device (the command-line ones among them start the bundle's heliostand, through HELIOSTAND_TEST_EXECUTABLE), the
# light field of 10^5 and 10^6 leaf balls, and the hectare's 60 years, each binary of the bundle in turn
# (heliostand, then every NAME/heliostand), so that two commits are measured side by side on one machine.
#
#   validation/bench/gpu/checks.sh BUNDLE_DIR OUT_DIR [tests] [light] [hectare]     (all three by default)
#
# On an H200 (16 host cores) the tests take about 3 min, a light run about 30 s (LIGHT_RUNS rounds, default 2),
# a hectare 130-190 s (HECTARE_LIMIT, default 300 s, stops a run that outgrows it). Each binary first grows
# planted_100 for a year, so that the driver's first build of the kernels falls on no measured run (on a fresh
# H200, 24.6 s of a hectare fell outside every stage, most likely that build: docs/performance.md).
# OUT_DIR gets machine.txt, tests.log, light_NAME_N.json, hectare_NAME.json, tables_NAME/ and summary.txt (the
# figures the docs quote, from the JSON). Run it from the repository's root (the scenarios).
# Exit status 1 when anything failed: a test, a run, a run stopped at its limit, tables that differ (as they do
# where a commit changes the answers: then read the figures, not the status).
# BALLS, HECTARE, WARM_UP and TEST_FILTER replace the light's sizes ("100000 1000000"), the hectare's scenario, the
# warm-up's and the tests' (CTest bench.gpu_bundle runs the whole script on this machine's OpenCL with small ones).
set -u
[ $# -ge 2 ] || { echo "usage: $0 BUNDLE_DIR OUT_DIR [tests] [light] [hectare]" >&2; exit 2; }
bundle=$1; out=$2; shift 2
parts=${*:-tests light hectare}
[ -x "$bundle/run" ] || { echo "error: $bundle/run: not a bundle made by pack.sh" >&2; exit 2; }
case $bundle in *"'"*) echo "error: $bundle: a bundle's path may not hold a single quote" >&2; exit 2;; esac
hectare=${HECTARE:-validation/bench/stands/hectare_60_years.toml}
warm_up=${WARM_UP:-validation/bench/stands/planted_100.toml}
for scenario in "$hectare" "$warm_up"; do
  [ -f "$scenario" ] || { echo "error: $scenario: no such scenario (run from the repository's root)" >&2; exit 2; }
done
balls=""
for n in ${BALLS:-100000 1000000}; do balls="$balls --balls $n"; done
mkdir -p "$out"
start=$(date +%s)
failed=0
fail() { echo "$1"; failed=1; }
elapsed() { echo $(( $(date +%s) - start )); }

# NVIDIA's driver installs its OpenCL library without an ICD file where a container mounts it: name it.
if [ -z "${OCL_ICD_VENDORS:-}" ] && ! ls /etc/OpenCL/vendors/*.icd >/dev/null 2>&1; then
  nvidia=$(ldconfig -p 2>/dev/null | awk '/libnvidia-opencl\.so\.1/ { print $NF; exit }')
  if [ -n "$nvidia" ]; then
    mkdir -p "$out/vendors" && echo "$nvidia" > "$out/vendors/nvidia.icd"
    export OCL_ICD_VENDORS="$out/vendors"
  fi
fi

# The binaries: heliostand, then NAME/heliostand for every other commit packed.
names="main"
for folder in "$bundle"/*/; do
  name=$(basename "$folder"); [ "$name" = libs ] || names="$names $name"
done
program() { if [ "$1" = main ]; then echo heliostand; else echo "$1/heliostand"; fi; }

{ command -v nvidia-smi >/dev/null && nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv,noheader
  echo "host cores: $(nproc)"; lscpu | grep -E '^(Model name|CPU family|Model):'; echo "binaries: $names"
  "$bundle/run" heliostand devices; } > "$out/machine.txt" 2>&1
cat "$out/machine.txt"

case " $parts " in *" tests "*)
  echo "== tests ($(elapsed) s)"
  filter='*LightSolver*:*LightEquivalence*:*LightCulling*:*StandAndAlone*:*OpenCLRootField*:*RootFieldSolverContract*'
  filter="$filter:*LightEightLanes*:*LightPatchRuns*:*LightBatches*:*LightScanBatches*"
  filter="$filter:*ComputeBackend*:*DeviceChoice*"
  filter="$filter:*GrowRoots*:*FarField*:*NearFieldSearch*:*MakeLightSolver*:*FoliageClumping*:*KernelOptions*"
  # the command-line runs on the device: the benchmarks, the roots, the threads, a resumed checkpoint, the compiles
  filter="$filter:BenchStandCli.*:BenchLight*Cli.*:BenchMachineCli.*:RootsCli.*:ThreadsCli.*:CheckpointCli.*"
  filter="$filter:KernelCompiles.*"
  # The command-line tests start the bundle's heliostand, not the build tree's (which did not travel).
  HELIOSTAND_TEST_EXECUTABLE="'$(cd "$bundle" && pwd)/run' heliostand" \
    "$bundle/run" heliostand_tests --gtest_filter="${TEST_FILTER:-$filter}" > "$out/tests.log" 2>&1
  status=$?
  if [ "$status" = 0 ]; then echo "tests exit 0"; else fail "tests exit $status"; fi
  grep -E '^\[  (PASSED|FAILED|SKIPPED) *\] [0-9]' "$out/tests.log";;
esac

case " $parts " in *" light "*|*" hectare "*)
  for name in $names; do
    echo "== warm-up $name ($(elapsed) s)"
    "$bundle/run" "$(program "$name")" bench stand "$warm_up" --years 1 -q > /dev/null 2>&1 ||
      fail "warm-up of $name failed"
  done;;
esac

case " $parts " in *" light "*)
  round=1
  while [ "$round" -le "${LIGHT_RUNS:-2}" ]; do
    for name in $names; do
      echo "== light $name $round ($(elapsed) s)"
      # shellcheck disable=SC2086  # $balls is one --balls N for each size
      "$bundle/run" "$(program "$name")" bench light $balls --subsample 20 \
        --reference-culled-max 1000 --opencl-exact-max 1000 -o "$out/light_${name}_$round.json" > /dev/null 2>&1
      status=$?
      if [ "$status" = 0 ]; then echo "exit 0"; else fail "light of $name exit $status"; fi
    done
    round=$((round + 1))
  done;;
esac

case " $parts " in *" hectare "*)
  for name in $names; do
    echo "== hectare $name ($(elapsed) s)"
    timeout "${HECTARE_LIMIT:-300}" "$bundle/run" "$(program "$name")" bench stand \
      "$hectare" --tables "$out/tables_$name" --force \
      -o "$out/hectare_$name.json" -q > /dev/null 2>&1
    status=$?
    if [ "$status" = 124 ]; then fail "hectare of $name stopped at ${HECTARE_LIMIT:-300} s"
    elif [ "$status" = 0 ]; then echo "exit 0"
    else fail "hectare of $name exit $status"; fi
  done
  for name in $names; do
    [ "$name" = main ] && continue
    if cmp -s "$out/tables_main/stand_table.csv" "$out/tables_$name/stand_table.csv"; then
      echo "stand table of $name: the same bytes as main's"
    else
      fail "stand table of $name: differs from main's (or a run did not finish)"
    fi
  done;;
esac

python3 "$(dirname "$0")/summary.py" "$out" > "$out/summary.txt" 2>&1 || fail "summary.py failed"
cat "$out/summary.txt"
echo "== done ($(elapsed) s)"
exit "$failed"
