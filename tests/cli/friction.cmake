# nanopush friction: rows on stdin -> wrench rows; errors name line, field and value; no partial output.
set(_np $<TARGET_FILE:nanopush>)

# R = 0 on a unit square (a = b = 0.5): f = 0, mf = -(sqrt 2 + ln(1 + sqrt 2))/6 = -0.38259785823...
add_test(NAME cli.friction.square_centre
         COMMAND sh -c "printf 'R,alpha\\n0,0\\n' | \"$0\" friction --a 0.5 --b 0.5" ${_np})
set_tests_properties(cli.friction.square_centre PROPERTIES
  PASS_REGULAR_EXPRESSION "R,alpha,fx,fy,mf\n0,0,0,-?0,-0\\.3825978582")

# Far iCOR: pure translation, fx = sin(alpha), fy = -cos(alpha) (counter-clockwise).
add_test(NAME cli.friction.translation
         COMMAND sh -c "printf '1e300,0\\n' | \"$0\" friction --a 27.5e-9 --b 50e-9" ${_np})
set_tests_properties(cli.friction.translation PROPERTIES PASS_REGULAR_EXPRESSION "1e\\+300,0,0,-1,-")

# The F77 engine gives the same row.
add_test(NAME cli.friction.f77_engine
         COMMAND sh -c "printf '0,0\\n' | \"$0\" friction --a 0.5 --b 0.5 --engine f77" ${_np})
set_tests_properties(cli.friction.f77_engine PROPERTIES PASS_REGULAR_EXPRESSION "0,0,0,-?0,-0\\.3825978582")

# Bad rows: clear message (line, field, value), non-zero exit, nothing on stdout.
add_test(NAME cli.friction.bad_alpha
         COMMAND sh -c "printf '0,0\\n1e-8,abc\\n' | \"$0\" friction 2>&1" ${_np})
set_tests_properties(cli.friction.bad_alpha PROPERTIES
  PASS_REGULAR_EXPRESSION "stdin line 2, field alpha = abc"
  FAIL_REGULAR_EXPRESSION "R,alpha,fx")
add_test(NAME cli.friction.bad_alpha_exit COMMAND sh -c "printf '0,0\\n1e-8,abc\\n' | \"$0\" friction" ${_np})
set_tests_properties(cli.friction.bad_alpha_exit PROPERTIES WILL_FAIL TRUE)
add_test(NAME cli.friction.negative_R COMMAND sh -c "printf '%s\\n' '-1,0' | \"$0\" friction 2>&1" ${_np})
set_tests_properties(cli.friction.negative_R PROPERTIES
  PASS_REGULAR_EXPRESSION "stdin line 1, field R = -1: must be a finite number >= 0")
add_test(NAME cli.friction.infinite_R COMMAND sh -c "printf '0,0\\ninf,0\\n' | \"$0\" friction 2>&1" ${_np})
set_tests_properties(cli.friction.infinite_R PROPERTIES
  PASS_REGULAR_EXPRESSION "stdin line 2, field R = inf" FAIL_REGULAR_EXPRESSION "R,alpha,fx")
add_test(NAME cli.friction.one_field COMMAND sh -c "printf '3\\n' | \"$0\" friction 2>&1" ${_np})
set_tests_properties(cli.friction.one_field PROPERTIES PASS_REGULAR_EXPRESSION "stdin line 1 = 3: expected two fields")
add_test(NAME cli.friction.bad_a COMMAND ${_np} friction --a 0 --b 1)
set_tests_properties(cli.friction.bad_a PROPERTIES WILL_FAIL TRUE)
add_test(NAME cli.friction.bad_a_message COMMAND sh -c "\"$0\" friction --a -2e-9 </dev/null 2>&1" ${_np})
set_tests_properties(cli.friction.bad_a_message PROPERTIES PASS_REGULAR_EXPRESSION "a = -2(\\.0*1)?e-09: must be > 0")

# The benchmark is a driver: run it briefly so it keeps working (no timing is asserted).
add_test(NAME cli.friction.bench COMMAND ${_np} friction --bench --bench-seconds 0.01)
set_tests_properties(cli.friction.bench PROPERTIES PASS_REGULAR_EXPRESSION "evaluations/s")

# The reproduce steps (quick), with their own checks (exit status 0 only if they all hold).
add_test(NAME cli.friction.reproduce
         COMMAND ${_np} reproduce --quick --only fig3_9_friction --only fig3_10_11_friction
                 --out ${CMAKE_CURRENT_BINARY_DIR}/reproduce_friction)
# The friction-resultant benchmark (issue 24) with tiny budgets: it runs, writes its CSV and
# report, and its forms agree (exit 4 otherwise). Never a timed test: no ratio is asserted.
add_test(NAME cli.friction.bench_friction
         COMMAND bash -c "set -e; rm -rf \"$1\"; \"$0\" bench-friction --seconds 0.01 --repeats 1 --no-plot --quiet \
--out \"$1\" > /dev/null; test -s \"$1/friction_bench.csv\"; test -s \"$1/friction_bench.schema.json\"; \
grep -q 'new and old agree.*| yes |' \"$1/report.md\"; echo bench-friction: ok" ${_np} ${CMAKE_CURRENT_BINARY_DIR}/bench_friction)
set_tests_properties(cli.friction.bench_friction PROPERTIES ENVIRONMENT "NANOPUSH_SCENES=${NANOPUSH_SCENES}"
                     PASS_REGULAR_EXPRESSION "bench-friction: ok")
