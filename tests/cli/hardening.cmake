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
