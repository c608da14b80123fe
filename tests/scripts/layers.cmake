# The layers of src/ (docs/architecture.md) are enforced by the build (cmake/HeliostandModule.cmake). These tests
# prove it: sources compiled exactly as a module's own (its include folder, its link line), which must fail where
# they include a layer above the module or VTK from a model, and must build where they include a layer below (the
# controls). The targets are not part of `all`; each test builds its own. They share the build tree, so they run one
# at a time (RESOURCE_LOCK).
set(LAYERS_DIR ${PROJECT_SOURCE_DIR}/tests/layers)
# How the compiler says an include was not found: GCC "X: No such file or directory", clang "'X' file not found"
# (the sanitizer tree is built with clang).
set(MISSING_HEADER "('? file not found|: No such file)")
function(layer_check name module source expect match)
  add_library(layers_${name} OBJECT EXCLUDE_FROM_ALL ${LAYERS_DIR}/${source})
  # The module's own include folders, read from its target: whatever the module compiles with, the check does.
  target_include_directories(layers_${name} PRIVATE $<TARGET_PROPERTY:heliostand_${module},INCLUDE_DIRECTORIES>)
  target_link_libraries(layers_${name} PRIVATE heliostand_${module})
  add_test(NAME layers.${name}
           COMMAND ${CMAKE_COMMAND} -DBUILD_DIR=${PROJECT_BINARY_DIR} -DTARGET=layers_${name} -DEXPECT=${expect}
                   "-DMATCH=${match}" -P ${LAYERS_DIR}/expect_build.cmake)
  set_tests_properties(layers.${name} PROPERTIES LABELS "unit" RESOURCE_LOCK build_tree TIMEOUT 900)
endfunction()
layer_check(model_cannot_include_the_stand light model_includes_stand.cpp fail "stand/stand\\.hpp${MISSING_HEADER}")
layer_check(model_includes_a_lower_layer light model_includes_lower_layer.cpp pass "")
layer_check(stand_cannot_include_io stand stand_includes_io.cpp fail "io/stand_output\\.hpp${MISSING_HEADER}")
layer_check(stand_includes_records stand stand_includes_records.cpp pass "")
layer_check(model_cannot_include_vtk architecture model_includes_vtk.cpp fail "vtkPolyData\\.h${MISSING_HEADER}")

# The models link alone: a program on heliostand_models and nothing above it grows and lights a tree.
add_executable(layers_models_only_program ${LAYERS_DIR}/models_only_program.cpp)
target_include_directories(layers_models_only_program PRIVATE ${PROJECT_BINARY_DIR}/layers/models)
target_link_libraries(layers_models_only_program PRIVATE heliostand_models)
add_test(NAME layers.models_link_alone COMMAND layers_models_only_program)
set_tests_properties(layers.models_link_alone PROPERTIES LABELS "unit" TIMEOUT 120
                     ENVIRONMENT "POCL_CACHE_DIR=${PROJECT_BINARY_DIR}/pocl-cache")

# No model includes toml++ (which, header-only under /usr/include, the include folders cannot keep out) or VTK.
add_test(NAME layers.models_include_no_toml_or_vtk
         COMMAND sh -c "! grep -rnE '#include <(toml|vtk)' '${PROJECT_SOURCE_DIR}/src/light' '${PROJECT_SOURCE_DIR}/src/architecture' '${PROJECT_SOURCE_DIR}/src/roots' '${PROJECT_SOURCE_DIR}/src/coupling' '${PROJECT_SOURCE_DIR}/src/hollow' '${PROJECT_SOURCE_DIR}/src/geometry' '${PROJECT_SOURCE_DIR}/src/rng' '${PROJECT_SOURCE_DIR}/src/compute' '${PROJECT_SOURCE_DIR}/src/core'")
set_tests_properties(layers.models_include_no_toml_or_vtk PROPERTIES LABELS "unit" TIMEOUT 60)

# What the test program's precompiled header stands for (tests/CMakeLists.txt): a test source without its own
# #include <gtest/gtest.h>, which the precompiled header would supply unseen, fails here.
add_test(NAME layers.test_sources_include_googletest
         COMMAND sh -c "! grep -rL --include='*_test.cpp' '#include <gtest/gtest.h>' '${PROJECT_SOURCE_DIR}/tests' | grep .")
set_tests_properties(layers.test_sources_include_googletest PROPERTIES LABELS "unit" TIMEOUT 60)
