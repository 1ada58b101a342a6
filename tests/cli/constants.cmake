# reproduce's constants step: the printed constants beside the thesis' own formulas, each with a
# verdict (Kelvin radius 0.54 nm, h = r/2, the 50 nm bar's mass, F_vdw, the MWCNT contact width, Fig 3.6).
set(_np $<TARGET_FILE:nanopush>)
add_test(NAME cli.reproduce.constants
         COMMAND bash -c "set -e; rm -rf \"$1\"; \"$0\" reproduce --only constants --out \"$1\" > /dev/null 2>&1; r=\"$1/report.md\"; \
grep -q '^| Kelvin radius, water, 20 °C, RH = 1/e (eq 2.60) | nm | 0.54 | 0.5386 | agrees' \"$r\"; \
grep -q 'fs(h = r/2) = 0 N | agrees' \"$r\"; \
grep -q '0.623425e-18 | 6.85768e-19 (50 nm: 6.23425e-19) | the printed mass is the 50 nm bar' \"$r\"; \
grep -q '| 1.71423e-05 | DIFFERS by 2.33x' \"$r\"; \
grep -q '| ~3 | 9.55 | DIFFERS' \"$r\"; grep -q '^| E\\* that gives 3 nm | GPa | (not printed) | 387 |' \"$r\"; \
grep -q 'falls | 1.04, 0.544, 0.456, 0.955, .* | DIFFERS: not monotone' \"$r\"; \
test -s \"$1/constants.csv\"; echo constants: ok" ${_np} ${CMAKE_CURRENT_BINARY_DIR}/reproduce_constants)
set_tests_properties(cli.reproduce.constants PROPERTIES ENVIRONMENT "NANOPUSH_SCENES=${NANOPUSH_SCENES}"
                     PASS_REGULAR_EXPRESSION "constants: ok")
