# A light command line (docs/performance.md, "Process start"): only nanopush-mpi links MPI;
# nanopush --version and run load no libmpi (tests/cli/scripts/startup_checks.sh).
add_test(NAME cli.startup.no_mpi
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/scripts/startup_checks.sh $<TARGET_FILE:nanopush>
                 ${CMAKE_CURRENT_BINARY_DIR}/startup)
set_tests_properties(cli.startup.no_mpi PROPERTIES ENVIRONMENT "NANOPUSH_SCENES=${NANOPUSH_SCENES}"
                     PASS_REGULAR_EXPRESSION "startup check: ok")
# With NANOPUSH_STATIC_DEPS (the default) the plain command line takes SUNDIALS, LAPACK/BLAS and
# the Fortran run time from their archives, and with GCC (static libraries, unsanitized) the
# C++ run time and libgcc too: none of them is a shared object it links or loads. toml++ is
# compiled into nanopush_scenes in every configuration (startup_checks.sh: no command loads it).
if(NANOPUSH_STATIC_DEPS)
  set(_static_libs "sundials|lapack|blas|gfortran|quadmath|tomlplusplus")
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND NOT NANOPUSH_SANITIZE AND NOT BUILD_SHARED_LIBS)
    string(APPEND _static_libs "|stdc\\+\\+|gcc_s")
  endif()
  add_test(NAME cli.startup.static_deps
           COMMAND bash -c "set -euo pipefail; deps=$(ldd \"$1\"); \
if grep -E 'lib(${_static_libs})' <<< \"$deps\"; then echo 'FAIL: linked shared'; exit 1; fi; \
echo \"$deps\" | wc -l | xargs echo shared objects:; \"$1\" --version" _ $<TARGET_FILE:nanopush>)
  set_tests_properties(cli.startup.static_deps PROPERTIES PASS_REGULAR_EXPRESSION "shared objects: [0-9]+\nnanopush [0-9]")
endif()
