#!/usr/bin/env bash
# Choices are types with one name table each (numerics/names.hpp; the scene choices in
# scenes/choices.hpp): no code compares an engine, method, friction law, surface kind,
# precision, cubic solver, fit gradients, sweep task, body shape or pressure assumption as
# text outside those tables; and trajectory rows
# are read by column name (row[col::fx], simulate.hpp), never rows[i][7]. Checked over the
# library, the bindings, the Python module and the drivers. Usage: check_choices.sh SOURCE_DIR
set -uo pipefail
cd "$1"
names='cxx|f77|faithful|modern|dop853|cvode|auto|thesis|printed|coulomb|smooth|rough|double|long|quad'
names+='|brent|eigen|brent_f77|lapack_f77|sensitivities|differences|run|friction|icor|estimate-mu'
names+='|bar|rod|tube|sphere|known|unknown|squares_nm|cubes'
vars='engine|method|law|kind|precision|prec|solver|gradients|task|shape|pressure|c4'
hits=$(grep -rnE --include='*.cpp' --include='*.hpp' \
         -e "\b[A-Za-z_]*($vars)[A-Za-z_]*\s*(==|!=)\s*\"($names)\"" \
         -e "\"($names)\"\s*(==|!=)\s*[A-Za-z_]*($vars)" \
         cxx bindings python/src drivers | grep -v '^cxx/include/nanopush/scenes/choices.hpp:' || true)
if [ -n "$hits" ]; then
  echo "$hits"
  echo "choices compared as text: $(echo "$hits" | wc -l) place(s); use the enums and their name tables"
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
