# Copyright 2026 the brdfbake authors.
# SPDX-License-Identifier: Apache-2.0
#
# The openpbr preset and what it rests on, from the command line: run as
# `cmake -DBRDFBAKE=path -DOUT=dir -P openpbr_cli_test.cmake`. --part and
# the two-sided ior axis on small glass bakes (and bad input refused in one
# line), then the whole preset, which writes openpbr_energy_arrays.h.

include(${CMAKE_CURRENT_LIST_DIR}/cli_util.cmake)

file(REMOVE_RECURSE "${OUT}")
file(MAKE_DIRECTORY "${OUT}")

# The preset is listed.
run_tool(TRUE out err bake --help)
if(NOT out MATCHES "openpbr")
  message(FATAL_ERROR "bake --help does not list the openpbr preset")
endif()

# The reflection alone over a two-sided ior axis; the header says both.
run_tool(TRUE out err bake --table E --model ggx-glass --part reflection --masking separable --size 4x3x4
         --warp ior=two-sided --range ior=0.4:2.5 --complement -o "${OUT}/opaque.exr")
if(NOT out MATCHES "E ggx-glass 4x12 \\(4 ior slices of 3 rows\\)" OR NOT EXISTS "${OUT}/opaque.exr")
  message(FATAL_ERROR "bake --part reflection: '${out}'")
endif()
file(STRINGS "${OUT}/opaque.exr" exr REGEX "brdfbake|ior")
if(NOT exr MATCHES "two-sided" OR NOT exr MATCHES "reflection: the reflection lobe alone")
  message(FATAL_ERROR "opaque.exr: the header lacks the two-sided axis or the part")
endif()
run_tool(TRUE out err bake --table E_avg --model ggx-glass --part transmission --size 3x4
         --warp ior=two-sided --range ior=0.5:2 -o "${OUT}/t_avg.exr")
if(NOT out MATCHES "E_avg ggx-glass 3x4" OR NOT EXISTS "${OUT}/t_avg.exr")
  message(FATAL_ERROR "bake --part transmission E_avg: '${out}'")
endif()
expect_error_matching("--part" bake --table E --model ggx-glass --part refraction -o "${OUT}/bad1.exr")
expect_error_matching("--part" bake --table E --model ggx --part reflection -o "${OUT}/bad2.exr")
expect_error_matching("two-sided" bake --table E --model ggx-glass --size 4x3x5 --warp ior=two-sided
                      --range ior=0.4:2.5 -o "${OUT}/bad3.exr")
expect_error_matching("two-sided" bake --table E --model ggx-glass --size 4x3x4 --warp ior=two-sided
                      --range ior=1.2:2.5 -o "${OUT}/bad4.exr")
expect_error_matching("--part" bake --preset openpbr --part reflection -o "${OUT}/bad5")

# The preset: one header, the engine's file name.
run_tool(TRUE out err bake --preset openpbr -o "${OUT}/impl/data")
if(NOT out MATCHES "wrote .*openpbr_energy_arrays.h" OR NOT EXISTS "${OUT}/impl/data/openpbr_energy_arrays.h")
  message(FATAL_ERROR "bake --preset openpbr: '${out}'")
endif()
file(READ "${OUT}/impl/data/openpbr_energy_arrays.h" header)
foreach(name IdealDielectricEnergyComplement IdealDielectricAverageEnergyComplement IdealDielectricReflectionRatio
             OpaqueDielectricEnergyComplement OpaqueDielectricAverageEnergyComplement IdealMetalEnergyComplement
             IdealMetalAverageEnergyComplement)
  if(NOT header MATCHES "OPENPBR_CONSTEXPR_GLOBAL OpenPBR_EnergyTableElement OpenPBR_${name}_Array\\[")
    message(FATAL_ERROR "openpbr_energy_arrays.h lacks OpenPBR_${name}_Array")
  endif()
endforeach()
file(GLOB leftovers "${OUT}/bad*" "${OUT}/.brdfbake-*" "${OUT}/impl/data/.brdfbake-*")
if(leftovers)
  message(FATAL_ERROR "files left behind: ${leftovers}")
endif()
message(STATUS "cli openpbr: all checks passed")
