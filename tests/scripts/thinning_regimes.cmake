# The worked thinning examples (stands/thinning-regimes/, one per regime family, docs/user-guide.md "Thinning"):
# `heliostand check` must accept every one, as a user would run it. One test per file, so a broken example is named;
# and one that the folder holds them, so that an emptied folder cannot pass by having nothing to check.
file(GLOB HELIOSTAND_THINNING_EXAMPLES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/stands/thinning-regimes/*.toml)
foreach(scenario IN LISTS HELIOSTAND_THINNING_EXAMPLES)
  get_filename_component(name ${scenario} NAME_WE)
  add_test(NAME example.thinning_regimes.check.${name} COMMAND $<TARGET_FILE:heliostand> check ${scenario})
  set_tests_properties(example.thinning_regimes.check.${name} PROPERTIES LABELS "examples")
endforeach()
list(LENGTH HELIOSTAND_THINNING_EXAMPLES HELIOSTAND_THINNING_EXAMPLE_COUNT)
add_test(NAME example.thinning_regimes.present
         COMMAND ${CMAKE_COMMAND} -E echo "${HELIOSTAND_THINNING_EXAMPLE_COUNT} thinning examples")
set_tests_properties(example.thinning_regimes.present PROPERTIES LABELS "examples"
                     PASS_REGULAR_EXPRESSION "^[1-9][0-9]* thinning examples")

# The regimes of the thinning walk-through (docs/user-guide.md "A thinning study"), the example stand under each.
file(GLOB HELIOSTAND_WALKTHROUGH_REGIMES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/stands/sobetsu/regimes/*.toml)
foreach(scenario IN LISTS HELIOSTAND_WALKTHROUGH_REGIMES)
  get_filename_component(name ${scenario} NAME_WE)
  add_test(NAME example.walkthrough.check.${name} COMMAND $<TARGET_FILE:heliostand> check ${scenario})
  set_tests_properties(example.walkthrough.check.${name} PROPERTIES LABELS "examples")
endforeach()
