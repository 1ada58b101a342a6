# reproduce's printed-readings step: the 16 readings of the printed law scored against Figs 3.18 and
# 3.29; the best reading by panels (then claims) in readings.csv is the one the report names, it is
# the reading called as_drawn (14), and its panel count is what the report says (docs/rough.md).
set(_np $<TARGET_FILE:nanopush>)
add_test(NAME cli.reproduce.printed_readings
         COMMAND bash -c "set -e; rm -rf \"$1\"; \"$0\" reproduce --only printed-readings --out \"$1\" > /dev/null 2>&1; \
best=$(awk -F, 'NR > 1 && ($6 > bp || ($6 == bp && $7 > bc)) { b = $1; bp = $6; bc = $7 } END { print b \" \" bp \" \" bc }' \"$1/printed_readings/readings.csv\"); \
set -- $best \"$1\"; test \"$1\" = 14; \
grep -q \"^\\*\\*Best reading: $1\\*\\* (F1 printed, F3 corrected, C4 cubes, 3.50 printed): $2/10 panels, $3/9 claims\" \"$4/report.md\"; \
test \"$2\" -ge 8; echo \"printed readings: best $1, $2/10 panels, $3/9 claims\"" ${_np} ${CMAKE_CURRENT_BINARY_DIR}/reproduce_printed_readings)
set_tests_properties(cli.reproduce.printed_readings PROPERTIES ENVIRONMENT "NANOPUSH_SCENES=${NANOPUSH_SCENES}"
                     PASS_REGULAR_EXPRESSION "printed readings: best 14, [0-9]+/10 panels")
