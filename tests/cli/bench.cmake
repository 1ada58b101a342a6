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
# A ratio judged against a bound prints three decimals, so its rounding cannot cross the
# bound (a ratio of 1.2549 used to print as "1.25 (NOT met)").
add_test(NAME cli.bench.ratio_digits COMMAND ${_np} bench fig3_6a --quick --quiet --no-plot
         --engines cxx-faithful --engines f77-native
         --out ${CMAKE_CURRENT_BINARY_DIR}/bench-digits/bench.csv)
set_tests_properties(cli.bench.ratio_digits PROPERTIES ENVIRONMENT "${_env}"
  PASS_REGULAR_EXPRESSION "wall ratio from [0-9]+[.][0-9][0-9][0-9] to [0-9]+[.][0-9][0-9][0-9] [(]")

add_test(NAME cli.bench.bad_engine COMMAND ${_np} bench fig3_6a --engines no-such-engine)
set_tests_properties(cli.bench.bad_engine PROPERTIES ENVIRONMENT "${_env}"
  PASS_REGULAR_EXPRESSION "--engines = no-such-engine: must be one of: cxx-faithful")
add_test(NAME cli.bench.bad_engine_fails COMMAND ${_np} bench fig3_6a --engines no-such-engine)
set_tests_properties(cli.bench.bad_engine_fails PROPERTIES ENVIRONMENT "${_env}" WILL_FAIL TRUE)

add_test(NAME cli.bench.bad_precision COMMAND ${_np} bench fig3_6a --precision single)
set_tests_properties(cli.bench.bad_precision PROPERTIES ENVIRONMENT "${_env}" WILL_FAIL TRUE)

add_test(NAME cli.bench.bad_repeats COMMAND ${_np} bench fig3_6a --repeats 0)
set_tests_properties(cli.bench.bad_repeats PROPERTIES ENVIRONMENT "${_env}"
  PASS_REGULAR_EXPRESSION "--repeats = 0: must be a whole number in \\[1, 1000\\]")

# The report states how steady the host was: the bare RHS time over the sweep.
add_test(NAME cli.bench.host_speed COMMAND ${_np} bench fig3_6a --quick --quiet --no-plot --engines cxx-faithful
         --out ${CMAKE_CURRENT_BINARY_DIR}/bench-host/bench.csv)
set_tests_properties(cli.bench.host_speed PROPERTIES ENVIRONMENT "${_env}"
  PASS_REGULAR_EXPRESSION "Host speed during the sweep[*][*]: one bare RHS call took [0-9.e+-]+ to [0-9.e+-]+ ns")
# The overhead table says from which rtol on the 10 ns target holds (which rtol depends on the
# host: only the column's form is checked, never a timing).
add_test(NAME cli.bench.overhead_from COMMAND ${_np} bench fig3_6a --quick --quiet --no-plot --engines cxx-faithful
         --out ${CMAKE_CURRENT_BINARY_DIR}/bench-overhead/bench.csv)
set_tests_properties(cli.bench.overhead_from PROPERTIES ENVIRONMENT "${_env}"
  PASS_REGULAR_EXPRESSION "[|] cxx-faithful [|] double [|][^\n]*[|] (rtol <= [0-9.e+-]+|every rtol of the sweep|no rtol of the sweep) [|]")
# --replay: the overhead table gains the integrator alone (RHS values replayed); engines that
# cannot replay (f77-native: the F77 RHS called from F77) say so. Form only, no timing.
add_test(NAME cli.bench.replay COMMAND ${_np} bench fig3_6a --quick --quiet --no-plot --replay
         --engines cxx-faithful --engines f77-native --out ${CMAKE_CURRENT_BINARY_DIR}/bench-replay/bench.csv)
set_tests_properties(cli.bench.replay PROPERTIES ENVIRONMENT "${_env}"
  PASS_REGULAR_EXPRESSION "[|] cxx-faithful [|] double [|][^\n]*[|] [0-9.e+-]+ / [0-9.e+-]+ / [0-9.e+-]+ [|] (rtol <= [0-9.e+-]+|every rtol of the sweep|no rtol of the sweep) [|]\n[|] f77-native [|] double [|][^\n]*[|] n/a [(]no replay[)] [|] n/a [|]")
# Without --replay the table keeps its six columns.
add_test(NAME cli.bench.no_replay COMMAND ${_np} bench fig3_6a --quick --quiet --no-plot --engines cxx-faithful
         --out ${CMAKE_CURRENT_BINARY_DIR}/bench-noreplay/bench.csv)
set_tests_properties(cli.bench.no_replay PROPERTIES ENVIRONMENT "${_env}"
  PASS_REGULAR_EXPRESSION "sweep[)] [|] <= 10 ns at [|]\n[|]---[|]---[|]---[|]---[|]---[|]---[|]\n"
  FAIL_REGULAR_EXPRESSION "alone")
# --no-plot: the report says so instead of linking images that were not written.
add_test(NAME cli.bench.no_plot_report COMMAND ${_np} bench fig3_6a --quick --quiet --no-plot --engines cxx-faithful
         --precision double --precision quad --out ${CMAKE_CURRENT_BINARY_DIR}/bench-noplot/bench.csv)
