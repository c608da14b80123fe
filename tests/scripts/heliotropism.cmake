# Seed 000 (heliotropism) validation: parameter sweeps of the dichotomy model with the paper's findings asserted
# (validation/heliotropism), reduced sizes so CTest stays within a couple of minutes; the metrics table goes to
# build/validation/heliotropism/heliotropism_metrics.md. The same program runs one stands/kanamaru-* scenario.
add_executable(heliotropism_validation ${PROJECT_SOURCE_DIR}/validation/heliotropism/heliotropism_validation.cpp)
target_link_libraries(heliotropism_validation PRIVATE heliostand_core)
target_include_directories(heliotropism_validation PRIVATE ${PROJECT_SOURCE_DIR}/src)

add_test(NAME validation.heliotropism.findings
         COMMAND heliotropism_validation validate ${PROJECT_BINARY_DIR}/validation/heliotropism)
set_tests_properties(validation.heliotropism.findings PROPERTIES TIMEOUT 600 LABELS "validation")

add_test(NAME validation.heliotropism.table1_scenario
         COMMAND heliotropism_validation run ${PROJECT_SOURCE_DIR}/stands/kanamaru-fig10e/scenario.toml
                 ${PROJECT_BINARY_DIR}/validation/heliotropism/fig10e)
set_tests_properties(validation.heliotropism.table1_scenario PROPERTIES TIMEOUT 600 LABELS "validation")
