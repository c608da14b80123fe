# Every `docs/NAME.md "Section"` in the checkout names a section NAME.md has, and every `"Section" below` (or above) in
# a Markdown file one of its own on that side (tests/docs/section_references.py): a renamed, removed or moved section
# would otherwise leave code comments and docs pointing at nothing. The other two run the check on a small fixture
# whose broken references are known, so that a check that found nothing would fail.
set(DOCS_CHECK ${PROJECT_SOURCE_DIR}/tests/docs/section_references.py)

add_test(NAME docs.section_references_name_sections
         COMMAND ${HELIOSTAND_TEST_PYTHON} ${DOCS_CHECK} ${PROJECT_SOURCE_DIR})
set_tests_properties(docs.section_references_name_sections PROPERTIES LABELS "docs" TIMEOUT 60)

# The fixture's ten broken references (seven titles it lacks, one doc it lacks, two of its own sections said to lie on
# the wrong side), in file and line order, and its twelve good ones not reported.
set(DOCS_FIXTURE_REPORT
    "docs/guide.md:16: docs/guide.md has no section \"Not a heading\"\n"
    "docs/guide.md:19: docs/guide.md has no section \"Planting rows\" above\n"
    "docs/guide.md:19: docs/guide.md has its section \"Pruning\" below, not above\n"
    "docs/guide.md:19: docs/guide.md has its section \"Planting\" above, not below\n"
    "src/tree.cpp:4: docs/guide.md has no section \"Thinning from above\"\n"
    "src/tree.cpp:4: docs/guide.md has no section \"Planting rows\"\n"
    "src/tree.cpp:4: docs/guide.md has no section \"Thin\"\n"
    "src/tree.cpp:5: docs/other.md: no such file\n"
    "src/tree.cpp:6: docs/guide.md has no section \"Harvest\"\n"
    "src/tree.cpp:7: docs/guide.md has no section \"Roots\"\n"
    "22 references to sections of the docs read, 10 broken")
string(CONCAT DOCS_FIXTURE_REPORT ${DOCS_FIXTURE_REPORT})
add_test(NAME docs.section_references_check_reports_the_broken_ones
         COMMAND ${CMAKE_COMMAND} -DEXPECT_EXIT=1 "-DEXPECT_OUTPUT=^${DOCS_FIXTURE_REPORT}\n*$"
                 -P ${PROJECT_SOURCE_DIR}/tests/expect_exit_and_output.cmake
                 ${HELIOSTAND_TEST_PYTHON} ${DOCS_CHECK} ${PROJECT_SOURCE_DIR}/tests/docs/fixture)
set_tests_properties(docs.section_references_check_reports_the_broken_ones PROPERTIES LABELS "docs" TIMEOUT 60)
# The same where git cannot list the files (a source archive, as the mutation harness builds from): the script walks
# the folders instead, and must report the same references in the same order.
add_test(NAME docs.section_references_check_reports_the_same_outside_git
         COMMAND ${CMAKE_COMMAND} -E env GIT_DIR=${PROJECT_BINARY_DIR}/no-such-git-folder
                 ${CMAKE_COMMAND} -DEXPECT_EXIT=1 "-DEXPECT_OUTPUT=^${DOCS_FIXTURE_REPORT}\n*$"
                 -P ${PROJECT_SOURCE_DIR}/tests/expect_exit_and_output.cmake
                 ${HELIOSTAND_TEST_PYTHON} ${DOCS_CHECK} ${PROJECT_SOURCE_DIR}/tests/docs/fixture)
set_tests_properties(docs.section_references_check_reports_the_same_outside_git PROPERTIES LABELS "docs" TIMEOUT 60)

