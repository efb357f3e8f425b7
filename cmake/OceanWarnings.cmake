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
