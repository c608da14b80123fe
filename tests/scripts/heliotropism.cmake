# Seed 000 (heliotropism) validation: parameter sweeps of the dichotomy model with the paper's findings asserted
# (validation/heliotropism), reduced sizes (about 5 min on the loaded shared 2 cores, less alone); the metrics table goes to
# build/validation/heliotropism/heliotropism_metrics.md. The same program runs one stands/kanamaru-* scenario.
include(${PROJECT_SOURCE_DIR}/cmake/PvbatchRenderTests.cmake)
add_executable(heliotropism_validation ${PROJECT_SOURCE_DIR}/validation/heliotropism/heliotropism_validation.cpp
                                      ${PROJECT_SOURCE_DIR}/validation/heliotropism/crown_shape.cpp)
target_link_libraries(heliotropism_validation PRIVATE heliostand_all)
target_include_directories(heliotropism_validation PRIVATE ${PROJECT_SOURCE_DIR}/src)
# Fig. 6 reads its two layouts from stands/kanamaru-fig6-*.
target_compile_definitions(heliotropism_validation PRIVATE HELIOSTAND_SOURCE_DIR="${PROJECT_SOURCE_DIR}")

add_test(NAME validation.heliotropism.findings
         COMMAND heliotropism_validation validate ${PROJECT_BINARY_DIR}/validation/heliotropism)
set_tests_properties(validation.heliotropism.findings PROPERTIES TIMEOUT 900 LABELS "validation"
                     FIXTURES_SETUP heliostand_heliotropism_sweeps)

# The sweeps' pictures: the findings run leaves one tree per sweep value in validation/heliotropism/trees;
# pvbatch draws each sweep's trees side by side (fig05_side.png ... fig14_side.png, fig10_top.png) into
# build/validation/heliotropism, and run_pvbatch.sh checks the images show something.
add_test(NAME validation.heliotropism.render_sweeps
         COMMAND sh ${PROJECT_SOURCE_DIR}/validation/paraview/run_pvbatch.sh
                 ${PROJECT_SOURCE_DIR}/validation/heliotropism/render_sweeps.py
                 ${PROJECT_BINARY_DIR}/validation/heliotropism/render
                 ${PROJECT_BINARY_DIR}/validation/heliotropism/trees
                 ${PROJECT_BINARY_DIR}/validation/heliotropism)
set_tests_properties(validation.heliotropism.render_sweeps PROPERTIES
  FIXTURES_REQUIRED heliostand_heliotropism_sweeps
  TIMEOUT 600)
heliostand_render_test(validation.heliotropism.render_sweeps)

# The runner end to end on a small scenario (the full Table 1 tree, stands/kanamaru-fig10e, takes minutes).
# Through tests/expect_exit_and_output.cmake: the exit status and the message are both checked (CTest's
# PASS_REGULAR_EXPRESSION alone would ignore the status).
set(HELIOSTAND_EXPECT ${PROJECT_SOURCE_DIR}/tests/expect_exit_and_output.cmake)
add_test(NAME validation.heliotropism.run_scenario
         COMMAND ${CMAKE_COMMAND} -DEXPECT_EXIT=0 "-DEXPECT_OUTPUT=12 generations, [1-9][0-9]* living tips"
                 -P ${HELIOSTAND_EXPECT}
                 $<TARGET_FILE:heliotropism_validation> run ${PROJECT_SOURCE_DIR}/stands/kanamaru-ci/scenario.toml
                 ${PROJECT_BINARY_DIR}/validation/heliotropism/kanamaru-ci)
