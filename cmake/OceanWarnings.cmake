# Compiler warnings and sanitizers applied to every target of the project.
function(ocean_target_defaults target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wconversion -Wshadow
                                           -Wnon-virtual-dtor -Wold-style-cast
                                           -Wno-missing-field-initializers)
  if(OCEAN_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()

if(OCEAN_SANITIZE)
  # -g1: line tables only — sanitizer reports keep file:line, and the build is ~30 % faster than
  # with full debug information (the CLI11/gtest-heavy files dominate it).
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=undefined
                      -fno-omit-frame-pointer -g1)
  add_link_options(-fsanitize=address,undefined)
endif()

if(OCEAN_FUZZ)
  # libFuzzer (tests/fuzz): every library is instrumented for coverage and checked by ASan+UBSan,
  # so that the fuzzers' coverage reaches into them; only the fuzz targets link libFuzzer itself
  # (-fsanitize=fuzzer, tests/fuzz/CMakeLists.txt).
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "OCEAN_FUZZ needs clang (libFuzzer): use the fuzz preset")
  endif()
  if(OCEAN_SANITIZE)
    message(FATAL_ERROR "OCEAN_FUZZ brings its own sanitizers: leave OCEAN_SANITIZE off")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined
                      -fno-omit-frame-pointer -g1)
  add_link_options(-fsanitize=address,undefined)
endif()
