# nanopush bench: the driver runs, writes its CSV with the documented header, refuses bad input.
set(_np $<TARGET_FILE:nanopush>)
set(_env "NANOPUSH_SCENES=${NANOPUSH_SCENES}")

add_test(NAME cli.bench.help COMMAND ${_np} bench --help)
set_tests_properties(cli.bench.help PROPERTIES PASS_REGULAR_EXPRESSION "--precision")

add_test(NAME cli.bench.quick COMMAND ${_np} bench fig3_6a --quick --quiet --no-plot
         --engines cxx-faithful --engines f77-native --precision double --precision long
         --out ${CMAKE_CURRENT_BINARY_DIR}/bench-quick/bench.csv)
set_tests_properties(cli.bench.quick PROPERTIES ENVIRONMENT "${_env}"
  PASS_REGULAR_EXPRESSION "Counts identical at every rtol")

add_test(NAME cli.bench.bad_engine COMMAND ${_np} bench fig3_6a --engines no-such-engine)
set_tests_properties(cli.bench.bad_engine PROPERTIES ENVIRONMENT "${_env}"
  PASS_REGULAR_EXPRESSION "--engines = no-such-engine: must be one of: cxx-faithful")
add_test(NAME cli.bench.bad_engine_fails COMMAND ${_np} bench fig3_6a --engines no-such-engine)
set_tests_properties(cli.bench.bad_engine_fails PROPERTIES ENVIRONMENT "${_env}" WILL_FAIL TRUE)

add_test(NAME cli.bench.bad_precision COMMAND ${_np} bench fig3_6a --precision single)
set_tests_properties(cli.bench.bad_precision PROPERTIES ENVIRONMENT "${_env}" WILL_FAIL TRUE)

add_test(NAME cli.bench.bad_repeats COMMAND ${_np} bench fig3_6a --repeats 0)
set_tests_properties(cli.bench.bad_repeats PROPERTIES ENVIRONMENT "${_env}"
  PASS_REGULAR_EXPRESSION "--repeats = 0: must be in")
