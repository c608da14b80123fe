# Hostile input (issue 12 item 3), end to end: a stand beyond the memory the run may use is refused before anything
# is written. `ulimit -v` gives the run 0.95 GiB, less than stands/tiny's estimate (1 GiB + 8 × 1.75 MiB): exit
# status 2, the estimate in the message, no output folder. (Not in the sanitizer build: ASan reserves terabytes of
# address space, which `ulimit -v` forbids.)
if(HELIOSTAND_SANITIZE)
  return()
endif()
set(HOSTILE_OUT ${PROJECT_BINARY_DIR}/tests/hostile/beyond-memory)
add_test(NAME cli.grow.refuses_a_stand_beyond_memory
         COMMAND sh -c "rm -rf '${HOSTILE_OUT}'; ulimit -v 996147 || exit 1; out=$('$<TARGET_FILE:heliostand>' grow '${PROJECT_SOURCE_DIR}/stands/tiny/scenario.toml' --out '${HOSTILE_OUT}' --device reference 2>&1); status=$?; echo \"$out\"; [ $status -eq 2 ] || { echo \"expected exit status 2, got $status\"; exit 1; }; echo \"$out\" | grep -q '8 trees need about 1.0 GiB' || { echo 'the estimate is not in the message'; exit 1; }; [ ! -e '${HOSTILE_OUT}' ] || { echo 'an output folder was written'; exit 1; }")
set_tests_properties(cli.grow.refuses_a_stand_beyond_memory PROPERTIES TIMEOUT 60)
