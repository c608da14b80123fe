# The mutation harness (validation/mutations/run.sh, on demand: ~20 minutes) applies each documented break as a
# patch. A change to the code a patch touches would leave the break unappliable and the harness unable to prove
# anything, so every patch must still apply to the committed sources (git apply --check, no change made). Skipped
# (exit 77) where the sources are not a git checkout. The same holds for the break that proves the sanitizer tree's
# unit-suite shards can fail (tests/sanitizers/one_past_the_end.patch: caught there, not in a Release tree, so it is
# applied by hand, not by the harness; docs/performance.md "Most of the unit suite under the sanitizers in CI").
file(GLOB HELIOSTAND_MUTATION_PATCHES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/validation/mutations/*.patch
     ${PROJECT_SOURCE_DIR}/tests/sanitizers/*.patch)
foreach(patch ${HELIOSTAND_MUTATION_PATCHES})
  get_filename_component(name ${patch} NAME_WE)
  add_test(NAME validation.mutations.applies.${name}
           COMMAND sh -c "git -C '${PROJECT_SOURCE_DIR}' rev-parse --git-dir >/dev/null 2>&1 || exit 77; exec git -C '${PROJECT_SOURCE_DIR}' apply --check '${patch}'")
  set_tests_properties(validation.mutations.applies.${name} PROPERTIES SKIP_RETURN_CODE 77 LABELS "validation" TIMEOUT 60)
endforeach()
# Every break the harness lists in mutations.tsv has its patch in the repository, and every patch there is listed:
# a patch left untracked passes the harness on the machine that wrote it and is missing from every clone (as
# docs_archive_files_unsorted.patch was for one commit), and a patch not listed is never run.
string(CONCAT HELIOSTAND_MUTATIONS_AGREE
       "mkdir -p \"$1\" && cd \"$0\""
       " && grep -v '^#' mutations.tsv | cut -f1 | sort > \"$1/listed\""
       " && ls *.patch | sed 's/[.]patch$//' | sort > \"$1/patches\""
       " && diff \"$1/listed\" \"$1/patches\"")
add_test(NAME validation.mutations.listed_and_patches_agree
         COMMAND sh -c "${HELIOSTAND_MUTATIONS_AGREE}"
                 ${PROJECT_SOURCE_DIR}/validation/mutations ${PROJECT_BINARY_DIR}/test-output/mutations-listed)
set_tests_properties(validation.mutations.listed_and_patches_agree PROPERTIES LABELS "validation" TIMEOUT 60)