# The summary of the goal hectare's runs in docs/performance.md ("Every hectare on two cores") is what
# validation/bench/hectare_runs.py makes of validation/bench/hectare_runs.csv: a run added to the file and not to the
# summary, or a figure changed in the summary alone, fails, and so does a goal table that quotes the summary's median
# or counts otherwise than the runs give them. The other checks run the script on the fixture in
# tests/docs/hectare_runs: a summary one median out of date is reported with the line that differs, a goal table's
# count one run behind with the words it should read, and rows that cannot be runs (a negative wall time, a run out
# of order, a section the doc lacks, a field missing, a processor or kernel generation not written as one) are errors
# naming the file, line and field.
set(HECTARE_RUNS_FIXTURE ${PROJECT_SOURCE_DIR}/tests/docs/hectare_runs)
# docs.RUNS_summary_matches_the_runs: validation/bench/RUNS.py --check on docs/performance.md itself.
function(add_runs_summary_test runs)
  add_test(NAME docs.${runs}_summary_matches_the_runs
           COMMAND ${HELIOSTAND_TEST_PYTHON} ${PROJECT_SOURCE_DIR}/validation/bench/${runs}.py
                   --check ${PROJECT_SOURCE_DIR}/docs/performance.md)
  set_tests_properties(docs.${runs}_summary_matches_the_runs PROPERTIES LABELS "docs" TIMEOUT 60)
endfunction()
add_runs_summary_test(hectare_runs)
# docs.RUNS_NAME: validation/bench/RUNS.py on the fixture tests/docs/RUNS exits with STATUS and prints what
# OUTPUT_REGEX matches; the arguments after it are the script's, besides the fixture's sections.md.
function(add_runs_fixture_test runs name status output_regex)
  set(fixture ${PROJECT_SOURCE_DIR}/tests/docs/${runs})
  add_test(NAME docs.${runs}_${name}
           COMMAND ${CMAKE_COMMAND} -DEXPECT_EXIT=${status} "-DEXPECT_OUTPUT=${output_regex}"
                   -P ${PROJECT_SOURCE_DIR}/tests/expect_exit_and_output.cmake
                   ${HELIOSTAND_TEST_PYTHON} ${PROJECT_SOURCE_DIR}/validation/bench/${runs}.py
                   --sections ${fixture}/sections.md ${ARGN})
  set_tests_properties(docs.${runs}_${name} PROPERTIES LABELS "docs" TIMEOUT 60)
endfunction()
# docs.RUNS_rejects_NAME for each "NAME|MESSAGE" after RUNS: the script on the fixture's NAME.csv exits with 2 and its
# first line of output matches MESSAGE.
function(add_runs_bad_row_tests runs)
  foreach(case IN LISTS ARGN)
    string(REPLACE "|" ";" case "${case}")
    list(GET case 0 name)
    list(GET case 1 message)
    add_runs_fixture_test(${runs} rejects_${name} 2 "^[^\n]*${message}"
                          --runs ${PROJECT_SOURCE_DIR}/tests/docs/${runs}/${name}.csv)
  endforeach()
endfunction()
add_runs_fixture_test(hectare_runs check_reports_a_stale_summary 1
    "stale.md: its summary of the hectare's runs differs from runs.csv's.*\n-\\| 2026-12-02 08:00 \\| 2 \\| 0 \\| 630.0 s \\(1.05\\) [^\n]*\n\\+\\| 2026-12-02 08:00 \\| 2 \\| 0 \\| 630.5 s \\(1.05\\) "
    --runs ${HECTARE_RUNS_FIXTURE}/runs.csv --check ${HECTARE_RUNS_FIXTURE}/stale.md)
add_runs_fixture_test(hectare_runs check_reports_an_unquoted_count 1
    "unquoted.md: the summary of 14 lines matches runs.csv\n.*unquoted.md: the front goal table's hectare verdict does not read \"\\(1 of 3 runs;\", as runs.csv gives it"
    --runs ${HECTARE_RUNS_FIXTURE}/runs.csv --check ${HECTARE_RUNS_FIXTURE}/unquoted.md)
add_runs_bad_row_tests(hectare_runs
    "bad_wall|bad_wall.csv:3: field 'wall_s': -580.0 seconds is not a positive, finite amount"
    "out_of_order|out_of_order.csv:4: field 'time_utc': the run is earlier than the row before it"
    "no_section|no_section.csv:3: field 'section': [^\n]*sections.md has no section \"A slow hour\""
    "short_row|short_row.csv:3: field 'peak_mib': missing"
    "bad_cpu|bad_cpu.csv:3: field 'cpu': 'AMD EPYC' is not a processor written as NAME family N model N"
    "bad_kernels|bad_kernels.csv:3: field 'kernels': 'floor and ceil as instruction' is not a generation of the light kernels named in runs_file.py's KERNEL_GENERATIONS")
