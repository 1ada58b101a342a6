# nanopush reproduce as a whole (each step also has tests beside its topic).
set(_np $<TARGET_FILE:nanopush>)
# reproduce --no-bench: the thesis content only, complete (report.md, no INCOMPLETE), no bench_* step.
add_test(NAME cli.reproduce.no_bench
         COMMAND bash -c "set -e; rm -rf \"$1\"; \"$0\" reproduce --quick --no-bench --out \"$1\" 2> \"$1.err\"; \
test -f \"$1/report.md\"; test ! -e \"$1/INCOMPLETE\"; ! grep -q bench_ \"$1.err\"; \
grep -q 'fig5_2' \"$1.err\"; echo reproduce no-bench: ok" ${_np} ${CMAKE_CURRENT_BINARY_DIR}/reproduce_no_bench)
set_tests_properties(cli.reproduce.no_bench PROPERTIES ENVIRONMENT "NANOPUSH_SCENES=${NANOPUSH_SCENES}"
                     PASS_REGULAR_EXPRESSION "reproduce no-bench: ok")
