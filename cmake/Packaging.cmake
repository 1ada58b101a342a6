# Install anywhere, link from anywhere: shared or static libraries, RPATH relative to the
# installed files, no build or source path in what is installed, and the Fortran runtime a
# static consumer needs recorded for the package files (cmake/Install.cmake).
include(GNUInstallDirs)

# BUILD_SHARED_LIBS decides for every nanopush library (the bench harness, a driver library,
# stays static). The C API library exports only its nanopush_* functions (bindings/CMakeLists.txt).
option(BUILD_SHARED_LIBS "Build the nanopush libraries as shared libraries" OFF)
# Drivers (nanopush, the legacy programs, examples): off for a library-only build.
option(NANOPUSH_DRIVERS "Build the command line, the legacy F77 programs and the examples" ON)

# Installed executables and libraries find the nanopush shared libraries relative to themselves,
# so an installed prefix can be copied or moved (bin/../lib, lib/../lib).
set(CMAKE_INSTALL_RPATH "$ORIGIN/../${CMAKE_INSTALL_LIBDIR}")

# No build or source path in the binaries: __FILE__ (assertions) and the debug information name
# files relative to the source tree (./cxx/...; in gdb: `directory /path/to/nanopush`) and the
# build tree (.). The build tree's map is given last: GCC tries the maps last-given first, and the
# build tree may lie inside the source tree. (Sanitizer builds still name the sources: GCC's
# ASan/UBSan instrumentation does not apply the maps.)
option(NANOPUSH_RELOCATABLE_PATHS "Keep build and source paths out of the compiled files" ON)
if(NANOPUSH_RELOCATABLE_PATHS AND CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
  add_compile_options("-ffile-prefix-map=${PROJECT_SOURCE_DIR}=." "-ffile-prefix-map=${PROJECT_BINARY_DIR}=.")
  # gfortran names the source in its run-time messages ("At line 12 of file ...", bounds checks
  # and I/O errors) and ignores -ffile-prefix-map there. With Ninja it compiles a preprocessed
  # copy whose line markers carry that name: this launcher makes them relative before compiling.
  if(CMAKE_Fortran_COMPILER_ID STREQUAL "GNU" AND CMAKE_GENERATOR MATCHES "Ninja"
     AND NOT CMAKE_Fortran_COMPILER_LAUNCHER)
    find_program(NANOPUSH_BASH bash REQUIRED)
    set(CMAKE_Fortran_COMPILER_LAUNCHER
        ${NANOPUSH_BASH} ${PROJECT_SOURCE_DIR}/cmake/fortran_relative_paths.sh ${PROJECT_SOURCE_DIR}/)
  endif()
endif()

# The Fortran run-time library, for consumers of the static libraries that do not enable Fortran
# (nanopushConfig.cmake: nanopush::fortran_runtime; nanopush.pc: Libs). An absolute path found
# now (the C++ compiler of a consumer need not search gfortran's directory), else -lgfortran.
# quadmath is linked by name (nanopush_numerics): every GCC-family compiler finds it.
set(NANOPUSH_FORTRAN_RUNTIME gfortran)
if(CMAKE_Fortran_COMPILER_ID STREQUAL "GNU")
  execute_process(COMMAND ${CMAKE_Fortran_COMPILER} -print-file-name=libgfortran.so
                  OUTPUT_VARIABLE _gfortran OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE _rc)
  if(_rc EQUAL 0 AND IS_ABSOLUTE "${_gfortran}" AND EXISTS "${_gfortran}")
    get_filename_component(_gfortran "${_gfortran}" REALPATH)
    set(NANOPUSH_FORTRAN_RUNTIME ${_gfortran})
  endif()
endif()
