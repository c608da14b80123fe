# Seed 000 (heliotropism) validation: parameter sweeps of the dichotomy model with the paper's findings asserted
# (validation/heliotropism), reduced sizes so CTest stays within a couple of minutes; the metrics table goes to
# build/validation/heliotropism/heliotropism_metrics.md. The same program runs one stands/kanamaru-* scenario.
include(${PROJECT_SOURCE_DIR}/cmake/PvbatchRenderTests.cmake)
add_executable(heliotropism_validation ${PROJECT_SOURCE_DIR}/validation/heliotropism/heliotropism_validation.cpp)
target_link_libraries(heliotropism_validation PRIVATE heliostand_core)
target_include_directories(heliotropism_validation PRIVATE ${PROJECT_SOURCE_DIR}/src)

add_test(NAME validation.heliotropism.findings
         COMMAND heliotropism_validation validate ${PROJECT_BINARY_DIR}/validation/heliotropism)
set_tests_properties(validation.heliotropism.findings PROPERTIES TIMEOUT 600 LABELS "validation"
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
add_test(NAME validation.heliotropism.run_scenario
         COMMAND heliotropism_validation run ${PROJECT_SOURCE_DIR}/stands/kanamaru-ci/scenario.toml
                 ${PROJECT_BINARY_DIR}/validation/heliotropism/kanamaru-ci)
set_tests_properties(validation.heliotropism.run_scenario PROPERTIES TIMEOUT 300 LABELS "validation"
                     PASS_REGULAR_EXPRESSION "12 generations, [1-9][0-9]* living tips")
# Bad input: every bad key reported with file, line and key, exit status 2.
add_test(NAME validation.heliotropism.bad_scenario
         COMMAND heliotropism_validation run ${PROJECT_SOURCE_DIR}/stands/kanamaru-bad/scenario.toml
                 ${PROJECT_BINARY_DIR}/validation/heliotropism/kanamaru-bad)
set_tests_properties(validation.heliotropism.bad_scenario PROPERTIES
  PASS_REGULAR_EXPRESSION "scenario.toml:3: key .model.kind.*trichotomy.*scenario.toml:4: key .model.heliotropism.*scenario.toml:5: key .model.leaf_radius.")
