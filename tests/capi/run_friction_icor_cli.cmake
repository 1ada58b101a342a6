# Friction and iCOR through the C API and the Fortran module give the numbers of the nanopush CLI.
# Invoked by tests/cli/capi.cmake with -DNANOPUSH -DREF_EXE -DFORTRAN_EXE -DWORK_DIR.
#   1. REF_EXE (tests/capi/test_capi_friction_icor.cpp) checks the C API against the C++ library
#      bit for bit and writes the library's friction wrench at the points below.
#   2. `nanopush friction` (muN = 1, nanobar defaults) must print the same text.
#   3. `nanopush icor formulas` and `nanopush icor roots` write their CSVs.
#   4. FORTRAN_EXE (tests/capi/test_fortran_friction_icor.f90) reads them all back and compares.
cmake_minimum_required(VERSION 3.25)

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "command failed (${rc}): ${ARGN}\n--- stdout\n${out}\n--- stderr\n${err}")
  endif()
  message(STATUS "${out}")
endfunction()

file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

# Friction points (R [m], alpha [rad]) for the nanobar (a = 27.5 nm, b = 50 nm): the iCOR at the
# CM, inside the contact, on its edge and corner, the switch to the far-field form (3 max(a, b)),
# far away and in the asymptotic form; several orientations.
set(points "R,alpha\n")
foreach(R 0 1e-09 2.75e-08 5.7008771254956898e-08 1.2e-07 1.4999999999999999e-07 1.5e-07 3e-07 1e-05 1)
  foreach(alpha 0 0.3 1.5707963267948966 2.5 -1.1 3.141592653589793)
    string(APPEND points "${R},${alpha}\n")
  endforeach()
endforeach()
file(WRITE ${WORK_DIR}/points.csv "${points}")

foreach(sense 1 -1)
  run(${REF_EXE} ${WORK_DIR}/points.csv ${sense} ${WORK_DIR}/friction_lib_${sense}.csv)
  execute_process(COMMAND ${NANOPUSH} friction --sense ${sense} INPUT_FILE ${WORK_DIR}/points.csv
                  RESULT_VARIABLE rc OUTPUT_VARIABLE cli ERROR_VARIABLE err)
  file(WRITE ${WORK_DIR}/friction_cli_${sense}.csv "${cli}")
  file(READ ${WORK_DIR}/friction_lib_${sense}.csv lib)
  if(NOT rc EQUAL 0 OR NOT cli STREQUAL lib)
    message(FATAL_ERROR "nanopush friction --sense ${sense} (${rc}) differs from the library: compare "
                        "${WORK_DIR}/friction_cli_${sense}.csv with ${WORK_DIR}/friction_lib_${sense}.csv\n${err}")
  endif()
  message(STATUS "nanopush friction --sense ${sense}: identical to the library")
endforeach()

# iCOR: two (mu, F/(mu W)) settings, and the cubic over explicit and logarithmic push points.
run(${NANOPUSH} icor formulas --n 9 --out ${WORK_DIR}/formulas_a.csv)
run(${NANOPUSH} icor formulas --n 6 --mu 0.37 --force-ratio 2.5 --yn-min 1e-9 --out ${WORK_DIR}/formulas_b.csv)
run(${NANOPUSH} icor roots --yn 0 1e-15 1e-9 5e-08 9.83e-08 2e-07 2.95e-07 --n 6 --yn-min 1e-12 --log
    --out ${WORK_DIR}/roots.csv)

run(${FORTRAN_EXE} ${WORK_DIR}/formulas_a.csv 0.1 1 ${WORK_DIR}/roots.csv ${WORK_DIR}/friction_cli_1.csv ${WORK_DIR}/friction_cli_-1.csv)
run(${FORTRAN_EXE} ${WORK_DIR}/formulas_b.csv 0.37 2.5 ${WORK_DIR}/roots.csv ${WORK_DIR}/friction_cli_1.csv ${WORK_DIR}/friction_cli_-1.csv)
message(STATUS "friction/icor CLI comparison: all checks hold")
