# Installs the built project into a scratch prefix, then configures, builds (warnings as errors)
# and runs examples/engine_integration against it, and checks what it printed and wrote:
#   - a height for each queried point, every one a finite number;
#   - the measured Hs within 4 sampling standard deviations of the spectrum's (the standard
#     deviation is the library's hs_sampling_rel_std, ½·√(1/(n_eff·seeds)); the same ≥ 4σ bound
#     as tests/statistics/surface_stats_test.cpp);
#   - the PPM image: the printed size, the file size that implies, and not one uniform colour.
# Exit status 77 of the example (no Vulkan device able to render) marks the test skipped after
# the checks of the simulation's figures have passed, or failed with OCEAN_REQUIRE_DEVICES=1
# (tests/support/require_devices.hpp).
file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix}
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${rc})")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples/engine_integration
                        -B ${WORK_DIR}/example -G ${GENERATOR}
                        -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=Release
                        -DCMAKE_COMPILE_WARNING_AS_ERROR=ON
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "configuring the example with find_package(ocean) failed (${rc})")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/example RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "building the example failed (${rc})")
endif()
set(image ${WORK_DIR}/ocean.ppm)
execute_process(COMMAND ${WORK_DIR}/example/engine_integration ${image}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message(STATUS "the example printed:\n${out}${err}")
if(NOT (rc EQUAL 0 OR rc EQUAL 77))
  message(FATAL_ERROR "the example failed (${rc})")
endif()

# A decimal printed with %.6f ("-0.123456") as an integer number of millionths.
function(to_millionths text out)
  if(NOT text MATCHES "^(-?)([0-9]+)\\.([0-9][0-9][0-9][0-9][0-9][0-9])$")
    message(FATAL_ERROR "'${text}' is not a number printed with six decimals")
  endif()
  math(EXPR value "${CMAKE_MATCH_2}${CMAKE_MATCH_3}")
  set(${out} ${CMAKE_MATCH_1}${value} PARENT_SCOPE)
endfunction()

# Heights: four lines "height at (x, z) m: <h> m" with finite numbers (nan/inf fail the match).
string(REGEX MATCHALL "height at [^\n]*" heights "${out}")
list(LENGTH heights count)
if(NOT count EQUAL 4)
  message(FATAL_ERROR "expected 4 heights, found ${count}")
endif()
foreach(line IN LISTS heights)
  if(NOT line MATCHES "m: -?[0-9]+\\.[0-9]+ m$")
    message(FATAL_ERROR "not a finite height: '${line}'")
  endif()
endforeach()

# Hs: |measured − spectrum| ≤ 4·σ·spectrum, in millionths (products stay below 2^63).
if(NOT out MATCHES "Hs measured ([-0-9.]+) m, spectrum ([-0-9.]+) m, sampling std ([-0-9.]+)")
  message(FATAL_ERROR "the example printed no Hs line")
endif()
to_millionths(${CMAKE_MATCH_1} measured)
to_millionths(${CMAKE_MATCH_2} spectrum)
to_millionths(${CMAKE_MATCH_3} sigma)
math(EXPR difference "${measured} - ${spectrum}")
if(difference LESS 0)
  math(EXPR difference "-${difference}")
endif()
math(EXPR bound "4 * ${sigma} * ${spectrum} / 1000000")
if(spectrum LESS_EQUAL 0 OR sigma LESS_EQUAL 0 OR difference GREATER bound)
  message(FATAL_ERROR "Hs measured ${measured} µm vs spectrum ${spectrum} µm: "
                      "|difference| ${difference} µm exceeds 4σ = ${bound} µm")
endif()

if(rc EQUAL 77)
  if(NOT "$ENV{OCEAN_REQUIRE_DEVICES}" STREQUAL "" AND NOT "$ENV{OCEAN_REQUIRE_DEVICES}" STREQUAL "0")
    message(FATAL_ERROR "OCEAN_REQUIRE_DEVICES is set, and the example found no Vulkan device "
                        "able to render")
  endif()
  message(STATUS "example: render skipped, no Vulkan device")
  return()
endif()

# The image: "rendered W x H" and a binary PPM of that size whose pixels are not all alike.
if(NOT out MATCHES "rendered ([0-9]+) x ([0-9]+) on ")
  message(FATAL_ERROR "the example printed no 'rendered' line")
endif()
set(width ${CMAKE_MATCH_1})
set(height ${CMAKE_MATCH_2})
if(NOT EXISTS ${image})
  message(FATAL_ERROR "the example wrote no image ${image}")
endif()
set(header "P6\n${width} ${height}\n255\n")
string(LENGTH "${header}" header_bytes)
math(EXPR expected "${header_bytes} + ${width} * ${height} * 3")
file(SIZE ${image} size)
if(NOT size EQUAL expected)
  message(FATAL_ERROR "${image} has ${size} bytes, expected ${expected} for ${width} x ${height}")
endif()
file(READ ${image} head LIMIT ${header_bytes})
if(NOT head STREQUAL header)
  message(FATAL_ERROR "${image} does not start with the PPM header '${header}'")
endif()
file(READ ${image} pixels OFFSET ${header_bytes} HEX)
string(SUBSTRING "${pixels}" 0 6 first)
string(REPLACE "${first}" "" others "${pixels}")
if(others STREQUAL "")
  message(FATAL_ERROR "${image} is one uniform colour (#${first})")
endif()
