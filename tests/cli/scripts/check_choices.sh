#!/usr/bin/env bash
# Choices are types (cxx/include/nanopush/scenes/choices.hpp): no code compares an engine,
# method, friction law or surface kind as text outside that name table; and trajectory rows
# are read by column name (row[col::fx], simulate.hpp), never rows[i][7]. Checked over the
# library, the bindings, the Python module and the drivers. Usage: check_choices.sh SOURCE_DIR
set -uo pipefail
cd "$1"
names='cxx|f77|faithful|modern|dop853|cvode|auto|thesis|printed|coulomb|smooth|rough'
hits=$(grep -rnE --include='*.cpp' --include='*.hpp' \
         -e "\b[A-Za-z_]*(engine|method|law|kind)[A-Za-z_]*\s*(==|!=)\s*\"($names)\"" \
         -e "\"($names)\"\s*(==|!=)\s*[A-Za-z_]*(engine|method|law|kind)" \
         cxx bindings python/src drivers | grep -v '^cxx/include/nanopush/scenes/choices.hpp:' || true)
if [ -n "$hits" ]; then
  echo "$hits"
  echo "choices compared as text: $(echo "$hits" | wc -l) place(s); use the enums of scenes/choices.hpp"
  exit 1
fi
rows=$(grep -rnE --include='*.cpp' --include='*.hpp' \
         'rows(\[[^]]*\]|\.back\(\)|\.front\(\))\[[0-9]+\]' cxx bindings python/src drivers || true)
if [ -n "$rows" ]; then
  echo "$rows"
  echo "trajectory columns by position: $(echo "$rows" | wc -l) place(s); use col:: names"
  exit 1
fi
echo "choices: ok"
