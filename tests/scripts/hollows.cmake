# Hollow figures (seed 004, Figs. 4.1-4.4 and beyond): the figure test writes the meshes as .vtp into
# <build>/validation/hollows/, pvbatch renders a close-up PNG of each into <build>/validation/hollows/png/ and
# check_png.py checks that they show something. Reported as skipped (exit 77) where ParaView, xvfb or apt are
# missing.
include(${PROJECT_SOURCE_DIR}/cmake/PvbatchRenderTests.cmake)
add_test(NAME hollow.figures.write_vtp
         COMMAND heliostand_tests --gtest_filter=FigureMeshes.WriteSeedLikeFiguresAsVtp)
set_tests_properties(hollow.figures.write_vtp PROPERTIES FIXTURES_SETUP heliostand_hollow_figures)

add_test(NAME hollow.figures.render
         COMMAND sh ${PROJECT_SOURCE_DIR}/validation/paraview/run_pvbatch.sh
                 ${PROJECT_SOURCE_DIR}/validation/hollows/render_hollows.py
                 ${PROJECT_BINARY_DIR}/validation/hollows/png
                 --figures ${PROJECT_BINARY_DIR}/validation/hollows ${PROJECT_BINARY_DIR}/validation/hollows/png)
set_tests_properties(hollow.figures.render PROPERTIES
  FIXTURES_REQUIRED heliostand_hollow_figures
  TIMEOUT 600)
heliostand_render_test(hollow.figures.render)

# render_hollows.py's stand mode (--stand FILE.vtm --focus X Y Z): a two-tree multiblock laid out like the
# stand output (block `trunk`, point data `tree_id`), one tree standing in front of the other's hollow.
add_test(NAME hollow.figures.render_stand_closeup
         COMMAND sh ${PROJECT_SOURCE_DIR}/validation/paraview/run_pvbatch.sh
                 ${PROJECT_SOURCE_DIR}/validation/hollows/stand_closeup_check.py
                 ${PROJECT_BINARY_DIR}/validation/hollows/png/stand
                 ${PROJECT_BINARY_DIR}/validation/hollows ${PROJECT_BINARY_DIR}/validation/hollows/png/stand)
set_tests_properties(hollow.figures.render_stand_closeup PROPERTIES
  FIXTURES_REQUIRED heliostand_hollow_figures
  TIMEOUT 600)
heliostand_render_test(hollow.figures.render_stand_closeup)
