if(NANOPUSH_SANITIZE)
  set(_san -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  add_compile_options(${_san})
  add_link_options(${_san})
endif()
# A sanitized library needs the sanitizer runtime in whatever links it, installed
# consumers included: nanopush_numerics and nanopush_f77 carry the link option in their
# usage requirements (cxx/ and fortran/CMakeLists.txt).
set(NANOPUSH_SANITIZE_LINK $<$<BOOL:${NANOPUSH_SANITIZE}>:-fsanitize=address,undefined>)
