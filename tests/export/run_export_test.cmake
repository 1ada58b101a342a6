# The installed package, checked as other projects and users meet it (issue 8, "install and link
# from anywhere"). One step per CTest (tests/cli/export.cmake), against a fresh install:
#   install          static: `cmake --install BUILD_DIR`; shared: configure nanopush with
#                    -DBUILD_SHARED_LIBS=ON -DNANOPUSH_TESTS=OFF -DNANOPUSH_PYTHON=OFF
#                    -DNANOPUSH_OBJECTS_FROM=BUILD_DIR in WORK_DIR/nanopush (it links BUILD_DIR's
#                    position-independent objects into shared libraries: cmake/ObjectReuse.cmake),
#                    build, then install
#   cmake_consumers  tests/export (C, C++ and Fortran; no CMAKE_CXX_STANDARD) and tests/export/cxx_only
#                    (C++ only: no Fortran enabled) built against the prefix; same numbers as
#                    `nanopush run` / `nanopush friction`
#   pkgconfig_c      tests/export/consumer.c built by `cc ... $(pkg-config --cflags --libs nanopush)`
#                    only; same numbers as `nanopush run`
#   mu_fortran       tests/export/mu (Fortran, nanopush_estimate_mu_from_force/_icor): bit for bit
#                    the numbers of `nanopush icor estimate-mu --out`
#   relocated_cli    the installed prefix copied elsewhere, the original removed: `nanopush run
#                    fig3_6a` from an empty directory, clean environment, equals the build tree's CSV
#   symbols          nm of libnanopush_{numerics,models,scenes}: no F77 and no benchmark symbols
#   no_build_paths   no file of the prefix names the source or the build tree
#   sonames          (shared) every library versioned: SONAME libnanopush_X.so.MAJOR.MINOR, and the
#                    command line and the C API record those names (readelf -d)
# Arguments: -DSTEP -DMODE=static|shared -DBUILD_DIR (the project's build tree) -DSOURCE_DIR
#   -DWORK_DIR (this mode's directory: prefix/ and the consumers' builds) -DSCENE -DGENERATOR
#   -DMAKE_PROGRAM -DC_COMPILER -DCXX_COMPILER -DFortran_COMPILER -DBUILD_TYPE -DCONFIG_FLAGS
#   (the build tree's -DCMAKE_<LANG>_FLAGS_<CONFIG>=..., |-separated, for the shared build).
cmake_minimum_required(VERSION 3.25)
string(REPLACE "|" ";" CONFIG_FLAGS "${CONFIG_FLAGS}")

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "command failed (${rc}): ${ARGN}\n--- stdout\n${out}\n--- stderr\n${err}")
  endif()
  set(RUN_OUT "${out}" PARENT_SCOPE)
endfunction()

set(prefix ${WORK_DIR}/prefix)
set(consumer_source ${SOURCE_DIR}/tests/export)
set(consumer_args -G ${GENERATOR} -DCMAKE_MAKE_PROGRAM=${MAKE_PROGRAM} -DCMAKE_BUILD_TYPE=Release
    -DCMAKE_C_COMPILER=${C_COMPILER} -DCMAKE_CXX_COMPILER=${CXX_COMPILER}
    -DCMAKE_Fortran_COMPILER=${Fortran_COMPILER}
    -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF
    -DCMAKE_FIND_USE_SYSTEM_PACKAGE_REGISTRY=OFF)

# The nanopush build tree this mode installs from.
if(MODE STREQUAL "shared")
  set(install_from ${WORK_DIR}/nanopush)
else()
  set(install_from ${BUILD_DIR})
endif()

# Install into DEST, a fresh directory.
function(fresh_install dest)
  file(REMOVE_RECURSE ${dest})
  run(${CMAKE_COMMAND} --install ${install_from} --prefix ${dest})
endfunction()

