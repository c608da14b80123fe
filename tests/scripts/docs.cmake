# Every `docs/NAME.md "Section"` in the checkout names a section NAME.md has, and every `"Section" below` (or above) in
# a Markdown file one of its own on that side (tests/docs/section_references.py): a renamed, removed or moved section
# would otherwise leave code comments and docs pointing at nothing. The other two run the check on a small fixture
# whose broken references are known, so that a check that found nothing would fail.
set(DOCS_CHECK ${PROJECT_SOURCE_DIR}/tests/docs/section_references.py)

add_test(NAME docs.section_references_name_sections
         COMMAND ${HELIOSTAND_TEST_PYTHON} ${DOCS_CHECK} ${PROJECT_SOURCE_DIR})
set_tests_properties(docs.section_references_name_sections PROPERTIES LABELS "docs" TIMEOUT 60)

# The fixture's ten broken references (seven titles it lacks, one doc it lacks, two of its own sections said to lie on
# the wrong side), in file and line order, and its twelve good ones not reported.
set(DOCS_FIXTURE_REPORT
    "docs/guide.md:16: docs/guide.md has no section \"Not a heading\"\n"
    "docs/guide.md:19: docs/guide.md has no section \"Planting rows\" above\n"
    "docs/guide.md:19: docs/guide.md has its section \"Pruning\" below, not above\n"
    "docs/guide.md:19: docs/guide.md has its section \"Planting\" above, not below\n"
    "src/tree.cpp:4: docs/guide.md has no section \"Thinning from above\"\n"
    "src/tree.cpp:4: docs/guide.md has no section \"Planting rows\"\n"
    "src/tree.cpp:4: docs/guide.md has no section \"Thin\"\n"
    "src/tree.cpp:5: docs/other.md: no such file\n"
    "src/tree.cpp:6: docs/guide.md has no section \"Harvest\"\n"
    "src/tree.cpp:7: docs/guide.md has no section \"Roots\"\n"
    "22 references to sections of the docs read, 10 broken")
string(CONCAT DOCS_FIXTURE_REPORT ${DOCS_FIXTURE_REPORT})
add_test(NAME docs.section_references_check_reports_the_broken_ones
         COMMAND ${CMAKE_COMMAND} -DEXPECT_EXIT=1 "-DEXPECT_OUTPUT=^${DOCS_FIXTURE_REPORT}\n*$"
                 -P ${PROJECT_SOURCE_DIR}/tests/expect_exit_and_output.cmake
                 ${HELIOSTAND_TEST_PYTHON} ${DOCS_CHECK} ${PROJECT_SOURCE_DIR}/tests/docs/fixture)
set_tests_properties(docs.section_references_check_reports_the_broken_ones PROPERTIES LABELS "docs" TIMEOUT 60)
# The same where git cannot list the files (a source archive, as the mutation harness builds from): the script walks
# the folders instead, and must report the same references in the same order.
add_test(NAME docs.section_references_check_reports_the_same_outside_git
         COMMAND ${CMAKE_COMMAND} -E env GIT_DIR=${PROJECT_BINARY_DIR}/no-such-git-folder
                 ${CMAKE_COMMAND} -DEXPECT_EXIT=1 "-DEXPECT_OUTPUT=^${DOCS_FIXTURE_REPORT}\n*$"
                 -P ${PROJECT_SOURCE_DIR}/tests/expect_exit_and_output.cmake
                 ${HELIOSTAND_TEST_PYTHON} ${DOCS_CHECK} ${PROJECT_SOURCE_DIR}/tests/docs/fixture)
set_tests_properties(docs.section_references_check_reports_the_same_outside_git PROPERTIES LABELS "docs" TIMEOUT 60)
