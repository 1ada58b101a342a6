# The CSV convention (docs/outputs.md) on everything nanopush writes: every CSV of
# `reproduce --quick` has a valid Table Schema sidecar whose fields are the header, each with
# a unit and a description; headers are plain identifiers; no cell spells nan.
set(_np $<TARGET_FILE:nanopush>)
set(_env "NANOPUSH_SCENES=${NANOPUSH_SCENES}")
set(_check ${CMAKE_CURRENT_LIST_DIR}/scripts/check_sidecars.cmake)

set(_out ${CMAKE_CURRENT_BINARY_DIR}/outputs-reproduce-quick)
add_test(NAME cli.outputs.reproduce_clean COMMAND ${CMAKE_COMMAND} -E rm -rf ${_out})
set_tests_properties(cli.outputs.reproduce_clean PROPERTIES FIXTURES_SETUP cli_outputs_clean)
add_test(NAME cli.outputs.reproduce COMMAND ${_np} reproduce --quick --out ${_out})
set_tests_properties(cli.outputs.reproduce PROPERTIES ENVIRONMENT "${_env}" TIMEOUT 900
  FIXTURES_REQUIRED cli_outputs_clean FIXTURES_SETUP cli_outputs_reproduce)
add_test(NAME cli.outputs.sidecars COMMAND ${CMAKE_COMMAND} -DDIR=${_out} -DMIN_FILES=60 -P ${_check})
set_tests_properties(cli.outputs.sidecars PROPERTIES FIXTURES_REQUIRED cli_outputs_reproduce TIMEOUT 300)

# The subcommands' own CSV files: run (scene recorded), icor tables, bench, friction --bench-csv.
set(_cmd ${CMAKE_CURRENT_BINARY_DIR}/outputs-commands)
add_test(NAME cli.outputs.commands_clean COMMAND ${CMAKE_COMMAND} -E rm -rf ${_cmd})
set_tests_properties(cli.outputs.commands_clean PROPERTIES FIXTURES_SETUP cli_outputs_cmd_clean)
function(_outputs_command name)
  add_test(NAME cli.outputs.command_${name} COMMAND ${_np} ${ARGN})
  set_tests_properties(cli.outputs.command_${name} PROPERTIES ENVIRONMENT "${_env}"
    FIXTURES_REQUIRED cli_outputs_cmd_clean FIXTURES_SETUP cli_outputs_cmd)
endfunction()
_outputs_command(run run fig3_6c --out ${_cmd}/run/fig3_6c.csv --quiet)
_outputs_command(icor_formulas icor formulas --n 5 --out ${_cmd}/icor/formulas.csv)
_outputs_command(icor_roots icor roots --yn 0 --yn 1e-9 --out ${_cmd}/icor/roots.csv)
_outputs_command(icor_rectangle icor rectangle --n 3 --out ${_cmd}/icor/rectangle.csv)
_outputs_command(icor_dynamic icor dynamic --yn 1e-7 --force-ratio 0.5 --force-ratio 2 --out ${_cmd}/icor/dynamic.csv)
_outputs_command(icor_estimate_mu icor estimate-mu --force 1e-6 --yn 2e-7 --yn-sigma 5e-9 --out ${_cmd}/icor/mu.csv)
_outputs_command(friction_bench friction --bench --bench-seconds 0.001 --bench-csv ${_cmd}/friction/bench.csv)
_outputs_command(bench bench fig3_6a --quick --quiet --no-plot --engines cxx-faithful --out ${_cmd}/bench/bench.csv)
add_test(NAME cli.outputs.command_sidecars COMMAND ${CMAKE_COMMAND} -DDIR=${_cmd} -DMIN_FILES=8 -P ${_check})
set_tests_properties(cli.outputs.command_sidecars PROPERTIES FIXTURES_REQUIRED cli_outputs_cmd)
add_test(NAME cli.outputs.run_scene COMMAND ${CMAKE_COMMAND} -DDIR=${_cmd}/run -DSCENE=fig3_6c -P ${_check})
set_tests_properties(cli.outputs.run_scene PROPERTIES FIXTURES_REQUIRED cli_outputs_cmd)
# The sidecar's provenance: the command line as typed, the version; the CSV itself holds no date.
add_test(NAME cli.outputs.run_provenance COMMAND ${CMAKE_COMMAND} -E cat ${_cmd}/run/fig3_6c.schema.json)
set_tests_properties(cli.outputs.run_provenance PROPERTIES FIXTURES_REQUIRED cli_outputs_cmd
  PASS_REGULAR_EXPRESSION "\"command\": \"nanopush run fig3_6c --out [^\"]*/run/fig3_6c.csv --quiet\"")

# Figures (issue 22 item 5): --format svg, theta0 digits in the Fig 3.6 table, plain labels,
# the .gp beside each figure re-runs from inside the output directory.
set(_figs ${CMAKE_CURRENT_BINARY_DIR}/outputs-figures-svg)
add_test(NAME cli.outputs.figures_clean COMMAND ${CMAKE_COMMAND} -E rm -rf ${_figs})
set_tests_properties(cli.outputs.figures_clean PROPERTIES FIXTURES_SETUP cli_outputs_figures_clean)
add_test(NAME cli.outputs.figures_svg COMMAND ${_np} reproduce --quick --only fig3_6 --format svg --out ${_figs})
set_tests_properties(cli.outputs.figures_svg PROPERTIES ENVIRONMENT "${_env}" TIMEOUT 300
  FIXTURES_REQUIRED cli_outputs_figures_clean FIXTURES_SETUP cli_outputs_figures)
add_test(NAME cli.outputs.figures_check COMMAND ${CMAKE_COMMAND} -DDIR=${_figs}
         -P ${CMAKE_CURRENT_LIST_DIR}/scripts/check_figures.cmake)
set_tests_properties(cli.outputs.figures_check PROPERTIES FIXTURES_REQUIRED cli_outputs_figures)
add_test(NAME cli.outputs.format_bad COMMAND ${_np} reproduce --only fig3_6 --format jpg --out ${_figs}-bad)
set_tests_properties(cli.outputs.format_bad PROPERTIES
  PASS_REGULAR_EXPRESSION "--format = jpg: must be one of png, svg, pdf")

# Outputs only ever replace their own regular files: a FIFO or a directory as --out is exit 5
# (the FIFO never blocks), a symlink is followed, a device written through; a scratch directory
# of the build tree holds them (scripts/output_targets.sh).
add_test(NAME cli.outputs.targets
  COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/scripts/output_targets.sh ${_np} ${CMAKE_CURRENT_BINARY_DIR}/outputs-targets)
set_tests_properties(cli.outputs.targets PROPERTIES ENVIRONMENT "${_env}" PASS_REGULAR_EXPRESSION "output targets: ok"
  FAIL_REGULAR_EXPRESSION "internal error" TIMEOUT 120)
