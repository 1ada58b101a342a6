# Warnings on for every language; the project builds clean with them.
add_library(nanopush_warnings INTERFACE)
target_compile_options(nanopush_warnings INTERFACE
  $<$<COMPILE_LANGUAGE:CXX>:-Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion>
  $<$<COMPILE_LANGUAGE:C>:-Wall -Wextra>
  $<$<COMPILE_LANGUAGE:Fortran>:-Wall -Wno-unused-dummy-argument -Wno-compare-reals>)
# Fixed-form F77 must stay re-entrant: locals on the stack, never static.
set(NANOPUSH_F77_FLAGS -frecursive -std=legacy -ffixed-form)
# The faithful C++ engine must take the F77 engine's steps bit for bit: never contract
# a*b+c into a fused multiply-add (matters with -march flags that enable FMA).
add_compile_options($<$<COMPILE_LANGUAGE:CXX,C,Fortran>:-ffp-contract=off>)
