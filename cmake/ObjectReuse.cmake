# One compile for two link configurations. Every object is compiled position-independent
# (CMAKE_POSITION_INDEPENDENT_CODE), so the objects of a static build are also those of a shared
# one. This build writes, per compiled target, the list of its objects
# (objects/<target>.txt, at generate time). A tree configured with
#   -DNANOPUSH_OBJECTS_FROM=<that build tree> -DBUILD_SHARED_LIBS=ON
# compiles nothing: each of its targets links the other tree's objects (same sources, same
# flags, so the same machine code) into shared libraries and executables. The test suite's
# shared install (tests/cli/export.cmake: export.shared.install) is built this way, in seconds
# instead of a second full compile. Targets must match: the other tree is this source tree
# built first with the same build type and flags (tests/export/run_export_test.cmake does that).

function(_nanopush_compiled_targets dir out)
  get_property(targets DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
  get_property(subdirs DIRECTORY ${dir} PROPERTY SUBDIRECTORIES)
  foreach(sub IN LISTS subdirs)
    _nanopush_compiled_targets(${sub} more)
    list(APPEND targets ${more})
  endforeach()
  set(kept "")
  foreach(t IN LISTS targets)
    get_target_property(type ${t} TYPE)
    if(type MATCHES "^(STATIC_LIBRARY|SHARED_LIBRARY|MODULE_LIBRARY|EXECUTABLE)$")
      list(APPEND kept ${t})
    endif()
  endforeach()
  set(${out} ${kept} PARENT_SCOPE)
endfunction()

_nanopush_compiled_targets(${PROJECT_SOURCE_DIR} _np_compiled)

if(NOT NANOPUSH_OBJECTS_FROM)
  foreach(t IN LISTS _np_compiled)
    file(GENERATE OUTPUT ${PROJECT_BINARY_DIR}/objects/${t}.txt CONTENT "$<JOIN:$<TARGET_OBJECTS:${t}>,\n>\n")
  endforeach()
  return()
endif()

foreach(t IN LISTS _np_compiled)
  set(list_file ${NANOPUSH_OBJECTS_FROM}/objects/${t}.txt)
  if(NOT EXISTS ${list_file})
    message(FATAL_ERROR "NANOPUSH_OBJECTS_FROM=${NANOPUSH_OBJECTS_FROM}: no object list for target ${t} "
                        "(${list_file}); build that tree first, with the same options")
  endif()
  file(STRINGS ${list_file} objects)
  # The link language the sources gave the target (CMake cannot infer it from objects).
  get_target_property(sources ${t} SOURCES)
  set(lang C)
  if(sources MATCHES "\\.(f|F|f90|F90)(;|$)")
    set(lang Fortran)
  endif()
  if(sources MATCHES "\\.(cpp|cxx|cc)(;|$)")
    set(lang CXX)
  endif()
  set_source_files_properties(${objects} TARGET_DIRECTORY ${t} PROPERTIES EXTERNAL_OBJECT TRUE GENERATED TRUE)
  set_target_properties(${t} PROPERTIES SOURCES "${objects}" LINKER_LANGUAGE ${lang} UNITY_BUILD OFF)
endforeach()
