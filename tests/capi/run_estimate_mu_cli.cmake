# The friction coefficient estimates through the Fortran module give the numbers of
# `nanopush icor estimate-mu`, bit for bit (the C API is checked against the C++ library itself by
# capi.friction_icor_c). Invoked by tests/cli/capi.cmake with -DNANOPUSH -DFORTRAN_EXE -DWORK_DIR.
# Each case is one line of words: MODE F SIGMA_F X SIGMA_X SIGMA_L SIGMA_H [L RADIUS DENSITY H Z0 G]; the
# same decimal strings go to the CLI (--out CSV, 17 significant digits) and to FORTRAN_EXE
# (tests/capi/test_fortran_estimate_mu.f90), which reads the CSV back and compares with ==.
cmake_minimum_required(VERSION 3.25)

file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

set(other_rod "400e-9 10e-9 2000 3e-19 0.3e-9 0")  # unlike the thesis nanorod in every field
set(cases
  "yn 1e-6 3e-8 200e-9 5e-9 5e-9 1e-19"                # docs/icor.md's example, every uncertainty
  "yn 2.5e-6 0 0 0 0 0"                                # push at the centre of mass, exact inputs
  "yn 7.3e-7 2e-8 2.95e-7 1e-9 1e-8 5e-20"             # push at the end of the rod (yn = b)
  "icor 2.5e-6 1e-7 120e-9 1e-8 5e-9 1e-19"            # observed iCOR (Fig 4.5)
  "icor 4e-7 1e-8 3.3e-8 2e-9 2e-9 3e-20 ${other_rod}"
  "yn 4e-7 1e-8 1.5e-7 2e-9 2e-9 3e-20 ${other_rod}")

set(n 0)
foreach(case IN LISTS cases)
  string(REPLACE " " ";" args "${case}")
  list(GET args 0 mode)
  list(GET args 1 F)
  list(GET args 2 sF)
  list(GET args 3 x)
  list(GET args 4 sx)
  list(GET args 5 sL)
  list(GET args 6 sH)
  set(rod_cli "")
  list(LENGTH args len)
  if(len EQUAL 13)
    list(SUBLIST args 7 6 rod)
    set(i 0)
    foreach(opt --length --radius --density --hamaker --z0 --gravity)
      list(GET rod ${i} v)
      list(APPEND rod_cli ${opt} ${v})
      math(EXPR i "${i} + 1")
    endforeach()
  endif()
  if(mode STREQUAL "yn")
    set(point --yn ${x} --yn-sigma ${sx})
  else()
    set(point --icor ${x} --icor-sigma ${sx})
  endif()
  math(EXPR n "${n} + 1")
  set(csv ${WORK_DIR}/estimate_mu_${n}.csv)
  execute_process(COMMAND ${NANOPUSH} icor estimate-mu --force ${F} --force-sigma ${sF} ${point}
                          --length-sigma ${sL} --hamaker-sigma ${sH} ${rod_cli} --out ${csv}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "nanopush icor estimate-mu failed (${rc}) for case ${n} (${case}):\n${out}\n${err}")
  endif()
  execute_process(COMMAND ${FORTRAN_EXE} ${csv} ${args} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "case ${n} (${case}): the Fortran module differs from the CLI (${rc}):\n${out}\n${err}")
  endif()
  message(STATUS "case ${n} (${case}):\n${out}")
endforeach()
message(STATUS "estimate-mu CLI comparison: all checks hold (${n} cases)")
