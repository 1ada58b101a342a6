# The installed package works for other projects and users, wherever it is (issue 8):
# tests/export/run_export_test.cmake, one CTest per check, for two install configurations:
#   export.static.*  `cmake --install` of this build tree (static libraries)
#   export.shared.*  nanopush configured again inside the test with -DBUILD_SHARED_LIBS=ON
#                    -DNANOPUSH_TESTS=OFF, linking this build tree's objects into shared libraries
#                    (cmake/ObjectReuse.cmake: no second compile), then installed
# Each mode's install step is a fixture of its checks:
#   cmake_consumers  C++ (no CMAKE_CXX_STANDARD), Fortran, and a C++-only project (no Fortran)
#   pkgconfig_c      a C program built with `pkg-config --cflags --libs nanopush` only
#   mu_fortran       Fortran μ estimation vs `nanopush icor estimate-mu`, bit for bit
#   relocated_cli    a copied prefix, original removed: `nanopush run fig3_6a` = the build tree's
#   symbols          no F77 / benchmark symbols in libnanopush_{numerics,models,scenes}
#   no_build_paths   no installed file names the source or build tree
# Sanitizer builds (NANOPUSH_SANITIZE) check the static install only, without no_build_paths:
# GCC's ASan/UBSan instrumentation writes source paths that -ffile-prefix-map does not reach, and
# a second, sanitized shared build would double the sanitizer run for no new coverage.
set(_export_modes static)
set(_export_steps cmake_consumers pkgconfig_c mu_fortran relocated_cli symbols)
if(NOT NANOPUSH_SANITIZE)
  list(APPEND _export_modes shared)
  list(APPEND _export_steps no_build_paths)
endif()
set(_config_flags "")
if(CMAKE_BUILD_TYPE)
  string(TOUPPER "${CMAKE_BUILD_TYPE}" _cfg)
  foreach(_lang C CXX Fortran)
    list(APPEND _config_flags "-DCMAKE_${_lang}_FLAGS_${_cfg}=${CMAKE_${_lang}_FLAGS_${_cfg}}")
  endforeach()
endif()
# Passed through one -D as a '|'-separated list (run_export_test.cmake splits it).
string(REPLACE ";" "|" _config_flags "${_config_flags}")

foreach(_mode IN LISTS _export_modes)
  set(_args
    -DMODE=${_mode}
    -DBUILD_DIR=${PROJECT_BINARY_DIR}
    -DSOURCE_DIR=${PROJECT_SOURCE_DIR}
    -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/export-${_mode}
    -DSCENE=${PROJECT_SOURCE_DIR}/drivers/scenes/thesis/fig3_6c.toml
    -DGENERATOR=${CMAKE_GENERATOR}
    -DMAKE_PROGRAM=${CMAKE_MAKE_PROGRAM}
    -DC_COMPILER=${CMAKE_C_COMPILER}
    -DCXX_COMPILER=${CMAKE_CXX_COMPILER}
    -DFortran_COMPILER=${CMAKE_Fortran_COMPILER}
    -DBUILD_TYPE=${CMAKE_BUILD_TYPE}
    "-DCONFIG_FLAGS=${_config_flags}")
  add_test(NAME export.${_mode}.install
    COMMAND ${CMAKE_COMMAND} -DSTEP=install ${_args} -P ${PROJECT_SOURCE_DIR}/tests/export/run_export_test.cmake)
  set_tests_properties(export.${_mode}.install PROPERTIES TIMEOUT 900 FIXTURES_SETUP export_${_mode}
    PASS_REGULAR_EXPRESSION "export ${_mode}: installed into")
  foreach(_step IN LISTS _export_steps)
    add_test(NAME export.${_mode}.${_step}
      COMMAND ${CMAKE_COMMAND} -DSTEP=${_step} ${_args} -P ${PROJECT_SOURCE_DIR}/tests/export/run_export_test.cmake)
    set_tests_properties(export.${_mode}.${_step} PROPERTIES TIMEOUT 600 FIXTURES_REQUIRED export_${_mode}
      PASS_REGULAR_EXPRESSION "export ${_mode} ${_step}: all checks hold")
  endforeach()
endforeach()
# Shared libraries only: versioned SONAMEs, recorded as such by what links them (readelf).
if("shared" IN_LIST _export_modes)
  add_test(NAME export.shared.sonames
    COMMAND ${CMAKE_COMMAND} -DSTEP=sonames -DMODE=shared -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/export-shared
            -DVERSION=${PROJECT_VERSION} -DSOVERSION=${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR}
            -P ${PROJECT_SOURCE_DIR}/tests/export/run_export_test.cmake)
  set_tests_properties(export.shared.sonames PROPERTIES TIMEOUT 600 FIXTURES_REQUIRED export_shared
    PASS_REGULAR_EXPRESSION "export shared sonames: all checks hold")
endif()