# Each kind of processor apart: on two_kinds.csv (runs.csv's runs and two of an Intel Xeon) the family-26 EPYC's
# summary and quotations read as on runs.csv alone, the Xeon's runs have tables of their own, and its column of the
# front goal table, one run behind, is named with the words it should read, and nothing else is.
add_runs_fixture_test(hectare_runs check_holds_each_kind_apart 1
    "two_kinds.md: the summary of 28 lines matches two_kinds.csv\n[^\n]*two_kinds.md: the front goal table's hectare row, the Intel Xeon of CPU family 6, model 85's column does not read \"\\| \\*\\*560.0–575.0 s\\*\\* in two runs, all under the line \\|\", as two_kinds.csv gives it[^\n]*\n$"
    --runs ${HECTARE_RUNS_FIXTURE}/two_kinds.csv --check ${HECTARE_RUNS_FIXTURE}/two_kinds.md)
# A kind's latest kernels are the latest it has run in runs_file.KERNEL_GENERATIONS's order, not in its rows': on
# older_kernels_last.csv (two_kinds.csv and a run of the Xeon's with the older kernels after its others, as a side by
# side with an older commit writes it) the Xeon's summary gains that run, but its column of the goal tables is still
# made from its runs of the latest kernels, so two_kinds.md is named for the same words as on two_kinds.csv.
add_runs_fixture_test(hectare_runs check_takes_the_latest_kernels_by_name 1
    "two_kinds.md: its summary of the hectare's runs differs from older_kernels_last.csv's.*\n\\+\\| library floor and ceil \\| 1 \\| 0 \\| 612.0 s [^\n]*\n.*\n With the latest kernels \\(floor and ceil as instructions\\), machine by machine:\n.*\n[^\n]*two_kinds.md: the front goal table's hectare row, the Intel Xeon of CPU family 6, model 85's column does not read \"\\| \\*\\*560.0–575.0 s\\*\\* in two runs, all under the line \\|\", as older_kernels_last.csv gives it[^\n]*\n$"
    --runs ${HECTARE_RUNS_FIXTURE}/older_kernels_last.csv --check ${HECTARE_RUNS_FIXTURE}/two_kinds.md)

# The same for the light goal's runs ("Every light goal run on two cores"): validation/bench/light_runs.py makes the
# summary of validation/bench/light_runs.csv, and the goal tables' light rows quote its counts of first solves over
# the line. On the fixture in tests/docs/light_runs: a summary with one machine's median out of date is reported with
# the line that differs, a goal table's count one run behind with the words it should read, and rows that cannot be
# runs (a size that is not the goal's, later solves apart by a comma, a kernel cache neither warm nor empty) are errors
# naming the file, line and field.
set(LIGHT_RUNS_FIXTURE ${PROJECT_SOURCE_DIR}/tests/docs/light_runs)
add_runs_summary_test(light_runs)
add_runs_fixture_test(light_runs check_reports_a_stale_summary 1
    "stale.md: its summary of the light goal's runs differs from runs.csv's.*\n-\\| 2026-12-02 08:00 \\| 2 \\| 1 \\| 1.078 s [^\n]*\n\\+\\| 2026-12-02 08:00 \\| 2 \\| 1 \\| 1.016 s "
    --runs ${LIGHT_RUNS_FIXTURE}/runs.csv --check ${LIGHT_RUNS_FIXTURE}/stale.md)
add_runs_fixture_test(light_runs check_reports_an_unquoted_count 1
    "unquoted.md: the summary of 19 lines matches runs.csv\n.*unquoted.md: the front goal table's 10⁵ light row does not read \"first 10⁵ solve [^\n]*, one of two on the machine started 2026-12-02 08:00\\)\", as runs.csv gives it"
    --runs ${LIGHT_RUNS_FIXTURE}/runs.csv --check ${LIGHT_RUNS_FIXTURE}/unquoted.md)
