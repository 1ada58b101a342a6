# A light command line (docs/performance.md, "Process start"): only nanopush-mpi links MPI;
# nanopush --version and run load no libmpi (tests/cli/scripts/startup_checks.sh).
add_test(NAME cli.startup.no_mpi
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/scripts/startup_checks.sh $<TARGET_FILE:nanopush>
                 ${CMAKE_CURRENT_BINARY_DIR}/startup)
set_tests_properties(cli.startup.no_mpi PROPERTIES ENVIRONMENT "NANOPUSH_SCENES=${NANOPUSH_SCENES}"
                     PASS_REGULAR_EXPRESSION "startup check: ok")
