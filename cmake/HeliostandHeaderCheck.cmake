# heliostand_header_check(): the target heliostand_header_check, which compiles every header of every module on
# its own. For each src/M/**/*.hpp a generated translation unit (build/header_check/M/...hpp.cpp) includes that
# header and nothing else, and is compiled with module M's include folder (build/layers/M), M's usage requirements
# and the project's warnings. A header that leans on an include its users happen to make before it, or that reaches
# a layer above its module's, fails here; the unity build (CMAKE_UNITY_BUILD), which joins sources, cannot see
# either. Not part of `all`: the README's test command builds it by name.
function(heliostand_header_check)
  add_custom_target(heliostand_header_check)
  get_property(modules GLOBAL PROPERTY HELIOSTAND_MODULES)
  foreach(module IN LISTS modules)
    file(GLOB_RECURSE headers CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/${module}/*.hpp)
    if(NOT HELIOSTAND_OPENCL)
      list(FILTER headers EXCLUDE REGEX ".*/opencl_[^/]*\\.hpp$")
    endif()
    set(sources)
    foreach(header IN LISTS headers)
      file(RELATIVE_PATH included ${PROJECT_SOURCE_DIR}/src ${header})
      set(source ${PROJECT_BINARY_DIR}/header_check/${included}.cpp)
      file(CONFIGURE OUTPUT ${source} CONTENT "#include \"${included}\"  // and nothing else\n")
      list(APPEND sources ${source})
    endforeach()
    if(NOT sources)
      continue()
    endif()
    add_library(heliostand_header_check_${module} OBJECT EXCLUDE_FROM_ALL ${sources})
    set_target_properties(heliostand_header_check_${module} PROPERTIES UNITY_BUILD OFF)
    target_include_directories(heliostand_header_check_${module} PRIVATE ${PROJECT_BINARY_DIR}/layers/${module})
    target_compile_options(heliostand_header_check_${module} PRIVATE ${HELIOSTAND_WARNING_FLAGS})
    target_link_libraries(heliostand_header_check_${module} PRIVATE heliostand_${module})
    add_dependencies(heliostand_header_check heliostand_header_check_${module})
  endforeach()
endfunction()
