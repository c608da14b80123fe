# Seed-003 root validation (validation/roots/): the tropism demonstrations as measured quantities,
# averaged over seeds (GoogleTest, each TEST a CTest), and the rooting-depth report against
# Jackson et al. (1996). The report writes a Markdown table and asserts nothing, so it is not a test: it is the
# build target `roots_depth_report` (cmake --build build --target roots_depth_report; docs/roots.md).
file(GLOB HELIOSTAND_ROOTS_VALIDATION_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/validation/roots/*_validation.cpp)
add_library(heliostand_roots_experiments STATIC ${PROJECT_SOURCE_DIR}/validation/roots/root_experiments.cpp)
target_include_directories(heliostand_roots_experiments PUBLIC ${PROJECT_SOURCE_DIR}/validation/roots)
target_link_libraries(heliostand_roots_experiments PUBLIC heliostand_all)

add_executable(heliostand_roots_validation ${HELIOSTAND_ROOTS_VALIDATION_SOURCES})
target_link_libraries(heliostand_roots_validation PRIVATE heliostand_roots_experiments GTest::gtest GTest::gtest_main)
gtest_discover_tests(heliostand_roots_validation
  DISCOVERY_TIMEOUT 60
  PROPERTIES ENVIRONMENT "POCL_CACHE_DIR=${PROJECT_BINARY_DIR}/pocl-cache")

add_executable(heliostand_roots_depth_report ${PROJECT_SOURCE_DIR}/validation/roots/report/depth_profile_report.cpp)
target_link_libraries(heliostand_roots_depth_report PRIVATE heliostand_roots_experiments)
add_custom_target(roots_depth_report
  COMMAND heliostand_roots_depth_report ${PROJECT_BINARY_DIR}/validation/roots_depth_profile.md
  COMMENT "Rooting-depth profile vs Jackson et al. (1996) -> ${PROJECT_BINARY_DIR}/validation/roots_depth_profile.md"
  VERBATIM)
# A report that cannot be written is an error (exit status 2, naming the file and the reason), never a silent 0:
# /dev/full takes the open and refuses the bytes, so only a write checked at its close sees it.
add_test(NAME validation.roots.depth_report_unwritable
         COMMAND ${CMAKE_COMMAND} -DEXPECT_EXIT=2 "-DEXPECT_OUTPUT=cannot write /dev/full: No space left on device"
                 -P ${PROJECT_SOURCE_DIR}/tests/expect_exit_and_output.cmake
                 $<TARGET_FILE:heliostand_roots_depth_report> /dev/full)
set_tests_properties(validation.roots.depth_report_unwritable PROPERTIES TIMEOUT 120 LABELS "validation")
