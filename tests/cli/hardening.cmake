# Hardening: bad input of every kind, external programs, interrupts (docs/errors.md). Each
# check asserts the exit status, the message and that nothing was left behind
# (tests/cli/scripts/hardening_checks.sh).
set(_np $<TARGET_FILE:nanopush>)
set(_hard_sh ${CMAKE_CURRENT_SOURCE_DIR}/cli/scripts/hardening_checks.sh)
foreach(_mode options scene programs interrupt)
  add_test(NAME cli.hardening.${_mode} COMMAND bash ${_hard_sh} ${_mode} ${_np} ${CMAKE_CURRENT_BINARY_DIR}/hardening/${_mode})
  set_tests_properties(cli.hardening.${_mode} PROPERTIES ENVIRONMENT "NANOPUSH_SCENES=${NANOPUSH_SCENES}"
                       PASS_REGULAR_EXPRESSION "hardening check ${_mode}: ok")
endforeach()

# The bad-input sweep on one rough preset (every key x 14 hostile values through --set): no
# signal, no undocumented status, every refusal names its field, nothing left behind. The
# sweep over every preset is run by hand: bash tests/cli/scripts/bad_input_sweep.sh NANOPUSH DIR.
add_test(NAME cli.hardening.bad_input_sweep
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/scripts/bad_input_sweep.sh ${_np}
                 ${CMAKE_CURRENT_BINARY_DIR}/hardening/sweep fig3_18)
set_tests_properties(cli.hardening.bad_input_sweep PROPERTIES ENVIRONMENT "NANOPUSH_SCENES=${NANOPUSH_SCENES}"
                     PASS_REGULAR_EXPRESSION "bad-input sweep: ok" TIMEOUT 300)

# Issue 34 (docs/errors.md): merge, conflicts, exit codes, messages; MPI that stops cleanly
# (tests/cli/scripts/issue34_checks.sh, each case from the issue's reproducer).
set(_i34_sh ${CMAKE_CURRENT_SOURCE_DIR}/cli/scripts/issue34_checks.sh)
foreach(_mode conflicts merge messages)
  add_test(NAME cli.hardening.${_mode} COMMAND bash ${_i34_sh} ${_mode} ${_np} ${CMAKE_CURRENT_BINARY_DIR}/hardening/i34_${_mode})
  set_tests_properties(cli.hardening.${_mode} PROPERTIES ENVIRONMENT "NANOPUSH_SCENES=${NANOPUSH_SCENES}"
                       PASS_REGULAR_EXPRESSION "issue 34 check ${_mode}: ok" TIMEOUT 300)
endforeach()
if(NANOPUSH_MPI)
  add_test(NAME cli.hardening.mpi_signal
           COMMAND bash ${_i34_sh} mpi_signal ${_np} ${CMAKE_CURRENT_BINARY_DIR}/hardening/i34_mpi_signal ${MPIEXEC_EXECUTABLE})
  set_tests_properties(cli.hardening.mpi_signal PROPERTIES PASS_REGULAR_EXPRESSION "issue 34 check mpi_signal: ok"
    TIMEOUT 600 RUN_SERIAL TRUE
    ENVIRONMENT "NANOPUSH_SCENES=${NANOPUSH_SCENES};OMPI_ALLOW_RUN_AS_ROOT=1;OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1;OMPI_MCA_rmaps_base_oversubscribe=1")
endif()
