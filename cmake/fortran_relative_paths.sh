#!/usr/bin/env bash
# Fortran compiler launcher (cmake/Packaging.cmake): fortran_relative_paths.sh PREFIX COMPILER ARGS...
# gfortran writes the source file's name into its run-time messages ("At line 12 of file ...")
# and does not apply -ffile-prefix-map to it. The Ninja generator compiles a preprocessed copy
# (*-pp.f, *-pp.f90, ...) whose line markers (# 1 "/abs/src/fortran/bsint.f") give that name: a
# copy with PREFIX removed from the markers is compiled instead, so the name is relative
# (fortran/bsint.f). Any other compile runs unchanged.
set -euo pipefail
prefix=$1
shift
args=()
for a in "$@"; do
  case $a in
    *-pp.f | *-pp.f90 | *-pp.F | *-pp.F90 | *-pp.for | *-pp.f95 | *-pp.f03 | *-pp.f08)
      if [[ -f $a ]]; then
        rel="${a%.*}-rel.${a##*.}"
        # Only line markers: '# <line> "<PREFIX>...'. PREFIX is a literal (escape sed's specials).
        esc=$(printf '%s' "$prefix" | sed -e 's/[]\\$*.^[]/\\&/g')
        sed -e "s|^\(# [0-9][0-9]* \"\)$esc|\1|" "$a" >"$rel"
        a=$rel
      fi
      ;;
  esac
  args+=("$a")
done
exec "${args[@]}"