set_tests_properties(validation.heliotropism.run_scenario PROPERTIES TIMEOUT 300 LABELS "validation")
# Bad input: every bad key reported with file, line and key, exit status 2.
add_test(NAME validation.heliotropism.bad_scenario
         COMMAND ${CMAKE_COMMAND} -DEXPECT_EXIT=2
                 "-DEXPECT_OUTPUT=scenario.toml:3: key .model.kind.*trichotomy.*scenario.toml:4: key .model.heliotropism.*scenario.toml:5: key .model.leaf_radius."
                 -P ${HELIOSTAND_EXPECT}
                 $<TARGET_FILE:heliotropism_validation> run ${PROJECT_SOURCE_DIR}/stands/kanamaru-bad/scenario.toml
                 ${PROJECT_BINARY_DIR}/validation/heliotropism/kanamaru-bad)
# A findings report that cannot be written (here a folder stands where heliotropism_metrics.md goes) is an error,
# exit status 2 naming the file and the reason, whatever the findings: one quick figure at one seed.
set(HELIOSTAND_UNWRITABLE_FINDINGS ${PROJECT_BINARY_DIR}/validation/heliotropism-unwritable)
add_test(NAME validation.heliotropism.unwritable_report
         COMMAND sh -c "mkdir -p \"$1/heliotropism_metrics.md\" && shift && exec \"$@\"" sh ${HELIOSTAND_UNWRITABLE_FINDINGS}
                 ${CMAKE_COMMAND} -DEXPECT_EXIT=2
                 "-DEXPECT_OUTPUT=cannot write [^ ]*/heliotropism_metrics.md: Is a directory" -P ${HELIOSTAND_EXPECT}
                 $<TARGET_FILE:heliotropism_validation> validate ${HELIOSTAND_UNWRITABLE_FINDINGS} --only 10 --seeds 1)
set_tests_properties(validation.heliotropism.unwritable_report PROPERTIES TIMEOUT 300 LABELS "validation")
# A crown file that cannot be written whole (files may not grow past 4 KiB: `ulimit -f 4`, SIGXFSZ ignored, as on a
# full disk): exit status 1 naming the file and the reason, VTK's own error as one log line ("error: VTK (...)"),
# not VTK's coloured, time-stamped dump of the pipeline request (the "ERR|" lines and "Modified Time" of its format).
add_test(NAME validation.heliotropism.full_disk
         COMMAND ${CMAKE_COMMAND} -DEXPECT_EXIT=1
                 "-DEXPECT_OUTPUT=error: VTK \\(vtk[A-Za-z]+\\.cxx:[0-9]+\\): .*vtkXMLPolyDataWriter.*error: cannot write [^ ]*/crown_gen_[0-9]+\\.vtp: File too large"
                 -P ${HELIOSTAND_EXPECT}
                 bash -c "trap '' XFSZ && ulimit -f 4 && exec \"$0\" run \"$1\" \"$2\""
                 $<TARGET_FILE:heliotropism_validation> ${PROJECT_SOURCE_DIR}/stands/kanamaru-ci/scenario.toml
                 ${PROJECT_BINARY_DIR}/validation/heliotropism/kanamaru-full-disk)
set_tests_properties(validation.heliotropism.full_disk PROPERTIES TIMEOUT 300 LABELS "validation"
                     FAIL_REGULAR_EXPRESSION "ERR\\||Modified Time")
# Figs. 16-17 on the conifer (validation/heliotropism/conifer_findings_validation.cpp; GoogleTest, each TEST a CTest).
add_executable(heliostand_conifer_findings ${PROJECT_SOURCE_DIR}/validation/heliotropism/conifer_findings_validation.cpp)
target_include_directories(heliostand_conifer_findings PRIVATE ${PROJECT_SOURCE_DIR}/src ${PROJECT_SOURCE_DIR}/tests)
target_link_libraries(heliostand_conifer_findings PRIVATE heliostand_all GTest::gtest GTest::gtest_main)
gtest_discover_tests(heliostand_conifer_findings
  DISCOVERY_TIMEOUT 60
  PROPERTIES ENVIRONMENT "POCL_CACHE_DIR=${PROJECT_BINARY_DIR}/pocl-cache" LABELS "validation")