# Compare the CSV text of two files (exact: same numbers, same format).
function(same_csv what actual expected)
  file(READ ${actual} a)
  file(READ ${expected} e)
  if(NOT a STREQUAL e)
    message(FATAL_ERROR "${what}: ${actual} differs from ${expected}")
  endif()
  string(LENGTH "${e}" n)
  message(STATUS "${what}: identical (${n} bytes of CSV)")
endfunction()

# -------------------------------------------------------------------------------------------
if(STEP STREQUAL "install")
  if(MODE STREQUAL "shared")
    # The build tree's objects (compiled once, position-independent) linked into shared
    # libraries, with the same build type and flags: the same machine code, so the same
    # numbers. No tests: the libraries, the command line and the legacy programs (not the
    # Python extension: no check here uses it, and python.install covers its install).
    string(TIMESTAMP t0 "%s")
    run(${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${install_from} -G ${GENERATOR}
        -DCMAKE_MAKE_PROGRAM=${MAKE_PROGRAM} -DCMAKE_BUILD_TYPE=${BUILD_TYPE} ${CONFIG_FLAGS}
        -DCMAKE_C_COMPILER=${C_COMPILER} -DCMAKE_CXX_COMPILER=${CXX_COMPILER}
        -DCMAKE_Fortran_COMPILER=${Fortran_COMPILER}
        -DBUILD_SHARED_LIBS=ON -DNANOPUSH_TESTS=OFF -DNANOPUSH_PYTHON=OFF
        -DNANOPUSH_OBJECTS_FROM=${BUILD_DIR})
    run(${CMAKE_COMMAND} --build ${install_from})
    string(TIMESTAMP t1 "%s")
    math(EXPR dt "${t1} - ${t0}")
    message(STATUS "shared nanopush configured and linked in ${dt} s")
  endif()
  fresh_install(${prefix})
  file(GLOB libs ${prefix}/lib/libnanopush_*)
  foreach(l IN LISTS libs)
    file(SIZE ${l} size)
    get_filename_component(name ${l} NAME)
    message(STATUS "  ${name}: ${size} bytes")
  endforeach()
  message(STATUS "export ${MODE}: installed into ${prefix}")
  return()
endif()

if(NOT EXISTS ${prefix}/lib/cmake/nanopush/nanopushConfig.cmake)
  message(FATAL_ERROR "no install in ${prefix}: the ${MODE} install step (fixture) did not run")
endif()
file(MAKE_DIRECTORY ${WORK_DIR}/${STEP})
set(work ${WORK_DIR}/${STEP})

# -------------------------------------------------------------------------------------------
if(STEP STREQUAL "cmake_consumers")
  set(build ${work}/build)
  file(REMOVE_RECURSE ${build} ${work}/build_cxx_only)
  run(${CMAKE_COMMAND} -S ${consumer_source} -B ${build} ${consumer_args})
  string(REGEX MATCH "nanopush_DIR = [^\n]*" dir_line "${RUN_OUT}")
  message(STATUS "${dir_line}")
  if(NOT dir_line STREQUAL "nanopush_DIR = ${prefix}/lib/cmake/nanopush")
    message(FATAL_ERROR "the consumer did not find the fresh install: ${dir_line}")
  endif()
  run(${CMAKE_COMMAND} --build ${build})
  # A C++-only project (no Fortran, no C, no CMAKE_CXX_STANDARD) configures, links and runs too.
  run(${CMAKE_COMMAND} -S ${consumer_source}/cxx_only -B ${work}/build_cxx_only ${consumer_args})
  string(REGEX MATCH "enabled languages: [^\n]*" lang_line "${RUN_OUT}")
  if(NOT lang_line STREQUAL "enabled languages: CXX")
    message(FATAL_ERROR "cxx_only should enable C++ alone: ${lang_line}")
  endif()
  run(${CMAKE_COMMAND} --build ${work}/build_cxx_only)
  message(STATUS "the C++-only consumer (no Fortran enabled) built")

  # Same numbers as the installed CLI: `nanopush friction` (C API from C++, Fortran module) ...
  set(points "R,alpha\n")
  foreach(R 0 1e-09 3e-08 1.2e-07 1.5e-07 1e-06 1)
    foreach(alpha 0 0.7 -2.2)
      string(APPEND points "${R},${alpha}\n")
    endforeach()
  endforeach()
  file(WRITE ${work}/friction_points.csv "${points}")
  execute_process(COMMAND ${prefix}/bin/nanopush friction --sense 1 INPUT_FILE ${work}/friction_points.csv
                  OUTPUT_FILE ${work}/friction_ref.csv RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "nanopush friction failed (${rc})")
  endif()
  file(READ ${work}/friction_ref.csv friction_ref)
  execute_process(COMMAND ${build}/consumer_cxx --friction 1 INPUT_FILE ${work}/friction_points.csv
                  RESULT_VARIABLE rc OUTPUT_VARIABLE friction_cxx ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 OR NOT friction_cxx STREQUAL friction_ref)
    file(WRITE ${work}/friction_consumer_cxx.csv "${friction_cxx}")
    message(FATAL_ERROR "consumer_cxx --friction (${rc}) differs from nanopush friction: compare "
                        "${work}/friction_consumer_cxx.csv with ${work}/friction_ref.csv\n${err}")
  endif()
  message(STATUS "consumer_cxx --friction (C API): identical to nanopush friction")

  # ... and `nanopush run`, for both engines.
  foreach(engine cxx f77)
    run(${prefix}/bin/nanopush run ${SCENE} --engine ${engine} --out ${work}/ref_${engine}.csv --quiet)
    foreach(exe ${build}/consumer_cxx ${work}/build_cxx_only/consumer_cxx_only)
      get_filename_component(name ${exe} NAME)
      run(${exe} ${SCENE} ${engine})
      file(WRITE ${work}/${name}_${engine}.csv "${RUN_OUT}")
      same_csv("${name} (${engine}) vs nanopush run" ${work}/${name}_${engine}.csv ${work}/ref_${engine}.csv)
    endforeach()
    run(${build}/consumer_fortran ${SCENE} ${engine} ${work}/ref_${engine}.csv ${work}/friction_ref.csv)
    message(STATUS "${RUN_OUT}")
  endforeach()

# -------------------------------------------------------------------------------------------
elseif(STEP STREQUAL "pkgconfig_c")
  find_program(PKG_CONFIG NAMES pkg-config pkgconf REQUIRED)
  set(ENV{PKG_CONFIG_PATH} ${prefix}/lib/pkgconfig)
  run(${PKG_CONFIG} --cflags --libs nanopush)
  string(STRIP "${RUN_OUT}" flags)
  message(STATUS "pkg-config --cflags --libs nanopush: ${flags}")
  string(REGEX MATCHALL "-lnanopush_[a-z0-9_]+" ours "${flags}")
  if(MODE STREQUAL "shared" AND NOT ours STREQUAL "-lnanopush_capi")
    message(FATAL_ERROR "shared: Libs should name libnanopush_capi alone (its dependencies are DT_NEEDED): ${ours}")
  endif()
  # Plain cc, the flags exactly as pkg-config prints them (through the shell, as a user types it).
  run(sh -c "cd '${work}' && '${C_COMPILER}' '${consumer_source}/consumer.c' -o consumer_c $(${PKG_CONFIG} --cflags --libs nanopush)")
  foreach(engine cxx f77)
    run(${prefix}/bin/nanopush run ${SCENE} --engine ${engine} --out ${work}/ref_${engine}.csv --quiet)
    # No LD_LIBRARY_PATH: a shared install is found through the RPATH pkg-config gave.
    run(${CMAKE_COMMAND} -E env --unset=LD_LIBRARY_PATH ${work}/consumer_c ${SCENE} ${engine} ${work}/ref_${engine}.csv)
    message(STATUS "${RUN_OUT}")
  endforeach()

# -------------------------------------------------------------------------------------------
elseif(STEP STREQUAL "mu_fortran")
  set(build ${work}/build)
  file(REMOVE_RECURSE ${build})
  run(${CMAKE_COMMAND} -S ${consumer_source}/mu -B ${build} ${consumer_args})
  run(${CMAKE_COMMAND} --build ${build})
  # Each case: the estimate-mu options; the program gets the same numbers and the CLI's CSV.
  # Each case: KIND:estimate-mu options (the CLI's default rod, the thesis nanorod, L = 590 nm).
  set(cases
      "force:--force 2e-7 --force-sigma 1e-8 --yn 1e-7 --yn-sigma 5e-9 --length-sigma 5e-9 --hamaker-sigma 1e-20"
      "force:--force 1.5e-7 --yn 0"
      "icor:--force 3e-7 --force-sigma 2e-8 --icor 4e-8 --icor-sigma 3e-9 --length-sigma 4e-9 --hamaker-sigma 2e-20")
  set(i 0)
  foreach(case IN LISTS cases)
    math(EXPR i "${i} + 1")
    string(REGEX REPLACE ":.*" "" kind "${case}")
    string(REGEX REPLACE "^[a-z]+:" "" opts "${case}")
    separate_arguments(opts UNIX_COMMAND "${opts}")
    run(${prefix}/bin/nanopush icor estimate-mu ${opts} --out ${work}/mu_${i}.csv)
    run(${build}/consumer_mu ${kind} ${work}/mu_${i}.csv)
    message(STATUS "case ${i} (${kind}): ${RUN_OUT}")
  endforeach()

# -------------------------------------------------------------------------------------------
elseif(STEP STREQUAL "relocated_cli")
  # A second fresh install, copied elsewhere; the original removed, so only the copy exists.
  set(original ${work}/original)
  set(copy ${work}/moved/copy)
  file(REMOVE_RECURSE ${work}/moved ${work}/empty)
  fresh_install(${original})
  file(MAKE_DIRECTORY ${work}/moved ${work}/empty)
  run(cp -a ${original} ${copy})
  file(REMOVE_RECURSE ${original})
  # Clean environment (no NANOPUSH_*, no LD_LIBRARY_PATH), from an empty directory.
  set(clean env -i PATH=/usr/bin:/bin HOME=${work}/empty)
  execute_process(COMMAND ${clean} ${copy}/bin/nanopush run fig3_6a --out ${work}/installed.csv
                  WORKING_DIRECTORY ${work}/empty RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "the moved nanopush failed (${rc}):\n${out}\n${err}")
  endif()
  message(STATUS "moved nanopush run fig3_6a:\n${out}")
  run(${BUILD_DIR}/nanopush run fig3_6a --out ${work}/build_tree.csv)
  same_csv("moved install vs build tree, nanopush run fig3_6a" ${work}/installed.csv ${work}/build_tree.csv)
  file(GLOB left ${work}/empty/*)
  if(left)
    message(FATAL_ERROR "nanopush run wrote into the working directory: ${left}")
  endif()
  # The presets it lists are the copy's own.
  execute_process(COMMAND ${clean} ${copy}/bin/nanopush presets WORKING_DIRECTORY ${work}/empty
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 OR NOT out MATCHES "preset scenes in ${copy}/share/nanopush/scenes\n"
     OR NOT out MATCHES "\nthesis/fig3_6a +fig3_6a +Thesis Fig 3.6 \\(a\\)")
    message(FATAL_ERROR "nanopush presets (${rc}) should list the copy's presets:\n${out}\n${err}")
  endif()
  # The legacy program beside it (`nanopush legacy`).
  execute_process(COMMAND ${clean} ${copy}/bin/nanopush legacy fig3_6a WORKING_DIRECTORY ${work}/empty
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 OR NOT out MATCHES "legacy program ${copy}/bin/nanobar on")
    message(FATAL_ERROR "nanopush legacy (${rc}) should run the copy's nanobar:\n${out}\n${err}")
  endif()
  message(STATUS "moved nanopush legacy fig3_6a: runs ${copy}/bin/nanobar, check holds")
  if(MODE STREQUAL "shared")
    run(ldd ${copy}/bin/nanopush)
    string(REGEX MATCHALL "libnanopush_[a-z0-9_]+\\.so[^\n]*" deps "${RUN_OUT}")
    foreach(d IN LISTS deps)
      if(NOT d MATCHES "=> ${copy}/")
        message(FATAL_ERROR "the moved nanopush should load its libraries from the copy: ${d}")
      endif()
    endforeach()
    message(STATUS "shared libraries from the copy: ${deps}")
  endif()

# -------------------------------------------------------------------------------------------
elseif(STEP STREQUAL "symbols")
  # Forbidden in the C++ solver (nanopush::core): the F77 routines (their gfortran names, from
  # fortran/*.f), the bridge (np_f77_*), the Fortran run time, and the benchmark harness
  # (namespace nanopush::bench, drivers/bench).
  file(GLOB f77_sources ${SOURCE_DIR}/fortran/*.f)
  set(f77_names "")
  foreach(f IN LISTS f77_sources)
    file(STRINGS ${f} lines REGEX "^      [A-Z ]*(SUBROUTINE|FUNCTION) +[A-Z][A-Z0-9_]*")
    foreach(l IN LISTS lines)
      string(REGEX REPLACE "^.*(SUBROUTINE|FUNCTION) +([A-Z][A-Z0-9_]*).*$" "\\2" name "${l}")
      string(TOLOWER "${name}" name)
      list(APPEND f77_names ${name})
    endforeach()
  endforeach()
  list(REMOVE_DUPLICATES f77_names)
  list(LENGTH f77_names n_f77)
  if(n_f77 LESS 20)
    message(FATAL_ERROR "found only ${n_f77} F77 routine names in ${SOURCE_DIR}/fortran: ${f77_names}")
  endif()
  string(JOIN "|" f77_alt ${f77_names})
  set(forbidden "(^| )(${f77_alt})_$|np_f77_|_gfortran_|MAIN__|nanopush5bench")
  set(n_libs 0)
  foreach(layer numerics models scenes)
    file(GLOB libs ${prefix}/lib/libnanopush_${layer}.a ${prefix}/lib/libnanopush_${layer}.so)
    if(NOT libs)
      message(FATAL_ERROR "no libnanopush_${layer} in ${prefix}/lib")
    endif()
    foreach(lib IN LISTS libs)
      run(nm --no-sort ${lib})
      string(REPLACE "\n" ";" syms "${RUN_OUT}")
      list(LENGTH syms n_syms)
      set(bad "")
      foreach(s IN LISTS syms)
        string(REGEX REPLACE "^[0-9a-fA-F]* *[A-Za-z?-] " "" s "${s}")
        if(s MATCHES "${forbidden}")
          list(APPEND bad "${s}")
        endif()
      endforeach()
      get_filename_component(name ${lib} NAME)
      if(bad)
        list(REMOVE_DUPLICATES bad)
        message(FATAL_ERROR "${name} holds F77 or benchmark symbols: ${bad}")
      endif()
      message(STATUS "${name}: ${n_syms} symbols, none of F77 (${n_f77} routines, np_f77_*, _gfortran_*) or the benchmark")
      math(EXPR n_libs "${n_libs} + 1")
    endforeach()
  endforeach()
  # The C API library of a shared install exports its nanopush_* functions and nothing else.
  if(MODE STREQUAL "shared")
    run(nm -D --defined-only ${prefix}/lib/libnanopush_capi.so)
    string(REPLACE "\n" ";" syms "${RUN_OUT}")
    set(bad "")
    set(n_api 0)
    foreach(s IN LISTS syms)
      string(REGEX REPLACE "^[0-9a-fA-F]* *[A-Za-z?-] " "" s "${s}")
      if(s STREQUAL "")
        continue()
      elseif(s MATCHES "^nanopush_[a-z0-9_]+$")
        math(EXPR n_api "${n_api} + 1")
      else()
        list(APPEND bad "${s}")
      endif()
    endforeach()
    if(bad OR n_api LESS 20)
      message(FATAL_ERROR "libnanopush_capi.so should export nanopush_* alone (${n_api} found); also: ${bad}")
    endif()
    message(STATUS "libnanopush_capi.so exports ${n_api} symbols, every one nanopush_*")
  endif()

# -------------------------------------------------------------------------------------------
elseif(STEP STREQUAL "no_build_paths")
  set(paths ${SOURCE_DIR})
  string(FIND "${BUILD_DIR}/" "${SOURCE_DIR}/" in_source)
  if(NOT in_source EQUAL 0)
    list(APPEND paths ${BUILD_DIR})
  endif()
  file(GLOB_RECURSE files LIST_DIRECTORIES false ${prefix}/*)
  list(LENGTH files n_files)
  foreach(p IN LISTS paths)
    execute_process(COMMAND grep -r -l -F --binary-files=text -e "${p}" ${prefix}
                    RESULT_VARIABLE rc OUTPUT_VARIABLE hits)
    if(rc EQUAL 0)
      message(FATAL_ERROR "installed files name ${p}:\n${hits}")
    endif()
  endforeach()
  message(STATUS "${n_files} installed files, none naming ${paths}")
# -------------------------------------------------------------------------------------------
elseif(STEP STREQUAL "sonames")
  # Every shared library is libnanopush_X.so -> libnanopush_X.so.SOVERSION (its SONAME) ->
  # libnanopush_X.so.VERSION, and the executables record the versioned name (readelf -d).
  find_program(READELF readelf REQUIRED)
  file(GLOB namelinks ${prefix}/lib/libnanopush_*.so)
  list(LENGTH namelinks n_libs)
  if(n_libs LESS 10)
    message(FATAL_ERROR "expected the nanopush shared libraries in ${prefix}/lib, found ${n_libs}: ${namelinks}")
  endif()
  foreach(link IN LISTS namelinks)
    get_filename_component(name ${link} NAME)
    if(NOT IS_SYMLINK ${link})
      message(FATAL_ERROR "${name} is not a symbolic link to a versioned library")
    endif()
    if(NOT IS_SYMLINK ${link}.${SOVERSION} OR IS_SYMLINK ${link}.${VERSION} OR NOT EXISTS ${link}.${VERSION})
      message(FATAL_ERROR "${name}: expected ${name}.${SOVERSION} (a link) -> ${name}.${VERSION} (the file)")
    endif()
    run(${READELF} -d ${link}.${VERSION})
    if(NOT RUN_OUT MATCHES "\\(SONAME\\)[^\n]*\\[${name}\\.${SOVERSION}\\]")
      message(FATAL_ERROR "${name}.${VERSION}: SONAME is not ${name}.${SOVERSION}:\n${RUN_OUT}")
    endif()
  endforeach()
  foreach(exe ${prefix}/bin/nanopush ${prefix}/lib/libnanopush_capi.so)
    run(${READELF} -d ${exe})
    string(REGEX MATCHALL "\\(NEEDED\\)[^\n]*\\[libnanopush_[a-z0-9_.]*\\]" needed "${RUN_OUT}")
    if(NOT needed)
      message(FATAL_ERROR "${exe} needs no nanopush library: is it linked statically?")
    endif()
    foreach(n IN LISTS needed)
      if(NOT n MATCHES "\\.so\\.${SOVERSION}\\]$")
        message(FATAL_ERROR "${exe} records an unversioned nanopush library: ${n}")
      endif()
    endforeach()
  endforeach()
  message(STATUS "${n_libs} shared libraries, each SONAME libnanopush_*.so.${SOVERSION}, file .so.${VERSION}")
else()
  message(FATAL_ERROR "unknown STEP ${STEP}")
endif()
message(STATUS "export ${MODE} ${STEP}: all checks hold")
