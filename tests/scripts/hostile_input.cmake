# Hostile input (issue 12 item 3), end to end: work beyond the memory the run may use is refused before anything is
# written. `ulimit -v` gives heliostand 0.95 GiB, less than each estimate asked for here: stands/tiny's and the bench
# tiny stand's (1 GiB + 8 × 1.75 MiB, stand/memory_estimate.hpp) and a canopy of 10^5 leaf balls (1 GiB + 10^5 × 2 KiB,
# light/light_benchmark.hpp). Each must exit with status 2, the estimate in its message, and leave no output behind.
# (Not in the sanitizer build: ASan reserves terabytes of address space, which `ulimit -v` forbids.)
if(HELIOSTAND_SANITIZE)
  return()
endif()
set(HOSTILE_OUT ${PROJECT_BINARY_DIR}/tests/hostile)

# `heliostand ARGUMENTS`, which should have written OUTPUT, under the limit: exit 2, ESTIMATE in the message, and
# OUTPUT absent.
function(heliostand_refuses_beyond_memory name arguments estimate output)
  add_test(NAME ${name}
           COMMAND sh -c "rm -rf '${output}'; ulimit -v 996147 || exit 1; out=$('$<TARGET_FILE:heliostand>' ${arguments} 2>&1); status=$?; echo \"$out\"; [ $status -eq 2 ] || { echo \"expected exit status 2, got $status\"; exit 1; }; echo \"$out\" | grep -qF -e '${estimate}' || { echo 'the estimate is not in the message'; exit 1; }; [ ! -e '${output}' ] || { echo 'output was written'; exit 1; }")
  set_tests_properties(${name} PROPERTIES TIMEOUT 60)
endfunction()

heliostand_refuses_beyond_memory(cli.grow.refuses_a_stand_beyond_memory
  "grow '${PROJECT_SOURCE_DIR}/stands/tiny/scenario.toml' --out '${HOSTILE_OUT}/beyond-memory' --device reference"
  "8 trees need about 1.0 GiB" "${HOSTILE_OUT}/beyond-memory")
heliostand_refuses_beyond_memory(cli.bench_stand.refuses_a_stand_beyond_memory
  "bench stand '${PROJECT_SOURCE_DIR}/validation/bench/stands/tiny.toml' --device reference --tables '${HOSTILE_OUT}/bench-stand-tables' -o '${HOSTILE_OUT}/bench-stand.json'"
  "8 trees need about 1.0 GiB" "${HOSTILE_OUT}/bench-stand-tables")
heliostand_refuses_beyond_memory(cli.bench_light.refuses_a_stand_beyond_memory
  "bench light --stand '${PROJECT_SOURCE_DIR}/validation/bench/stands/tiny.toml' --device none -o '${HOSTILE_OUT}/bench-light-stand.json'"
  "8 trees need about 1.0 GiB" "${HOSTILE_OUT}/bench-light-stand.json")
heliostand_refuses_beyond_memory(cli.bench_light.refuses_a_canopy_beyond_memory
  "bench light --balls 100000 --subsample 20 --reference-exact-max 1 --reference-culled-max 1 --device none -o '${HOSTILE_OUT}/bench-light-balls.json'"
  "--balls: 100000 leaf balls need about 1.2 GiB" "${HOSTILE_OUT}/bench-light-balls.json")
