# heliostand_module(NAME [USES module...] [EXTERNAL target...] [SOURCES file...] [EXCLUDE file...])
#
# One module of heliostand: the static library heliostand_NAME of every .cpp in src/NAME/ (recursively; without
# opencl_*.cpp when HELIOSTAND_OPENCL is off, and without the EXCLUDE file names), plus SOURCES.
#
# The layers are enforced twice:
#  - includes: the module's sources see one include folder, build/layers/NAME/, which holds symbolic links to
#    src/NAME and to the modules it reaches (those in USES, and what they reach), and nothing else.
#    `#include "stand/stand.hpp"` from a module that does not reach the stand finds no such file.
#  - links: the library links heliostand_M for each M in USES and the EXTERNAL targets, nothing else, so a call up a
#    layer is an undefined symbol when a program links.
# A module may only USE modules declared before it, so the order of the calls is the layering.
function(heliostand_module name)
  cmake_parse_arguments(PARSE_ARGV 1 MODULE "" "" "USES;EXTERNAL;SOURCES;EXCLUDE")
  set(folder ${PROJECT_SOURCE_DIR}/src/${name})
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS ${folder}/*.cpp)
  if(NOT HELIOSTAND_OPENCL)
    list(FILTER sources EXCLUDE REGEX ".*/opencl_[^/]*\\.cpp$")
  endif()
  foreach(excluded IN LISTS MODULE_EXCLUDE)
    list(FILTER sources EXCLUDE REGEX ".*/${excluded}$")
  endforeach()

  set(reachable ${name})
  foreach(module IN LISTS MODULE_USES)
    if(NOT TARGET heliostand_${module})
      message(FATAL_ERROR "heliostand module '${name}' uses '${module}', which is not declared before it")
    endif()
    get_property(below GLOBAL PROPERTY HELIOSTAND_REACHES_${module})
    list(APPEND reachable ${below})
  endforeach()
  list(REMOVE_DUPLICATES reachable)
  set_property(GLOBAL PROPERTY HELIOSTAND_REACHES_${name} ${reachable})
  heliostand_layer(${name} ${reachable})
  set(layer ${PROJECT_BINARY_DIR}/layers/${name})

  add_library(heliostand_${name} STATIC ${sources} ${MODULE_SOURCES})
  target_include_directories(heliostand_${name} PRIVATE ${layer})
  target_compile_options(heliostand_${name} PRIVATE ${HELIOSTAND_WARNING_FLAGS})
  list(TRANSFORM MODULE_USES PREPEND heliostand_ OUTPUT_VARIABLE used_libraries)
  target_link_libraries(heliostand_${name} PUBLIC ${used_libraries} ${MODULE_EXTERNAL})
  set_property(GLOBAL APPEND PROPERTY HELIOSTAND_MODULES ${name})
endfunction()

# heliostand_layer(NAME module...): the include folder build/layers/NAME with a link to src/M for each module M.
function(heliostand_layer name)
  set(layer ${PROJECT_BINARY_DIR}/layers/${name})
  file(REMOVE_RECURSE ${layer})
  file(MAKE_DIRECTORY ${layer})
  foreach(module IN LISTS ARGN)
    file(CREATE_LINK ${PROJECT_SOURCE_DIR}/src/${module} ${layer}/${module} SYMBOLIC)
  endforeach()
endfunction()

# heliostand_module_group(NAME module...): the INTERFACE library heliostand_NAME of several modules, and the include
# folder build/layers/NAME of everything they reach (for a program that may use those modules and nothing above).
function(heliostand_module_group name)
  add_library(heliostand_${name} INTERFACE)
  set(reachable)
  foreach(module IN LISTS ARGN)
    target_link_libraries(heliostand_${name} INTERFACE heliostand_${module})
    get_property(below GLOBAL PROPERTY HELIOSTAND_REACHES_${module})
    list(APPEND reachable ${below})
  endforeach()
  list(REMOVE_DUPLICATES reachable)
  heliostand_layer(${name} ${reachable})
endfunction()
