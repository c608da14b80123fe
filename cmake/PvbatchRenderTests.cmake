# One headless X server (Xvfb) per test run for every ParaView render test, so successive and concurrent renders
# cannot race for a display (issue 15): a CTest fixture starts it before the first render test and stops it after
# the last; the render tests read its display from HELIOSTAND_XVFB_DIR (run_pvbatch.sh). Why Xvfb is started
# the way it is (-displayfd, -noreset): validation/paraview/xvfb.sh.
#
# Usage, after add_test: heliostand_render_test(TEST_NAME ...)
include_guard(GLOBAL)

set(HELIOSTAND_XVFB_DIR ${PROJECT_BINARY_DIR}/xvfb)

add_test(NAME paraview.xvfb.start
         COMMAND sh ${PROJECT_SOURCE_DIR}/validation/paraview/xvfb.sh start ${HELIOSTAND_XVFB_DIR})
set_tests_properties(paraview.xvfb.start PROPERTIES
  FIXTURES_SETUP heliostand_xvfb SKIP_RETURN_CODE 77 TIMEOUT 120 LABELS "paraview")
add_test(NAME paraview.xvfb.stop
         COMMAND sh ${PROJECT_SOURCE_DIR}/validation/paraview/xvfb.sh stop ${HELIOSTAND_XVFB_DIR})
set_tests_properties(paraview.xvfb.stop PROPERTIES
  FIXTURES_CLEANUP heliostand_xvfb TIMEOUT 120 LABELS "paraview")

# Marks each test as a pvbatch render: it needs the shared X server, reports exit 77 as skipped, and takes the
# `pvbatch` lock, which is about memory, not the display: one render of the example peaks at several GB.
function(heliostand_render_test)
  foreach(test IN LISTS ARGN)
    set_property(TEST ${test} APPEND PROPERTY FIXTURES_REQUIRED heliostand_xvfb)
    set_property(TEST ${test} APPEND PROPERTY ENVIRONMENT "HELIOSTAND_XVFB_DIR=${HELIOSTAND_XVFB_DIR}")
    set_property(TEST ${test} APPEND PROPERTY LABELS paraview)
    set_tests_properties(${test} PROPERTIES SKIP_RETURN_CODE 77 RESOURCE_LOCK pvbatch)
  endforeach()
endfunction()
