# Defects a command-line probe found, each case from its reproducer (docs/errors.md): plan's
# options and outputs checked before planning, fit's outputs before the fit, a file path ending
# in '/' refused before anything is made, output directories named '-...' drawn by gnuplot,
# forces' flags, a table cut short refused by convert, messages naming what was written, and
# where the error line stands on stderr (tests/cli/scripts/probe_checks.sh MODE).
function(_probe_check name mode)
  add_test(NAME cli.${name}
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/scripts/probe_checks.sh ${mode} $<TARGET_FILE:nanopush>
                   ${CMAKE_CURRENT_BINARY_DIR}/probe/${mode})
  set_tests_properties(cli.${name} PROPERTIES ENVIRONMENT "NANOPUSH_SCENES=${NANOPUSH_SCENES}"
                       PASS_REGULAR_EXPRESSION "probe check ${mode}: ok" TIMEOUT 300)
endfunction()
_probe_check(plan.options_first plan_options)
_probe_check(fit.outputs_first fit_outputs)
_probe_check(outputs.trailing_slash trailing_slash)
_probe_check(plot.dash_dir dash_dir)
_probe_check(forces.flags forces)
_probe_check(convert.cut_short convert)
_probe_check(hardening.named_inputs messages)
_probe_check(hardening.stderr_lines stderr_lines)
