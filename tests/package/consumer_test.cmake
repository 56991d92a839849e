# Copyright 2026 the brdfbake authors.
# SPDX-License-Identifier: Apache-2.0
#
# The installed package as a consumer sees it: `cmake --install` of this
# build into a fresh prefix, then examples/consumer configured with
# find_package(brdfbake) against that prefix, built and run; compiled with
# the flags pkg-config gives for the installed .pc files; and the same
# example with brdfbake as a subdirectory (add_subdirectory).
# Run as cmake -DBUILD_DIR=... -DSOURCE_DIR=... -DWORK_DIR=... -P consumer_test.cmake.

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${ARGN}: exit ${rc}\n${out}\n${err}")
  endif()
  message(STATUS "${out}")
endfunction()

file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)
run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
foreach(f include/brdfbake/batch.h include/brdfbake/models/ggx.h include/brdfbake/version.h
          lib/cmake/brdfbake/brdfbakeConfig.cmake bin/brdfbake)
  if(NOT EXISTS ${prefix}/${f})
    message(FATAL_ERROR "not installed: ${f}")
  endif()
endforeach()

# find_package against the installed tree: build and run every program.
run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples/consumer -B ${WORK_DIR}/installed
    -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=Release)
run(${CMAKE_COMMAND} --build ${WORK_DIR}/installed -j2)
run(${WORK_DIR}/installed/shade)
run(${WORK_DIR}/installed/mixed_batch)
run(${WORK_DIR}/installed/bake_one)
run(${WORK_DIR}/installed/bake_preset ${WORK_DIR}/baked)
foreach(f DFGLUTData.js DFGLUTData.glsl dfg.ktx2)
  if(NOT EXISTS ${WORK_DIR}/baked/${f})
    message(FATAL_ERROR "bake_preset did not write ${f}")
  endif()
endforeach()

# pkg-config against the installed tree: the batch examples compiled and
# linked with brdfbake-core's flags alone.
find_program(PKG_CONFIG pkg-config REQUIRED)
foreach(pc brdfbake-core brdfbake-baker brdfbake)
  if(NOT EXISTS ${prefix}/lib/pkgconfig/${pc}.pc)
    message(FATAL_ERROR "not installed: lib/pkgconfig/${pc}.pc")
  endif()
endforeach()
set(ENV{PKG_CONFIG_PATH} ${prefix}/lib/pkgconfig)
execute_process(COMMAND ${PKG_CONFIG} --cflags --libs brdfbake-core OUTPUT_VARIABLE flags
                RESULT_VARIABLE rc OUTPUT_STRIP_TRAILING_WHITESPACE)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "pkg-config --cflags --libs brdfbake-core: exit ${rc}")
endif()
separate_arguments(flags UNIX_COMMAND "${flags}")
foreach(example shade mixed_batch)
  run(c++ -std=c++17 -O2 ${SOURCE_DIR}/examples/consumer/${example}.cc ${flags}
      -o ${WORK_DIR}/pc_${example})
  run(${WORK_DIR}/pc_${example})
endforeach()
# The baker's flags name everything it needs: a program using it links.
execute_process(COMMAND ${PKG_CONFIG} --cflags --libs brdfbake-baker OUTPUT_VARIABLE flags
                RESULT_VARIABLE rc OUTPUT_STRIP_TRAILING_WHITESPACE)
separate_arguments(flags UNIX_COMMAND "${flags}")
run(c++ -std=c++17 -O2 ${SOURCE_DIR}/examples/consumer/bake_one.cc ${flags}
    -o ${WORK_DIR}/pc_bake_one)
run(${WORK_DIR}/pc_bake_one)

# add_subdirectory: configured (not built: that would compile the library a
# second time) with a parent build type it must keep, and with the
# brdfbake:: targets defined.
run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples/consumer -B ${WORK_DIR}/subdir
    -DBRDFBAKE_SOURCE_DIR=${SOURCE_DIR} -DCMAKE_BUILD_TYPE=RelWithDebInfo)
file(STRINGS ${WORK_DIR}/subdir/CMakeCache.txt type REGEX "^CMAKE_BUILD_TYPE:")
if(NOT type STREQUAL "CMAKE_BUILD_TYPE:STRING=RelWithDebInfo")
  message(FATAL_ERROR "add_subdirectory changed the parent's build type: ${type}")
endif()
file(STRINGS ${WORK_DIR}/subdir/CMakeCache.txt tests REGEX "^BRDFBAKE_BUILD_TESTS:")
if(NOT tests STREQUAL "BRDFBAKE_BUILD_TESTS:BOOL=OFF")
  message(FATAL_ERROR "a subproject builds brdfbake's tests: ${tests}")
endif()
# brdfbake::core alone through add_subdirectory, configured with the
# packages only the baker and the full library need made unfindable
# (CMAKE_DISABLE_FIND_PACKAGE_<name>), then the mixed-material example
# built and run (with the ggx family alone, to keep the build short).
run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples/consumer -B ${WORK_DIR}/core_only
    -DBRDFBAKE_SOURCE_DIR=${SOURCE_DIR} -DBRDFBAKE_CORE_ONLY=ON -DBRDFBAKE_MODELS=ggx
    -DCMAKE_BUILD_TYPE=Release
    -DCMAKE_DISABLE_FIND_PACKAGE_TBB=ON -DCMAKE_DISABLE_FIND_PACKAGE_OpenEXR=ON
    -DCMAKE_DISABLE_FIND_PACKAGE_Imath=ON -DCMAKE_DISABLE_FIND_PACKAGE_tomlplusplus=ON
    -DCMAKE_DISABLE_FIND_PACKAGE_CLI11=ON -DCMAKE_DISABLE_FIND_PACKAGE_GTest=ON
    -DCMAKE_DISABLE_FIND_PACKAGE_benchmark=ON)
run(${CMAKE_COMMAND} --build ${WORK_DIR}/core_only -j2 --target mixed_batch)
run(${WORK_DIR}/core_only/mixed_batch)
file(REMOVE_RECURSE ${WORK_DIR})
