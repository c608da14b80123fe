# heliostand report (issue 11 item 6; src/report/, Debian's python3-matplotlib): the tiny stand grown as its
# scenario says (tree 4 thinned at age 23) and as an unthinned control (tests/report/grow_tiny_runs.sh), reported on
# its own and both compared on the same axes. tests/report/report_test.py checks that every chart is a PNG showing
# something and that report.md embeds it, that a blank chart fails that check, and that bad input or a missing
# interpreter or matplotlib is refused with a message and no report left. The driver needs python3 with
# matplotlib, as the command does.
set(REPORT_TESTS ${PROJECT_BINARY_DIR}/tests/report)
# Debian's python3 (HELIOSTAND_TEST_PYTHON, tests/CMakeLists.txt), for which python3-matplotlib installs.
set(PY ${HELIOSTAND_TEST_PYTHON})
set(REPORT_DRIVER ${PROJECT_SOURCE_DIR}/tests/report/report_test.py)
set(REPORT_TINY ${PROJECT_SOURCE_DIR}/stands/tiny/scenario.toml)

add_test(NAME cli.report.grow_tiny_runs
         COMMAND sh ${PROJECT_SOURCE_DIR}/tests/report/grow_tiny_runs.sh $<TARGET_FILE:heliostand> ${PROJECT_SOURCE_DIR}
                 ${REPORT_TESTS})
set_tests_properties(cli.report.grow_tiny_runs PROPERTIES FIXTURES_SETUP heliostand_report_runs TIMEOUT 300
                     ENVIRONMENT "POCL_CACHE_DIR=${PROJECT_BINARY_DIR}/pocl-cache")

# One run into its default folder RUN_DIR/report; tree 4's thinning at age 23 gives one before/after chart.
add_test(NAME cli.report.single_run
         COMMAND ${PY} ${REPORT_DRIVER} made $<TARGET_FILE:heliostand> ${REPORT_TESTS}/tiny-thinned/report 1
                 -- ${REPORT_TESTS}/tiny-thinned)
set_tests_properties(cli.report.single_run PROPERTIES
  FIXTURES_REQUIRED heliostand_report_runs FIXTURES_SETUP heliostand_report_single)

# Both runs on the same axes, labelled (a --label between the folders must not swallow the next folder); only the
# thinned run has a before/after chart.
add_test(NAME cli.report.compare_runs
         COMMAND ${PY} ${REPORT_DRIVER} made $<TARGET_FILE:heliostand> ${REPORT_TESTS}/comparison 1
                 -- ${REPORT_TESTS}/tiny-thinned --label "thinned at 23" ${REPORT_TESTS}/tiny-unthinned --label unthinned
                    --out ${REPORT_TESTS}/comparison)
set_tests_properties(cli.report.compare_runs PROPERTIES FIXTURES_REQUIRED heliostand_report_runs)

# The non-blank check can fail: the single run's stems chart painted one colour must be named blank.
add_test(NAME cli.report.blank_chart_fails_check
         COMMAND ${PY} ${REPORT_DRIVER} blank-fails ${REPORT_TESTS}/tiny-thinned/report stems_per_ha.png 1)
set_tests_properties(cli.report.blank_chart_fails_check PROPERTIES FIXTURES_REQUIRED heliostand_report_single)

# Bad input: exit status 2, the file (and line and column) named, no report folder.
add_test(NAME cli.report.missing_stand_table
         COMMAND sh -c "mkdir -p '${REPORT_TESTS}/not-a-run' && exec '${PY}' '${REPORT_DRIVER}' refused '$<TARGET_FILE:heliostand>' 2 'not-a-run/stand_table.csv: no such file' '${REPORT_TESTS}/not-a-run/report' -- '${REPORT_TESTS}/not-a-run'")
add_test(NAME cli.report.bad_number
         COMMAND sh -c "'${PY}' '${REPORT_DRIVER}' spoil '${REPORT_TESTS}/tiny-thinned' '${REPORT_TESTS}/bad-number' stand_table.csv 3 stand_age many && exec '${PY}' '${REPORT_DRIVER}' refused '$<TARGET_FILE:heliostand>' 2 \"bad-number/stand_table.csv:3:1: column stand_age: 'many' is not a number\" '${REPORT_TESTS}/bad-number/report' -- '${REPORT_TESTS}/bad-number'")
add_test(NAME cli.report.missing_column
         COMMAND sh -c "'${PY}' '${REPORT_DRIVER}' spoil '${REPORT_TESTS}/tiny-thinned' '${REPORT_TESTS}/missing-column' trees.csv 1 dbh_cm dbh && exec '${PY}' '${REPORT_DRIVER}' refused '$<TARGET_FILE:heliostand>' 2 'missing-column/trees.csv:1: missing column dbh_cm' '${REPORT_TESTS}/missing-column/report' -- '${REPORT_TESTS}/missing-column'")
set_tests_properties(cli.report.bad_number cli.report.missing_column PROPERTIES
                     FIXTURES_REQUIRED heliostand_report_runs)

# Missing software: exit status 1 and a message saying what to install.
add_test(NAME cli.report.without_python
         COMMAND ${PY} ${REPORT_DRIVER} refused $<TARGET_FILE:heliostand> 1 "apt-get install python3 python3-matplotlib"
                 ${REPORT_TESTS}/tiny-thinned/report-without-python HELIOSTAND_PYTHON=/nonexistent/python3
                 -- ${REPORT_TESTS}/tiny-thinned --out ${REPORT_TESTS}/tiny-thinned/report-without-python)
add_test(NAME cli.report.without_matplotlib
         COMMAND ${PY} ${REPORT_DRIVER} refused $<TARGET_FILE:heliostand> 1 "apt-get install python3-matplotlib"
                 ${REPORT_TESTS}/tiny-thinned/report-without-matplotlib
                 PYTHONPATH=${PROJECT_SOURCE_DIR}/tests/report/without_matplotlib
                 -- ${REPORT_TESTS}/tiny-thinned --out ${REPORT_TESTS}/tiny-thinned/report-without-matplotlib)
set_tests_properties(cli.report.without_python cli.report.without_matplotlib PROPERTIES
                     FIXTURES_REQUIRED heliostand_report_runs)
