# nanopush bench: the driver runs, writes its CSV with the documented header, refuses bad input.
set(_np $<TARGET_FILE:nanopush>)
set(_env "NANOPUSH_SCENES=${NANOPUSH_SCENES}")

# cli.bench.NAME: a quick bench run (no plot, no progress) with ARGS, its CSV in bench-DIR/;
# the output must match PASS and, when FAIL is given, must not match FAIL.
function(_bench_quick name)
  cmake_parse_arguments(PARSE_ARGV 1 _b "" "DIR;PASS;FAIL" "ARGS")
  add_test(NAME cli.bench.${name} COMMAND ${_np} bench ${_b_ARGS} --quick --quiet --no-plot
           --out ${CMAKE_CURRENT_BINARY_DIR}/bench-${_b_DIR}/bench.csv)
  set_tests_properties(cli.bench.${name} PROPERTIES ENVIRONMENT "${_env}" PASS_REGULAR_EXPRESSION "${_b_PASS}")
  if(DEFINED _b_FAIL)
    set_tests_properties(cli.bench.${name} PROPERTIES FAIL_REGULAR_EXPRESSION "${_b_FAIL}")
  endif()
endfunction()

add_test(NAME cli.bench.help COMMAND ${_np} bench --help)
set_tests_properties(cli.bench.help PROPERTIES PASS_REGULAR_EXPRESSION "--precision")

_bench_quick(quick DIR quick ARGS fig3_6a --engines cxx-faithful --engines f77-native --precision double --precision long
  PASS "Counts identical at every rtol")
# A ratio judged against a bound prints three decimals, so its rounding cannot cross the
# bound (a ratio of 1.2549 used to print as "1.25 (NOT met)").
_bench_quick(ratio_digits DIR digits ARGS fig3_6a --engines cxx-faithful --engines f77-native
  PASS "wall ratio from [0-9]+[.][0-9][0-9][0-9] to [0-9]+[.][0-9][0-9][0-9] [(]")

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
_bench_quick(host_speed DIR host ARGS fig3_6a --engines cxx-faithful
  PASS "Host speed during the sweep[*][*]: one bare RHS call took [0-9.e+-]+ to [0-9.e+-]+ ns")
# The overhead table says from which rtol on the 10 ns target holds (which rtol depends on the
# host: only the column's form is checked, never a timing).
_bench_quick(overhead_from DIR overhead ARGS fig3_6a --engines cxx-faithful
  PASS "[|] cxx-faithful [|] double [|][^\n]*[|] (rtol <= [0-9.e+-]+|every rtol of the sweep|no rtol of the sweep) [|]")
# --replay: the overhead table gains the integrator alone (RHS values replayed); engines that
# cannot replay (f77-native: the F77 RHS called from F77) say so. Form only, no timing.
_bench_quick(replay DIR replay ARGS fig3_6a --replay --engines cxx-faithful --engines f77-native
  PASS "[|] cxx-faithful [|] double [|][^\n]*[|] [0-9.e+-]+ / [0-9.e+-]+ / [0-9.e+-]+ [|] (rtol <= [0-9.e+-]+|every rtol of the sweep|no rtol of the sweep) [|]\n[|] f77-native [|] double [|][^\n]*[|] n/a [(]no replay[)] [|] n/a [|]")
# Without --replay the table keeps its six columns.
_bench_quick(no_replay DIR noreplay ARGS fig3_6a --engines cxx-faithful
  PASS "sweep[)] [|] <= 10 ns at [|]\n[|]---[|]---[|]---[|]---[|]---[|]---[|]\n"
  FAIL "alone")
# --no-plot: the report says so instead of linking images that were not written.
_bench_quick(no_plot_report DIR noplot ARGS fig3_6a --engines cxx-faithful --precision double --precision quad
  PASS "Plots: not written [(]--no-plot[)]"
  FAIL "!\\[")

# The issue's targets are cxx-modern's against odeint-bs: the faithful engine (the F77
# engine's clipped steps) is compared with the peer without a met / NOT met verdict.
_bench_quick(faithful_no_verdict DIR faithful ARGS fig3_6a --engines cxx-faithful --engines odeint-bs
  PASS "cxx-faithful vs odeint-bs[*][*] [(][^)]*no target"
  FAIL "met[)]")

# A smooth scene with an initial rotation rate has no closed form in the harness: the
# reference comes from two __float128 runs and must pass the acceptance rule.
file(READ ${NANOPUSH_SCENES}/thesis/fig3_6a.toml _fig3_6a)
string(REPLACE "theta = -0.5" "theta = -0.5\nomega = 3e9" _spin "${_fig3_6a}")
file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/bench_spin.toml "${_spin}")
_bench_quick(extended_reference DIR spin ARGS ${CMAKE_CURRENT_BINARY_DIR}/bench_spin.toml --engines cxx-modern
  PASS "Reference: extended \\(C\\+\\+ BS in __float128[^\n]*: accepted")

# Where neither engine reaches any error level of 1e-6..1e-12 (stick-slip without event
# location), the ratio table says so; it must not report ratios of 0 as "met".
_bench_quick(ratios_not_measured DIR stick ARGS stick_mu015 --engines cxx-modern --engines odeint-bs --rhs-budget 20000
  PASS "No error level in 1e-6..1e-12 is reached by both engines: not measured here"
  FAIL "ratio 0 \\(met\\)")

# The event-location table: a level that only cxx-events reaches is met without a ratio, and
# one that neither side reaches is not measured (it used to read "0 (met)").
_bench_quick(events_table DIR events ARGS stick_mu015 --engines cxx-events --engines odeint-bs --rhs-budget 20000
  PASS "[|] 1e-8 [|][^|]*[|][^|]*[|] n/a: only cxx-events reaches it [(]met[)]"
  FAIL "[|] 0 [(]met[)]")

# The interpolant's acceptance, ours against ODEX's: an engine run only when named, and the
# report's comparison table (docs/bulirsch_stoer.md, "The interpolant's error control").
_bench_quick(odex_comparison DIR odex ARGS fig3_6a --engines cxx-modern --engines cxx-modern-odex
  PASS "cxx-modern \\(dense_accept 1\\) vs cxx-modern-odex \\(ODEX's 10\\)")

# Stick-slip scenes take reproduce's budgets by default (rtol 1e-3..1e-9, every third k: 5
# rows per engine); an option the user gives is kept (--kstep 6 --kmax 12: 2 rows).
add_test(NAME cli.bench.stick_slip_defaults
         COMMAND bash -c "set -e; \"$0\" bench stick_mu015 --engines cxx-events --quiet --no-plot --out \"$1/d.csv\" \
> /dev/null; test $(grep -c '^cxx-events' \"$1/d.csv\") -eq 5; grep -q '^cxx-events,double,1e-09,' \"$1/d.csv\"; \
\"$0\" bench stick_mu015 --engines cxx-events --kstep 6 --kmax 12 --quiet --no-plot --out \"$1/g.csv\" > /dev/null; \
test $(grep -c '^cxx-events' \"$1/g.csv\") -eq 2; echo stick-slip defaults: ok" ${_np} ${CMAKE_CURRENT_BINARY_DIR}/bench-stick-defaults)
set_tests_properties(cli.bench.stick_slip_defaults PROPERTIES ENVIRONMENT "${_env}"
  PASS_REGULAR_EXPRESSION "stick-slip defaults: ok")
