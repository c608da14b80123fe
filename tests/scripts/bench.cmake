# The stand benchmark (validation/bench/, issue 16): its scenarios must stay valid, its committed surveys must be
# what make_planted_stands.py writes, and scaling.py must turn `heliostand bench stand` runs into its table (on the
# tiny bench stand for one year: timings are never checked, only that the row is there with the stand's counts).
set(BENCH_DIR ${PROJECT_SOURCE_DIR}/validation/bench)

file(GLOB HELIOSTAND_BENCH_SCENARIOS CONFIGURE_DEPENDS ${BENCH_DIR}/stands/*.toml)
foreach(scenario IN LISTS HELIOSTAND_BENCH_SCENARIOS)
  get_filename_component(name ${scenario} NAME_WE)
  add_test(NAME bench.check.${name} COMMAND $<TARGET_FILE:heliostand> check ${scenario})
  set_tests_properties(bench.check.${name} PROPERTIES LABELS "bench")
endforeach()

add_test(NAME bench.planted_surveys_are_generated
         COMMAND sh -c "rm -rf \"$0\" && \"$1\" \"$2/make_planted_stands.py\" \"$0\" && for f in planted_100 planted_400 planted_1600 planted_2500 old_100; do cmp \"$0/$f.csv\" \"$2/stands/$f.csv\" || exit 1; done"
                 ${PROJECT_BINARY_DIR}/test-output/bench-surveys ${HELIOSTAND_TEST_PYTHON} ${BENCH_DIR})
set_tests_properties(bench.planted_surveys_are_generated PROPERTIES LABELS "bench")
# Its --help shows its usage (before, any first argument was taken for the folder: `--help` wrote one so named). The
# option goes inside sh -c: given to cmake -P as an argument of its own, cmake takes it for its own --help.
add_test(NAME bench.planted_surveys_script_shows_its_help
         COMMAND ${CMAKE_COMMAND} -DEXPECT_EXIT=0 "-DEXPECT_OUTPUT=usage: make_planted_stands.py \\[-h\\] \\[folder\\]"
                 -P ${PROJECT_SOURCE_DIR}/tests/expect_exit_and_output.cmake
                 sh -c "\"$0\" \"$1\" --help" ${HELIOSTAND_TEST_PYTHON} ${BENCH_DIR}/make_planted_stands.py)
set_tests_properties(bench.planted_surveys_script_shows_its_help PROPERTIES LABELS "bench" TIMEOUT 60
                     WORKING_DIRECTORY ${PROJECT_BINARY_DIR})

# 8 trees, 1 year: the row reads "| 8 | 8 |" (trees, tree-years), then the leaf balls and root segments at the end,
# the wall, light and roots seconds and the light's share.
add_test(NAME bench.scaling_table
         COMMAND ${CMAKE_COMMAND} -DEXPECT_EXIT=0 "-DEXPECT_OUTPUT=\\| 8 \\| 8 \\| [1-9][0-9,]* \\| [1-9][0-9,]* \\| [0-9]+\\.[0-9] \\| [0-9]+\\.[0-9] \\| [0-9]+\\.[0-9] \\| [0-9]+ % \\|"
                 -P ${PROJECT_SOURCE_DIR}/tests/expect_exit_and_output.cmake
                 ${HELIOSTAND_TEST_PYTHON} ${BENCH_DIR}/scaling.py --heliostand $<TARGET_FILE:heliostand> --years 1
                 --device reference --stand ${BENCH_DIR}/stands/tiny.toml --out ${PROJECT_BINARY_DIR}/test-output/bench-scaling)
set_tests_properties(bench.scaling_table PROPERTIES LABELS "bench" TIMEOUT 300
                     ENVIRONMENT "POCL_CACHE_DIR=${PROJECT_BINARY_DIR}/pocl-cache")
# Bad arguments are refused before any stand is grown, with what was wrong and exit 2, and a run that fails (here a
# device heliostand refuses) ends the script with heliostand's own message and one line of its own, not a Python
# traceback: before, all three ended in a traceback, the first two only after scaling.py had started.
add_test(NAME bench.scaling_refuses_a_missing_program
         COMMAND ${CMAKE_COMMAND} -DEXPECT_EXIT=2 "-DEXPECT_OUTPUT=argument --heliostand: [^ ]*no-such-heliostand is not a program that can be run"
                 -P ${PROJECT_SOURCE_DIR}/tests/expect_exit_and_output.cmake
                 ${HELIOSTAND_TEST_PYTHON} ${BENCH_DIR}/scaling.py --heliostand ${PROJECT_BINARY_DIR}/no-such-heliostand
                 --out ${PROJECT_BINARY_DIR}/test-output/bench-scaling-refused)
add_test(NAME bench.scaling_refuses_zero_years
         COMMAND ${CMAKE_COMMAND} -DEXPECT_EXIT=2 "-DEXPECT_OUTPUT=argument --years: a whole number >= 1 is expected, got 0"
                 -P ${PROJECT_SOURCE_DIR}/tests/expect_exit_and_output.cmake
                 ${HELIOSTAND_TEST_PYTHON} ${BENCH_DIR}/scaling.py --heliostand $<TARGET_FILE:heliostand> --years 0
                 --out ${PROJECT_BINARY_DIR}/test-output/bench-scaling-refused)
add_test(NAME bench.scaling_reports_a_failed_run
         COMMAND ${CMAKE_COMMAND} -DEXPECT_EXIT=1 "-DEXPECT_OUTPUT=device 'bogus'.*scaling.py: the run above failed \\(exit status 2\\); no table written"
                 -P ${PROJECT_SOURCE_DIR}/tests/expect_exit_and_output.cmake
                 ${HELIOSTAND_TEST_PYTHON} ${BENCH_DIR}/scaling.py --heliostand $<TARGET_FILE:heliostand> --years 1
                 --device bogus --stand ${BENCH_DIR}/stands/tiny.toml --out ${PROJECT_BINARY_DIR}/test-output/bench-scaling-refused)
# An --out that names a file, or no folder at all (`--out=`, a script's unset variable: the current folder before),
# is refused before any stand is grown; before, a file ended in a Python traceback.
add_test(NAME bench.scaling_refuses_a_file_for_its_folder
         COMMAND ${CMAKE_COMMAND} -DEXPECT_EXIT=2 "-DEXPECT_OUTPUT=argument --out: [^ ]*scaling.py exists and is not a folder"
                 -P ${PROJECT_SOURCE_DIR}/tests/expect_exit_and_output.cmake
                 ${HELIOSTAND_TEST_PYTHON} ${BENCH_DIR}/scaling.py --heliostand $<TARGET_FILE:heliostand> --years 1
                 --stand ${BENCH_DIR}/stands/tiny.toml --out ${BENCH_DIR}/scaling.py)
add_test(NAME bench.scaling_refuses_an_empty_folder_name
         COMMAND ${CMAKE_COMMAND} -DEXPECT_EXIT=2 "-DEXPECT_OUTPUT=argument --out: a folder name is expected, got an empty one"
                 -P ${PROJECT_SOURCE_DIR}/tests/expect_exit_and_output.cmake
                 ${HELIOSTAND_TEST_PYTHON} ${BENCH_DIR}/scaling.py --heliostand $<TARGET_FILE:heliostand> --years 1
                 --stand ${BENCH_DIR}/stands/tiny.toml --out=)
set_tests_properties(bench.scaling_refuses_a_missing_program bench.scaling_refuses_zero_years
                     bench.scaling_reports_a_failed_run bench.scaling_refuses_a_file_for_its_folder
                     bench.scaling_refuses_an_empty_folder_name PROPERTIES LABELS "bench" TIMEOUT 60)
# The same binary given twice (to see the machine's noise): each of its two tables has the tiny stand's one row
# ("| 8 | 8 |"), and the ratio table one ("| 8 | " then a ratio); runs filed by path instead of position put both
# runs in each table. The machine line names the CPU family and model from the runs' JSON (lscpu's model name alone
# does not tell these machines apart).
add_test(NAME bench.scaling_table_same_binary_twice
         COMMAND sh -c "out=$(\"$0\" \"$1/scaling.py\" --heliostand \"$2\" --heliostand \"$2\" --years 1 --device reference --stand \"$1/stands/tiny.toml\" --out \"$3\") || exit 1; rows=$(printf '%s\\n' \"$out\" | grep -c '^| 8 | 8 |'); ratios=$(printf '%s\\n' \"$out\" | grep -c '^| 8 | [0-9]*[.][0-9][0-9] | '); machine=$(printf '%s\\n' \"$out\" | grep -c '^Machine: [0-9]* CPUs (.*; CPU family [0-9a-z]*, model [0-9a-z]*; '); echo \"stand rows $rows (want 2), ratio rows $ratios (want 1), machine lines with the CPU family $machine (want 1)\"; [ \"$rows\" = 2 ] && [ \"$ratios\" = 1 ] && [ \"$machine\" = 1 ]"
                 ${HELIOSTAND_TEST_PYTHON} ${BENCH_DIR} $<TARGET_FILE:heliostand> ${PROJECT_BINARY_DIR}/test-output/bench-scaling-twice)
set_tests_properties(bench.scaling_table_same_binary_twice PROPERTIES LABELS "bench" TIMEOUT 300
                     ENVIRONMENT "POCL_CACHE_DIR=${PROJECT_BINARY_DIR}/pocl-cache")
# The GPU machine's bundle (validation/bench/gpu): packed from this build with a second copy of heliostand as
# another "commit", it must load every library from itself (pack.sh checks the loader's trace and fails if not), and
# checks.sh must run each part on it with small sizes and exit 0, the two binaries side by side: their tiny stands'
# tables the same bytes and a ratio line for each figure. The machine's CPU family is listed ("AMD EPYC" alone does
# not tell the 2-core machines apart: docs/performance.md).
add_test(NAME bench.gpu_bundle
         COMMAND ${CMAKE_COMMAND} -DEXPECT_EXIT=0
                 "-DEXPECT_OUTPUT=CPU family: +[0-9]+.*PASSED  \\] [1-9].*stand table of again: the same bytes as main's.*main / again, hectare: [0-9.]+.*main / again, light of 2000 balls \\(medians\\): [0-9.]+"
                 -P ${PROJECT_SOURCE_DIR}/tests/expect_exit_and_output.cmake
                 sh -c "rm -rf \"$1\" \"$2\" && \"$0/gpu/pack.sh\" \"$3\" \"$1\" again=\"$4\" && BALLS=2000 LIGHT_RUNS=1 HECTARE=\"$0/stands/tiny.toml\" WARM_UP=\"$0/stands/tiny.toml\" TEST_FILTER='KernelOptions.*:ThreadsCli.RefusesZeroThreads' \"$0/gpu/checks.sh\" \"$1\" \"$2\""
                 ${BENCH_DIR} ${PROJECT_BINARY_DIR}/test-output/gpu-bundle ${PROJECT_BINARY_DIR}/test-output/gpu-checks
                 ${PROJECT_BINARY_DIR} $<TARGET_FILE:heliostand>)
set_tests_properties(bench.gpu_bundle PROPERTIES LABELS "bench" TIMEOUT 300 WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
                     ENVIRONMENT "POCL_CACHE_DIR=${PROJECT_BINARY_DIR}/pocl-cache")
# The bundle's command-line tests start the bundle's own heliostand, not this build's: with a bundle whose heliostand
# is not a program at all, checks.sh's tests part must fail on the one command-line test it runs (were the build's
# heliostand started instead, the test would pass).
add_test(NAME bench.gpu_bundle_cli_tests_start_its_heliostand
         COMMAND ${CMAKE_COMMAND} -DEXPECT_EXIT=1 "-DEXPECT_OUTPUT=tests exit 1.*\\[  FAILED  \\] 1 test"
                 -P ${PROJECT_SOURCE_DIR}/tests/expect_exit_and_output.cmake
                 sh -c "rm -rf \"$1\" \"$2\" && \"$0/gpu/pack.sh\" \"$3\" \"$1\" && printf '#!/bin/sh\\nexit 3\\n' > \"$1/heliostand\" && TEST_FILTER='ThreadsCli.RefusesZeroThreads' \"$0/gpu/checks.sh\" \"$1\" \"$2\" tests"
                 ${BENCH_DIR} ${PROJECT_BINARY_DIR}/test-output/gpu-bundle-stub ${PROJECT_BINARY_DIR}/test-output/gpu-checks-stub
                 ${PROJECT_BINARY_DIR})
set_tests_properties(bench.gpu_bundle_cli_tests_start_its_heliostand PROPERTIES LABELS "bench" TIMEOUT 300
                     WORKING_DIRECTORY ${PROJECT_SOURCE_DIR} ENVIRONMENT "POCL_CACHE_DIR=${PROJECT_BINARY_DIR}/pocl-cache")
# first_touch.py (what the first write to fresh memory costs, docs/performance.md "What a first touch costs here,
# measured apart"): on 4 MiB without a pause it prints ten lines for 4 KiB and huge pages, each with both passes'
# seconds a GiB; timings are never checked. A size of 0 MiB is refused with what was wrong and exit 2.
add_test(NAME bench.first_touch_measures_each_kind_and_time
         COMMAND sh -c "out=$(\"$0\" \"$1/first_touch.py\" --mib 4 --pause 0) || exit 1; printf '%s\\n' \"$out\"; lines=$(printf '%s\\n' \"$out\" | grep -c -E '^(4 KiB|huge) pages (fresh|right after unmapping|after 0 s): [0-9]+[.][0-9]{3} s a GiB [(]first pass[)], [0-9]+[.][0-9]{3} s a GiB [(]second pass[)]$'); echo \"measurement lines $lines (want 10)\"; [ \"$lines\" = 10 ]"
                 ${HELIOSTAND_TEST_PYTHON} ${BENCH_DIR})
# Its pages made resident first: three lines with the call's seconds a GiB before both passes', or, on a kernel older
# than Linux 5.14, one line saying the call is not supported.
add_test(NAME bench.first_touch_measures_pages_made_resident_first
         COMMAND sh -c "out=$(\"$0\" \"$1/first_touch.py\" --mib 4 --pause 0) || exit 1; printf '%s\\n' \"$out\"; lines=$(printf '%s\\n' \"$out\" | grep -c -E '^4 KiB pages made resident first (fresh|right after unmapping|after 0 s): [0-9]+[.][0-9]{3} s a GiB [(]made resident[)], [0-9]+[.][0-9]{3} s a GiB [(]first pass[)], [0-9]+[.][0-9]{3} s a GiB [(]second pass[)]$'); unsupported=$(printf '%s\\n' \"$out\" | grep -c '^4 KiB pages made resident first: not supported here'); echo \"made-resident lines $lines (want 3), unsupported $unsupported\"; [ \"$lines\" = 3 ] || [ \"$lines$unsupported\" = 01 ]"
                 ${HELIOSTAND_TEST_PYTHON} ${BENCH_DIR})
add_test(NAME bench.first_touch_refuses_zero_mib
         COMMAND ${CMAKE_COMMAND} -DEXPECT_EXIT=2 "-DEXPECT_OUTPUT=argument --mib: a whole number >= 1 is expected, got 0"
                 -P ${PROJECT_SOURCE_DIR}/tests/expect_exit_and_output.cmake
                 ${HELIOSTAND_TEST_PYTHON} ${BENCH_DIR}/first_touch.py --mib 0)
set_tests_properties(bench.first_touch_measures_each_kind_and_time bench.first_touch_measures_pages_made_resident_first
                     bench.first_touch_refuses_zero_mib PROPERTIES
                     LABELS "bench" TIMEOUT 60)
