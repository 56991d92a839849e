# Copyright 2026 the brdfbake authors.
# SPDX-License-Identifier: Apache-2.0
#
# The eevee preset and what it rests on, from the command line: run as
# `cmake -DBRDFBAKE=path -DOUT=dir -P eevee_cli_test.cmake`. --part
# transmission-schlick and the one-minus-square warp on a small glass bake
# (an ior axis to inf), bad input refused in one line, then the whole
# preset, which writes eevee_lut.cc.

include(${CMAKE_CURRENT_LIST_DIR}/cli_util.cmake)

file(REMOVE_RECURSE "${OUT}")
file(MAKE_DIRECTORY "${OUT}")

run_tool(TRUE out err bake --help)
if(NOT out MATCHES "eevee" OR NOT out MATCHES "transmission-schlick")
  message(FATAL_ERROR "bake --help does not list the eevee preset or the transmission-schlick part")
endif()

# The Schlick-weighted refraction over an ior axis to inf, mu on the
# one-minus-square warp; the header says both.
run_tool(TRUE out err bake --table E --model ggx-glass --part transmission-schlick --masking separable
         --size 5x3x4 --range ior=1:inf --warp mu=one-minus-square -o "${OUT}/btdf.exr")
if(NOT out MATCHES "E ggx-glass 5x12 \\(4 ior slices of 3 rows\\)" OR NOT EXISTS "${OUT}/btdf.exr")
  message(FATAL_ERROR "bake --part transmission-schlick: '${out}'")
endif()
file(STRINGS "${OUT}/btdf.exr" exr REGEX "brdfbake")
if(NOT exr MATCHES "one-minus-square" OR NOT exr MATCHES "transmission-schlick" OR NOT exr MATCHES "inf")
  message(FATAL_ERROR "btdf.exr: the header lacks the warp, the part or the ior axis to inf")
endif()
expect_error_matching("transmission-schlick" bake --table E --model ggx-glass --part transmission-schlick
                      --inverse --size 4x3x4 -o "${OUT}/bad1.exr")
expect_error_matching("--warp" bake --table E --model ggx-glass --warp mu=one-minus-squared -o "${OUT}/bad2.exr")
expect_error_matching("--range" bake --table E --model ggx-glass --part transmission --size 4x3x4
                      --range ior=1:inf -o "${OUT}/bad3.exr")
expect_error_matching("--shader" bake --preset eevee --shader glsl -o "${OUT}/bad4")

# The preset: one file, the engine's name, its array and the #include of
# Blender's own tables.
run_tool(TRUE out err bake --preset eevee -o "${OUT}/eevee_next")
if(NOT out MATCHES "wrote .*eevee_lut.cc" OR NOT EXISTS "${OUT}/eevee_next/eevee_lut.cc")
  message(FATAL_ERROR "bake --preset eevee: '${out}'")
endif()
file(READ "${OUT}/eevee_next/eevee_lut.cc" source)
foreach(needle "const float btdf_ggx\\[16\\]\\[64\\]\\[64\\]\\[1\\] = {" "#include \"eevee_lut_blender.cc\""
               "namespace blender::eevee::lut")
  if(NOT source MATCHES "${needle}")
    message(FATAL_ERROR "eevee_lut.cc lacks '${needle}'")
  endif()
endforeach()
file(GLOB leftovers "${OUT}/bad*" "${OUT}/.brdfbake-*" "${OUT}/eevee_next/.brdfbake-*")
if(leftovers)
  message(FATAL_ERROR "files left behind: ${leftovers}")
endif()
message(STATUS "cli eevee: all checks passed")
