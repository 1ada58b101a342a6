# Install nanopush from BUILD_DIR into a fresh prefix, configure/build the consumer project
# (tests/export) against it, and check its programs print the same numbers as `nanopush run`.
# Invoked by tests/cli/export.cmake with:
#   -DBUILD_DIR -DWORK_DIR -DCONSUMER_SOURCE -DSCENE -DGENERATOR -DMAKE_PROGRAM
#   -DC_COMPILER -DCXX_COMPILER -DFortran_COMPILER
cmake_minimum_required(VERSION 3.25)

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "command failed (${rc}): ${ARGN}\n--- stdout\n${out}\n--- stderr\n${err}")
  endif()
  set(RUN_OUT "${out}" PARENT_SCOPE)
endfunction()

set(prefix ${WORK_DIR}/prefix)
set(build ${WORK_DIR}/build)
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

# 1. A fresh install.
run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
message(STATUS "installed into ${prefix}")

# 2. The consumer, configured against that prefix only (no package registries).
run(${CMAKE_COMMAND} -S ${CONSUMER_SOURCE} -B ${build} -G ${GENERATOR}
    -DCMAKE_MAKE_PROGRAM=${MAKE_PROGRAM} -DCMAKE_BUILD_TYPE=Release
    -DCMAKE_C_COMPILER=${C_COMPILER} -DCMAKE_CXX_COMPILER=${CXX_COMPILER}
    -DCMAKE_Fortran_COMPILER=${Fortran_COMPILER}
    -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF
    -DCMAKE_FIND_USE_SYSTEM_PACKAGE_REGISTRY=OFF)
string(REGEX MATCH "nanopush_DIR = [^\n]*" dir_line "${RUN_OUT}")
message(STATUS "${dir_line}")
if(NOT dir_line STREQUAL "nanopush_DIR = ${prefix}/lib/cmake/nanopush")
  message(FATAL_ERROR "the consumer did not find the fresh install: ${dir_line}")
endif()
run(${CMAKE_COMMAND} --build ${build})

# 3. Same numbers as the installed CLI: `nanopush friction` (C API from C++, Fortran module) ...
set(points "R,alpha\n")
foreach(R 0 1e-09 3e-08 1.2e-07 1.5e-07 1e-06 1)
  foreach(alpha 0 0.7 -2.2)
    string(APPEND points "${R},${alpha}\n")
  endforeach()
endforeach()
file(WRITE ${WORK_DIR}/friction_points.csv "${points}")
execute_process(COMMAND ${prefix}/bin/nanopush friction --sense 1 INPUT_FILE ${WORK_DIR}/friction_points.csv
                OUTPUT_FILE ${WORK_DIR}/friction_ref.csv RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "nanopush friction failed (${rc})")
endif()
file(READ ${WORK_DIR}/friction_ref.csv friction_ref)
execute_process(COMMAND ${build}/consumer_cxx --friction 1 INPUT_FILE ${WORK_DIR}/friction_points.csv
                RESULT_VARIABLE rc OUTPUT_VARIABLE friction_cxx ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT friction_cxx STREQUAL friction_ref)
  file(WRITE ${WORK_DIR}/friction_consumer_cxx.csv "${friction_cxx}")
  message(FATAL_ERROR "consumer_cxx --friction (${rc}) differs from nanopush friction: compare "
                      "${WORK_DIR}/friction_consumer_cxx.csv with ${WORK_DIR}/friction_ref.csv\n${err}")
endif()
message(STATUS "consumer_cxx --friction (C API): identical to nanopush friction")

# ... and `nanopush run`, for both engines.
foreach(engine cxx f77)
  run(${prefix}/bin/nanopush run ${SCENE} --engine ${engine} --out ${WORK_DIR}/ref_${engine}.csv --quiet)
  file(READ ${WORK_DIR}/ref_${engine}.csv ref)
  run(${build}/consumer_cxx ${SCENE} ${engine})
  if(NOT RUN_OUT STREQUAL ref)
    file(WRITE ${WORK_DIR}/consumer_cxx_${engine}.csv "${RUN_OUT}")
    message(FATAL_ERROR "consumer_cxx (${engine}) differs from nanopush run: compare "
                        "${WORK_DIR}/consumer_cxx_${engine}.csv with ${WORK_DIR}/ref_${engine}.csv")
  endif()
  string(LENGTH "${ref}" nbytes)
  message(STATUS "consumer_cxx (${engine}): identical to nanopush run (${nbytes} bytes of CSV)")
  run(${build}/consumer_fortran ${SCENE} ${engine} ${WORK_DIR}/ref_${engine}.csv ${WORK_DIR}/friction_ref.csv)
  message(STATUS "${RUN_OUT}")
endforeach()
# 4. A project without Fortran gets a clear message from the package, not a link error later.
execute_process(COMMAND ${CMAKE_COMMAND} -S ${CONSUMER_SOURCE}/cxx_only -B ${WORK_DIR}/build_cxx_only -G ${GENERATOR}
                        -DCMAKE_MAKE_PROGRAM=${MAKE_PROGRAM} -DCMAKE_C_COMPILER=${C_COMPILER}
                        -DCMAKE_CXX_COMPILER=${CXX_COMPILER} -DCMAKE_PREFIX_PATH=${prefix}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc EQUAL 0 OR NOT err MATCHES "nanopush: enable the Fortran language in this project")
  message(FATAL_ERROR "a C/C++-only consumer should fail with the 'enable Fortran' message:\n${err}")
endif()
message(STATUS "a C/C++-only consumer is told to enable Fortran")
message(STATUS "export test: all checks hold")
