# Seed-003 crown–root coupling validation (validation/coupling/): the sky-light, soil-nutrient and
# root-pruning demonstrations as measured quantities averaged over seeds (GoogleTest, each TEST a CTest).
add_executable(heliostand_coupling_validation
  ${PROJECT_SOURCE_DIR}/validation/coupling/coupling_experiments.cpp
  ${PROJECT_SOURCE_DIR}/validation/coupling/coupling_validation.cpp)
target_include_directories(heliostand_coupling_validation PRIVATE ${PROJECT_SOURCE_DIR}/validation/coupling)
target_link_libraries(heliostand_coupling_validation PRIVATE heliostand_all GTest::gtest GTest::gtest_main)
gtest_discover_tests(heliostand_coupling_validation
  DISCOVERY_TIMEOUT 60
  PROPERTIES ENVIRONMENT "POCL_CACHE_DIR=${PROJECT_BINARY_DIR}/pocl-cache" LABELS "validation")
