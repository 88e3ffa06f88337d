# triwalk_set_warnings(target): the project's warning level, applied per target
# (never directory-wide, so third-party sources keep their own flags).
function(triwalk_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor)
  # GCC 12 reports std::string concatenation as overlapping memcpy at -O3
  # (GCC bug 105329, a false positive); keep every other warning.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    target_compile_options(${target} PRIVATE -Wno-restrict)
  endif()
  if(TRIWALK_WARNINGS_AS_ERRORS)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