set_tests_properties(cli.bench.no_plot_report PROPERTIES ENVIRONMENT "${_env}"
  PASS_REGULAR_EXPRESSION "Plots: not written [(]--no-plot[)]"
  FAIL_REGULAR_EXPRESSION "!\\[")

# The issue's targets are cxx-modern's against odeint-bs: the faithful engine (the F77
# engine's clipped steps) is compared with the peer without a met / NOT met verdict.
add_test(NAME cli.bench.faithful_no_verdict COMMAND ${_np} bench fig3_6a --quick --quiet --no-plot
         --engines cxx-faithful --engines odeint-bs
         --out ${CMAKE_CURRENT_BINARY_DIR}/bench-faithful/bench.csv)
set_tests_properties(cli.bench.faithful_no_verdict PROPERTIES ENVIRONMENT "${_env}"
  PASS_REGULAR_EXPRESSION "cxx-faithful vs odeint-bs[*][*] [(][^)]*no target"
  FAIL_REGULAR_EXPRESSION "met[)]")

# A smooth scene with an initial rotation rate has no closed form in the harness: the
# reference comes from two __float128 runs and must pass the acceptance rule.
file(READ ${NANOPUSH_SCENES}/thesis/fig3_6a.toml _fig3_6a)
string(REPLACE "theta = -0.5" "theta = -0.5\nomega = 3e9" _spin "${_fig3_6a}")
file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/bench_spin.toml "${_spin}")
add_test(NAME cli.bench.extended_reference COMMAND ${_np} bench ${CMAKE_CURRENT_BINARY_DIR}/bench_spin.toml
         --quick --quiet --no-plot --engines cxx-modern --out ${CMAKE_CURRENT_BINARY_DIR}/bench-spin/bench.csv)
set_tests_properties(cli.bench.extended_reference PROPERTIES
  PASS_REGULAR_EXPRESSION "Reference: extended \\(C\\+\\+ BS in __float128[^\n]*: accepted")

# Where neither engine reaches any error level of 1e-6..1e-12 (stick-slip without event
# location), the ratio table says so; it must not report ratios of 0 as "met".
add_test(NAME cli.bench.ratios_not_measured COMMAND ${_np} bench stick_mu015 --quick --quiet --no-plot
         --engines cxx-modern --engines odeint-bs --rhs-budget 20000
         --out ${CMAKE_CURRENT_BINARY_DIR}/bench-stick/bench.csv)
set_tests_properties(cli.bench.ratios_not_measured PROPERTIES ENVIRONMENT "${_env}"
  PASS_REGULAR_EXPRESSION "No error level in 1e-6..1e-12 is reached by both engines: not measured here"
  FAIL_REGULAR_EXPRESSION "ratio 0 \\(met\\)")

# The event-location table: a level that only cxx-events reaches is met without a ratio, and
# one that neither side reaches is not measured (it used to read "0 (met)").
add_test(NAME cli.bench.events_table COMMAND ${_np} bench stick_mu015 --quick --quiet --no-plot
         --engines cxx-events --engines odeint-bs --rhs-budget 20000
         --out ${CMAKE_CURRENT_BINARY_DIR}/bench-events/bench.csv)
set_tests_properties(cli.bench.events_table PROPERTIES ENVIRONMENT "${_env}"
  PASS_REGULAR_EXPRESSION "[|] 1e-8 [|][^|]*[|][^|]*[|] n/a: only cxx-events reaches it [(]met[)]"
  FAIL_REGULAR_EXPRESSION "[|] 0 [(]met[)]")

# The interpolant's acceptance, ours against ODEX's: an engine run only when named, and the
# report's comparison table (docs/bulirsch_stoer.md, "The interpolant's error control").
add_test(NAME cli.bench.odex_comparison COMMAND ${_np} bench fig3_6a --quick --quiet --no-plot
         --engines cxx-modern --engines cxx-modern-odex
         --out ${CMAKE_CURRENT_BINARY_DIR}/bench-odex/bench.csv)
set_tests_properties(cli.bench.odex_comparison PROPERTIES ENVIRONMENT "${_env}"
  PASS_REGULAR_EXPRESSION "cxx-modern \\(dense_accept 1\\) vs cxx-modern-odex \\(ODEX's 10\\)")

# Stick-slip scenes take reproduce's budgets by default (rtol 1e-3..1e-9, every third k: 5
# rows per engine); an option the user gives is kept (--kstep 6 --kmax 12: 2 rows).
add_test(NAME cli.bench.stick_slip_defaults
         COMMAND bash -c "set -e; \"$0\" bench stick_mu015 --engines cxx-events --quiet --no-plot --out \"$1/d.csv\" \
> /dev/null; test $(grep -c '^cxx-events' \"$1/d.csv\") -eq 5; grep -q '^cxx-events,double,1e-09,' \"$1/d.csv\"; \
\"$0\" bench stick_mu015 --engines cxx-events --kstep 6 --kmax 12 --quiet --no-plot --out \"$1/g.csv\" > /dev/null; \
test $(grep -c '^cxx-events' \"$1/g.csv\") -eq 2; echo stick-slip defaults: ok" ${_np} ${CMAKE_CURRENT_BINARY_DIR}/bench-stick-defaults)
set_tests_properties(cli.bench.stick_slip_defaults PROPERTIES ENVIRONMENT "${_env}"
  PASS_REGULAR_EXPRESSION "stick-slip defaults: ok")
