#!/usr/bin/env bash
# A bad-input sweep over the presets: every scene key of the table set, through --set, to
# values a hostile but fair user would try. Each run must end with a documented exit status
# (0, 2 or 3: never a signal, never 1, 5 or 70), a refusal (2) must name the key it refused,
# and nothing may be left in the working directory but the output a successful run writes.
# Prints the counts per exit status. Usage: bad_input_sweep.sh NANOPUSH WORKDIR [PRESET...]
# (default: every preset). The full sweep is run by hand (docs/errors.md gives the counts
# of the last one); CTest runs it on three presets.
set -uo pipefail
np=$1 dir=$2
shift 2
presets=("$@")
if [ ${#presets[@]} -eq 0 ]; then mapfile -t presets < <("$np" presets | awk 'NR>2 && NF{print $2}'); fi
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir" || exit 1
mapfile -t keys < <("$np" scene-keys | awk '/^[a-z]/{print $1}')
values=(nan inf -inf 1e308 -1e308 -1 0 1e-320 abc '' 1e999 0x10 '"x"' true)
declare -A count
bad=0 total=0
for p in "${presets[@]}"; do
  for k in "${keys[@]}"; do
    for v in "${values[@]}"; do
      total=$((total + 1))
      timeout 60 "$np" run "$p" --set "$k=$v" --set solver.max_steps=20000 --out out.csv --quiet > /dev/null 2> err.txt
      rc=$?
      count[$rc]=$(( ${count[$rc]:-0} + 1 ))
      case $rc in
        0) rm -f out.csv out.schema.json ;;
        2) grep -Eq -- '^nanopush: error: [^ ]+( [^ ]+)* = .+: .+' err.txt \
             || { echo "UNNAMED $p $k=$v: $(head -c 300 err.txt)"; bad=$((bad + 1)); }
           sed -E 's/= [^:]*:/= V:/' err.txt | head -1 >> messages.txt ;;
        3) ;;
        *) echo "EXIT $rc $p $k=$v: $(head -c 300 err.txt)"; bad=$((bad + 1)) ;;
      esac
      left=$(ls -A | grep -v '^err.txt$\|^messages.txt$')
      if [ -n "$left" ]; then echo "LEFT $p $k=$v: $left"; bad=$((bad + 1)); rm -f -- $left; fi
    done
  done
done
summary="bad-input sweep: $total runs over ${#presets[@]} presets x ${#keys[@]} keys x ${#values[@]} values; exit status:"
for rc in $(printf '%s\n' "${!count[@]}" | sort -n); do summary+=" $rc: ${count[$rc]};"; done
echo "$summary problems: $bad; $(sort -u messages.txt | wc -l) distinct refusals (messages.txt)"
[ "$bad" = 0 ] && echo "bad-input sweep: ok"
