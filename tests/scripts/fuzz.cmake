# Hostile input (issue 12 item 3): libFuzzer harnesses of the three readers a user's files reach — survey CSV,
# scenario TOML, soil CSV — built with -DHELIOSTAND_FUZZ=ON (clang; ASan and UBSan on), each fuzzed for a short
# while from its seed corpus (tests/fuzz/corpus/). A crash, a sanitizer finding, a leak, an input slower than
# -timeout or a heap beyond -rss_limit_mb fails the test; the input that did it is left in
# BUILD/fuzz/artifacts/ (rerun it: BUILD/tests/NAME_fuzz FILE). HELIOSTAND_FUZZ_SECONDS sets the time per reader.
if(NOT HELIOSTAND_FUZZ)
  return()
endif()
set(HELIOSTAND_FUZZ_SECONDS 30 CACHE STRING "Seconds each reader is fuzzed by its CTest")
foreach(reader IN ITEMS survey scenario soil)
  add_executable(${reader}_fuzz ${PROJECT_SOURCE_DIR}/tests/fuzz/${reader}_fuzz.cpp)
  target_link_libraries(${reader}_fuzz PRIVATE heliostand_all)
  target_link_options(${reader}_fuzz PRIVATE -fsanitize=fuzzer)
  target_compile_definitions(${reader}_fuzz PRIVATE HELIOSTAND_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  # The fuzzer adds what it finds to the first (writable) corpus folder; the seeds in the repo stay as they are.
  set(work_corpus ${PROJECT_BINARY_DIR}/fuzz/corpus/${reader})
  # The harness writes each input to a scratch folder under TMPDIR (tests/fuzz/fuzz_input_file.hpp), a folder of
  # the test's own here: the test fails if the fuzzer leaves anything in it once it has run.
  set(scratch ${PROJECT_BINARY_DIR}/fuzz/tmp/${reader})
  add_test(NAME fuzz.${reader}
           COMMAND sh -c "rm -rf '${scratch}' && mkdir -p '${work_corpus}' '${PROJECT_BINARY_DIR}/fuzz/artifacts' '${scratch}' && '$<TARGET_FILE:${reader}_fuzz>' -max_total_time=${HELIOSTAND_FUZZ_SECONDS} -timeout=10 -rss_limit_mb=2048 -max_len=4096 -print_final_stats=1 -artifact_prefix='${PROJECT_BINARY_DIR}/fuzz/artifacts/${reader}-' '${work_corpus}' '${PROJECT_SOURCE_DIR}/tests/fuzz/corpus/${reader}' || exit $?
                      left=$(ls -A '${scratch}'); [ -z \"$left\" ] || { echo \"scratch files left behind in ${scratch}: $left\"; exit 1; }")
  set_tests_properties(fuzz.${reader} PROPERTIES LABELS "fuzz" TIMEOUT 300 ENVIRONMENT "TMPDIR=${scratch}")
endforeach()
