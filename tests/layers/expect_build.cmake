# cmake -DBUILD_DIR=... -DTARGET=... -DEXPECT=fail|pass [-DMATCH=regex] -P expect_build.cmake
# Builds one target of the build tree and checks that it fails (with MATCH in the compiler's output: the reason we
# expect, not any failure) or that it builds.
execute_process(COMMAND ${CMAKE_COMMAND} --build ${BUILD_DIR} --target ${TARGET}
                RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
if(EXPECT STREQUAL "fail")
  if(result EQUAL 0)
    message(FATAL_ERROR "target ${TARGET} built, but it must not: a layer lets an upward include through")
  endif()
  if(NOT output MATCHES "${MATCH}")
    message(FATAL_ERROR "target ${TARGET} failed, but not because of `${MATCH}`:\n${output}")
  endif()
  message(STATUS "target ${TARGET} fails as it must: ${MATCH}")
else()
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "target ${TARGET} must build:\n${output}")
  endif()
  message(STATUS "target ${TARGET} builds")
endif()
