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
