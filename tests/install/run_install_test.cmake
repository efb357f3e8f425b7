# Installs the built project into a scratch prefix (then moves the prefix: the package must be
# relocatable), and builds and runs separate consumer projects against it:
#   - find_package(ocean) and ocean::ocean (C++) and ocean::c (C), as usual;
#   - find_package(ocean COMPONENTS c) with the C++ libraries' dependencies (oneTBB, hwy,
#     libpng, OpenEXR, Vulkan, TinyGLTF, CUDA) hidden from CMake: the system prefixes ignored;
#   - the control: the full package in that hidden setup must fail to configure;
#   - a C program compiled with `pkg-config --cflags --libs ocean-c` alone.
file(REMOVE_RECURSE ${WORK_DIR})
set(staging ${WORK_DIR}/staging)
set(prefix ${WORK_DIR}/prefix)
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${staging}
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${rc})")
endif()
file(RENAME ${staging} ${prefix})

function(run_program path what)
  execute_process(COMMAND ${path} RESULT_VARIABLE rc OUTPUT_VARIABLE out)
  message(STATUS "${what} printed: ${out}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (${rc})")
  endif()
endfunction()

execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/install/consumer
                        -B ${WORK_DIR}/consumer -G ${GENERATOR}
                        -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=Release
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "configuring the consumer with find_package(ocean) failed (${rc})")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/consumer RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "building the consumer failed (${rc})")
endif()
run_program(${WORK_DIR}/consumer/consumer "consumer")
run_program(${WORK_DIR}/consumer/consumer_c "the C consumer of libocean_c.so")

# No C++ dev package: every system prefix ignored by find_package and the find_* commands (the
# packages of oneTBB, hwy, OpenEXR, TinyGLTF, Vulkan, libpng and CUDA all live under them; "/"
# because /lib is /usr/lib on a merged-/usr system), and
# no package registry; the compiler itself is not looked up with find_*.
set(hidden -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=Release
           "-DCMAKE_IGNORE_PREFIX_PATH=/\;/usr\;/usr/local\;/opt"
           -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF -DCMAKE_FIND_USE_SYSTEM_PACKAGE_REGISTRY=OFF)
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/install/consumer_c
                        -B ${WORK_DIR}/consumer_c_only -G ${GENERATOR} ${hidden}
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "find_package(ocean COMPONENTS c) failed with the C++ dependencies hidden")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/consumer_c_only RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "building the C-only consumer failed (${rc})")
endif()
run_program(${WORK_DIR}/consumer_c_only/consumer_c "the C-only consumer (COMPONENTS c)")

# The control: the same hiding makes the full package fail (its dependencies are not found), so
# the C-only success above is the export set's doing, not a hiding that hides nothing.
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/install/consumer
                        -B ${WORK_DIR}/consumer_hidden -G ${GENERATOR} ${hidden}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc EQUAL 0)
  message(FATAL_ERROR "control: the full package configured with its dependencies hidden")
endif()
string(REGEX MATCH "Could NOT find [A-Za-z]+|Could not find a package configuration file [^\n]*"
       why "${out}${err}")
message(STATUS "control: the full package fails in the hidden setup, as it must (${why})")

# pkg-config alone: the compiler and the flags of lib/pkgconfig/ocean-c.pc.
if(PKG_CONFIG AND C_COMPILER)
  set(ENV{PKG_CONFIG_PATH} ${prefix}/${LIBDIR}/pkgconfig)
  set(ENV{PKG_CONFIG_LIBDIR} ${prefix}/${LIBDIR}/pkgconfig)  # nothing of the system's
  execute_process(COMMAND ${PKG_CONFIG} --cflags --libs ocean-c RESULT_VARIABLE rc
                  OUTPUT_VARIABLE flags OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "pkg-config --cflags --libs ocean-c failed (${rc})")
  endif()
  message(STATUS "pkg-config ocean-c: ${flags}")
  if(NOT flags MATCHES "-I${prefix}/")
    message(FATAL_ERROR "ocean-c.pc does not point into the moved prefix: ${flags}")
  endif()
  separate_arguments(flag_list UNIX_COMMAND "${flags}")
  execute_process(COMMAND ${C_COMPILER} ${SOURCE_DIR}/tests/install/consumer/main_c.c ${flag_list}
                          -Wl,-rpath,${prefix}/${LIBDIR} -o ${WORK_DIR}/consumer_pkgconfig
                  RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "compiling the C consumer with pkg-config's flags failed (${rc})")
  endif()
  run_program(${WORK_DIR}/consumer_pkgconfig "the pkg-config consumer")
else()
  message(STATUS "no pkg-config or C compiler given: the pkg-config consumer is not built")
endif()
