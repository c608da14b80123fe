# heliostand batch (issue 12 item 1): a small manifest (2 tiny stands x 2 scenarios x 2 seeds, three years, tables
# only, reference solvers) on the local worker pool and spread over 2 MPI ranks must give the same bytes in every
# file (run.json's timings excluded); a batch with one bad run must finish the others and report it; a batch
# started again over an unfinished one completes it. tests/batch/batch_test.py does the checks. The batches
# compared run one after another at one path (tests/batch/batch_at_root.sh says why), hence the resource lock.
set(BATCH_TESTS ${PROJECT_BINARY_DIR}/tests/batch)
set(BATCH_SOURCES ${PROJECT_SOURCE_DIR}/tests/batch)
set(BATCH_DRIVER ${BATCH_SOURCES}/batch_test.py)
set(BATCH_AT_ROOT sh ${BATCH_SOURCES}/batch_at_root.sh ${BATCH_TESTS}/root)
set(BATCH_ENV "POCL_CACHE_DIR=${PROJECT_BINARY_DIR}/pocl-cache")

add_test(NAME cli.batch.local_pool
         COMMAND ${BATCH_AT_ROOT} ${BATCH_TESTS}/local fresh
                 $<TARGET_FILE:heliostand> batch ${BATCH_SOURCES}/two_stands.toml --out ${BATCH_TESTS}/root --jobs 2)
set_tests_properties(cli.batch.local_pool PROPERTIES FIXTURES_SETUP heliostand_batch_local TIMEOUT 300
                     RESOURCE_LOCK heliostand_batch_root ENVIRONMENT "${BATCH_ENV}")

# One run fails (exit status 1); the other two finish and summary.csv names the failure and its reason.
add_test(NAME cli.batch.one_run_fails
         COMMAND sh -c "'$<TARGET_FILE:heliostand>' batch '${BATCH_SOURCES}/one_fails.toml' --out '${BATCH_TESTS}/one-fails' --jobs 2 --force; exec python3 '${BATCH_DRIVER}' one-fails '${BATCH_TESTS}/one-fails' $? broken/as-is/seed-1 output_interval")
set_tests_properties(cli.batch.one_run_fails PROPERTIES TIMEOUT 300 ENVIRONMENT "${BATCH_ENV}")

# A batch started again over an unfinished one (a run without run.json, no summary yet) keeps the finished runs,
# grows the unfinished one again, and ends as the uninterrupted batch did.
add_test(NAME cli.batch.restart_completes_unfinished_runs
         COMMAND sh -c "rm -rf '${BATCH_TESTS}/unfinished' && cp -r '${BATCH_TESTS}/local' '${BATCH_TESTS}/unfinished' && rm '${BATCH_TESTS}/unfinished/runs/corner/sparse-sky/seed-2/run.json' '${BATCH_TESTS}/unfinished/summary.csv' && sh '${BATCH_SOURCES}/batch_at_root.sh' '${BATCH_TESTS}/root' '${BATCH_TESTS}/restarted' '${BATCH_TESTS}/unfinished' '$<TARGET_FILE:heliostand>' batch '${BATCH_SOURCES}/two_stands.toml' --out '${BATCH_TESTS}/root' --jobs 2 && exec python3 '${BATCH_DRIVER}' same '${BATCH_TESTS}/local' '${BATCH_TESTS}/restarted' --regrown corner/sparse-sky/seed-2")
set_tests_properties(cli.batch.restart_completes_unfinished_runs PROPERTIES FIXTURES_REQUIRED heliostand_batch_local
                     TIMEOUT 300 RESOURCE_LOCK heliostand_batch_root ENVIRONMENT "${BATCH_ENV}")

if(MPI_CXX_FOUND AND MPIEXEC_EXECUTABLE)
  # Open MPI refuses to start as root (CI's container) without the two OMPI_ALLOW_* variables; containers also
  # forbid the shared-memory transport's single-copy mechanism (ptrace), which the ranks do not need.
  add_test(NAME cli.batch.mpi_ranks
           COMMAND ${BATCH_AT_ROOT} ${BATCH_TESTS}/mpi fresh
                   ${MPIEXEC_EXECUTABLE} ${MPIEXEC_NUMPROC_FLAG} 2 --oversubscribe
                   $<TARGET_FILE:heliostand> batch ${BATCH_SOURCES}/two_stands.toml --out ${BATCH_TESTS}/root)
  set_tests_properties(cli.batch.mpi_ranks PROPERTIES FIXTURES_SETUP heliostand_batch_mpi TIMEOUT 300
                       RESOURCE_LOCK heliostand_batch_root
                       ENVIRONMENT "${BATCH_ENV};OMPI_ALLOW_RUN_AS_ROOT=1;OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1;OMPI_MCA_btl_vader_single_copy_mechanism=none")
  if(HELIOSTAND_SANITIZE)  # Open MPI's own leaks are suppressed by library (sanitizers/lsan.supp), on whole stacks
    set_tests_properties(cli.batch.mpi_ranks PROPERTIES ENVIRONMENT_MODIFICATION
                         "${HELIOSTAND_LSAN_SUPPRESSIONS}:fast_unwind_on_malloc=0")
  endif()
  add_test(NAME cli.batch.mpi_equals_local_pool
           COMMAND python3 ${BATCH_DRIVER} same ${BATCH_TESTS}/local ${BATCH_TESTS}/mpi)
  set_tests_properties(cli.batch.mpi_equals_local_pool PROPERTIES
                       FIXTURES_REQUIRED "heliostand_batch_local;heliostand_batch_mpi")
endif()
