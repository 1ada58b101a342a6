# What the tests over every rough preset and friction law share (compare_laws.cmake,
# rough_laws.cmake): the thesis law's documented failure, and one test per law that runs the
# including file as the check (cmake -P).

# Whether a command's exit status `rc` and standard error `err` under `law` are the thesis law's
# documented failure where it chatters at rest (mu N > F, no static friction): exit 3, and a
# message that says where the bar came to rest and that the coulomb law continues. Sets out_var.
function(thesis_law_rests_as_documented law rc err out_var)
  if(rc EQUAL 3 AND law STREQUAL "thesis"
     AND err MATCHES "no_static_friction: .*came to rest at t = [0-9.e+-]+ s \\(x = .* theta = "
     AND err MATCHES "--law coulomb")
    set(${out_var} TRUE PARENT_SCOPE)
  else()
    set(${out_var} FALSE PARENT_SCOPE)
  endif()
endfunction()

# Tests <name>_thesis, <name>_printed and <name>_coulomb: cmake -P on the calling file with -DNP
# (the nanopush program), -DLAW and the further -D arguments in ARGN.
function(add_test_per_law name)
  foreach(_law IN ITEMS thesis printed coulomb)
    add_test(NAME ${name}_${_law}
             COMMAND ${CMAKE_COMMAND} -DNP=$<TARGET_FILE:nanopush> -DLAW=${_law} ${ARGN} -P ${CMAKE_CURRENT_LIST_FILE})
    set_tests_properties(${name}_${_law} PROPERTIES ENVIRONMENT "NANOPUSH_SCENES=${NANOPUSH_SCENES}")
  endforeach()
endfunction()