add_runs_bad_row_tests(light_runs
    "bad_balls|bad_balls.csv:3: field 'balls': '10000' is not a size of the light goal"
    "bad_later|bad_later.csv:2: field 'later_s': '0.62,' is not a number of seconds"
    "bad_cache|bad_cache.csv:2: field 'kernel_cache': 'cold' is not one of warm, empty")
# Each kind apart, as for the hectare: on two_kinds.csv the Xeon's 10⁶ cell, which both goal tables must read, is
# read in one of them only, and both places are named with the words they should read (which one is behind, the
# script cannot tell), and nothing else is.
add_runs_fixture_test(light_runs check_holds_each_kind_apart 1
    "two_kinds.md: the summary of 37 lines matches two_kinds.csv\n[^\n]*two_kinds.md: the front goal table's 10⁶ light row, the Intel Xeon of CPU family 6, model 85's column \\(one of two places that must read it[^\n]*\n[^\n]*two_kinds.md: \"The goal table in full\"'s 10⁶ light row, the Intel Xeon of CPU family 6, model 85's column [^\n]* does not read \"\\| 4.91–5.18 s \\(first 5.25–5.45 s\\) \\|\"[^\n]*\n$"
    --runs ${LIGHT_RUNS_FIXTURE}/two_kinds.csv --check ${LIGHT_RUNS_FIXTURE}/two_kinds.md)
# The latest kernels by name, as for the hectare: older_kernels_last.csv adds a run of the Xeon's with the older kernels
# after its others; its summary gains that run's two rows, and its 10⁶ cell is still the one two_kinds.csv gives.
add_runs_fixture_test(light_runs check_takes_the_latest_kernels_by_name 1
    "two_kinds.md: its summary of the light goal's runs differs from older_kernels_last.csv's.*\n\\+\\| 10⁵ \\| library floor and ceil \\| the commit's own code \\| warm \\| 1 \\| 0 \\| 0.801 s [^\n]*\n.*\n[^\n]*two_kinds.md: the front goal table's 10⁶ light row, the Intel Xeon of CPU family 6, model 85's column [^\n]* does not read \"\\| 4.91–5.18 s \\(first 5.25–5.45 s\\) \\|\"[^\n]*\n[^\n]*two_kinds.md: \"The goal table in full\"'s 10⁶ light row, the Intel Xeon of CPU family 6, model 85's column [^\n]* does not read \"\\| 4.91–5.18 s \\(first 5.25–5.45 s\\) \\|\"[^\n]*\n$"
    --runs ${LIGHT_RUNS_FIXTURE}/older_kernels_last.csv --check ${LIGHT_RUNS_FIXTURE}/two_kinds.md)

# --write on the same fixtures (tests/docs/runs_write.py, each test a CTest of its own): a doc written from the runs
# before runs.csv's last (before.md, from runs_before.csv) is brought to read as runs.csv gives it, its summary and
# every quotation, so that --check passes; nothing else changes, a wrapped quotation keeps its line break, lines pushed
# past 120 characters are wrapped again without parting a number from its unit, and a second --write changes nothing.
# A quotation read in two places is left and named (exit 1), the earlier runs come from the last commit where --was
# does not name them, and without earlier runs (or with a committed file the doc cannot hold) the summary is written
# and the quotations named.
# The tests are the file's own `def test_NAME` methods, read from it, so that none is left out of CTest.
set(RUNS_WRITE_TEST ${PROJECT_SOURCE_DIR}/tests/docs/runs_write.py)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${RUNS_WRITE_TEST})
file(STRINGS ${RUNS_WRITE_TEST} RUNS_WRITE_METHODS REGEX "^    def test_[a-z0-9_]+\\(self\\):$")
foreach(method IN LISTS RUNS_WRITE_METHODS)
  string(REGEX REPLACE "^    def test_([a-z0-9_]+)\\(self\\):$" "\\1" name "${method}")
  add_test(NAME docs.runs_write.${name}
           COMMAND ${HELIOSTAND_TEST_PYTHON} ${RUNS_WRITE_TEST} RunsWrite.test_${name})
  set_tests_properties(docs.runs_write.${name} PROPERTIES LABELS "docs" TIMEOUT 60
                       ENVIRONMENT "PYTHONDONTWRITEBYTECODE=1")
endforeach()
