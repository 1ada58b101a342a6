# nanopush reproduce as a whole (each step also has tests beside its topic).
set(_np $<TARGET_FILE:nanopush>)
# reproduce --no-bench: the thesis content only, complete (report.md, no INCOMPLETE), no bench_* step.
add_test(NAME cli.reproduce.no_bench
         COMMAND bash -c "set -e; rm -rf \"$1\"; \"$0\" reproduce --quick --no-bench --out \"$1\" 2> \"$1.err\"; \
test -f \"$1/report.md\"; test ! -e \"$1/INCOMPLETE\"; ! grep -q bench_ \"$1.err\"; \
grep -q 'fig5_2' \"$1.err\"; echo reproduce no-bench: ok" ${_np} ${CMAKE_CURRENT_BINARY_DIR}/reproduce_no_bench)
set_tests_properties(cli.reproduce.no_bench PROPERTIES ENVIRONMENT "NANOPUSH_SCENES=${NANOPUSH_SCENES}"
                     PASS_REGULAR_EXPRESSION "reproduce no-bench: ok")
# reproduce --jobs: steps run at once write the same tables and report as one at a time
# (report.md up to its wall-time line; every CSV byte for byte).
add_test(NAME cli.reproduce.jobs
         COMMAND bash -c "set -e; rm -rf \"$1\"; for j in 1 2; do \"$0\" reproduce --quick --no-bench --jobs $j \
--out \"$1/j$j\" 2> \"$1.j$j.err\"; grep -q \"at a time\" \"$1.j$j.err\"; done; \
diff <(grep -v '^Wall time' \"$1/j1/report.md\") <(grep -v '^Wall time' \"$1/j2/report.md\"); \
n=0; while IFS= read -r f; do cmp \"$1/j1/$f\" \"$1/j2/$f\"; n=$((n+1)); done < <(cd \"$1/j1\" && find . -name '*.csv'); \
test $n -gt 20; echo \"reproduce jobs: $n tables identical\"" ${_np} ${CMAKE_CURRENT_BINARY_DIR}/reproduce_jobs)
set_tests_properties(cli.reproduce.jobs PROPERTIES ENVIRONMENT "NANOPUSH_SCENES=${NANOPUSH_SCENES}"
                     PASS_REGULAR_EXPRESSION "reproduce jobs: [0-9]+ tables identical" RUN_SERIAL TRUE)
