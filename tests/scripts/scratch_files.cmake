# The unit tests leave no scratch files behind: the survey, scenario and soil tests write their inputs under
# GoogleTest's temporary folder (tests/survey/survey_test_files.hpp), one folder per test and process, and delete
# them when the process exits. Here that folder is one of the test's own (TEST_TMPDIR), and nothing may be left below
# its heliostand_inputs/ after a run of tests that write inputs, not even an empty folder.
set(HELIOSTAND_SCRATCH_TMPDIR ${PROJECT_BINARY_DIR}/test-output/scratch-files)
add_test(NAME unit.scratch_files_removed
         COMMAND sh -c "rm -rf \"$1\" && mkdir -p \"$1\" && TEST_TMPDIR=\"$1/\" \"$2\" --gtest_filter='SurveyUnits.*:SurveySeparators.*:ThinningRegimesScenario.*:TomlFile.*' || exit 1
                        left=$(find \"$1\" -mindepth 2 | head -3); [ -z \"$left\" ] || { echo \"scratch files left behind: $left\"; exit 1; }"
                 sh ${HELIOSTAND_SCRATCH_TMPDIR} $<TARGET_FILE:heliostand_tests>)
set_tests_properties(unit.scratch_files_removed PROPERTIES LABELS "input" TIMEOUT 300
                     ENVIRONMENT "POCL_CACHE_DIR=${PROJECT_BINARY_DIR}/pocl-cache")
