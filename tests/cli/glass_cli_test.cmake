# Copyright 2026 the brdfbake authors.
# SPDX-License-Identifier: Apache-2.0
#
# The ggx-glass tables from the command line: run as
# `cmake -DBRDFBAKE=path -DOUT=dir -P glass_cli_test.cmake`. A small E and
# E_avg bake (entering and --inverse), eval of one value with its error,
# and bad input refused in one line with no file left behind.

include(${CMAKE_CURRENT_LIST_DIR}/cli_util.cmake)

file(REMOVE_RECURSE "${OUT}")
file(MAKE_DIRECTORY "${OUT}")

# The model is listed and suggested.
run_tool(TRUE out err eval --help)
if(NOT out MATCHES "ggx-glass")
  message(FATAL_ERROR "eval --help does not list ggx-glass")
endif()
expect_error_matching("ggx-glass" eval --model ggx-glas --quantity E)

# Bakes: E over mu x roughness x ior, E_avg over roughness x ior, and the
# inverse side; the header records the ior axis and its warp.
run_tool(TRUE out err bake --table E --model ggx-glass --size 4x3x3 --error-channel -o "${OUT}/E.exr")
if(NOT out MATCHES "E ggx-glass 4x9 \\(3 ior slices of 3 rows\\)" OR
   NOT out MATCHES "max abs error [0-9.]+e-0[78]" OR NOT EXISTS "${OUT}/E.exr")
  message(FATAL_ERROR "bake ggx-glass E: '${out}'")
endif()
file(STRINGS "${OUT}/E.exr" exr REGEX "brdfbake|ior")
if(NOT exr MATCHES "\"name\":\"ior\"" OR NOT exr MATCHES "fresnel-z" OR NOT exr MATCHES "ggx-glass")
  message(FATAL_ERROR "E.exr: the header lacks the ior axis or the model")
endif()
run_tool(TRUE out err bake --table E --model ggx-glass --size 4x3x3 --inverse --range ior=1.2:2
         --warp ior=linear -o "${OUT}/E_inv.exr")
if(NOT out MATCHES "inverse" OR NOT EXISTS "${OUT}/E_inv.exr")
  message(FATAL_ERROR "bake ggx-glass --inverse: '${out}'")
endif()
file(STRINGS "${OUT}/E_inv.exr" exr REGEX "brdfbake|ior")
if(NOT exr MATCHES "1 / ior")
  message(FATAL_ERROR "E_inv.exr: the header does not say eta = 1 / ior")
endif()
run_tool(TRUE out err bake --table E_avg --model ggx-glass --size 3x2 --masking separable
         -o "${OUT}/Eavg.exr")
if(NOT out MATCHES "E_avg ggx-glass 3x2" OR NOT EXISTS "${OUT}/Eavg.exr")
  message(FATAL_ERROR "bake ggx-glass E_avg: '${out}'")
endif()

# eval: one value with its error. At roughness 0 the smooth interface
# keeps every bit of energy: E = 1 exactly, error 0.
run_tool(TRUE out err eval --quantity E --model ggx-glass --roughness 0.3 --ior 1.5 --mu-o 0.4)
if(NOT out MATCHES "^mu,roughness,E,E_error\n0\\.4[0-9]*,0\\.[23][0-9]*,0\\.9[0-9]+,[0-9.]+e-[0-9]+\n$")
  message(FATAL_ERROR "eval ggx-glass E: '${out}'")
endif()
run_tool(TRUE out err eval --quantity E_avg --model ggx-glass --roughness 0.5 --ior 0.6)
if(NOT out MATCHES "^mu,roughness,E_avg,E_avg_error\n1,0\\.5,0\\.[0-9]+,[0-9.]+e-[0-9]+\n$")
  message(FATAL_ERROR "eval ggx-glass E_avg: '${out}'")
endif()
run_tool(TRUE out err eval --quantity E --model ggx-glass --roughness 0 --ior 1.5 --mu-o 0.4)
if(NOT out MATCHES "^mu,roughness,E,E_error\n0\\.4[0-9]*,0,1,0\n$")
  message(FATAL_ERROR "eval ggx-glass E at roughness 0: '${out}'")
endif()

# Bad input: one line naming the parameter, no file.
expect_error_matching("--ior" eval --quantity E --model ggx-glass --roughness 0.3 --ior 0 --mu-o 0.4)
expect_error_matching("--ior" eval --quantity E --model ggx-glass --roughness 0.3 --ior -1.5)
expect_error_matching("--ior" eval --quantity E --model ggx-glass --roughness 0.3 --ior nan)
expect_error_matching("--ior" eval --quantity E --model ggx-glass --roughness 0.3 --ior 1e3)
expect_error_matching("--ior" eval --quantity E --model ggx --roughness 0.3 --ior 1.5)
expect_error_matching("--quantity" eval --quantity dfg --model ggx-glass --roughness 0.3)
expect_error_matching("--quantity" eval --quantity D --model ggx-glass --roughness 0.3)
expect_error_matching("--grid" eval --grid hemisphere --model ggx-glass --roughness 0.3 -o "${OUT}/bad.exr")
expect_error_matching("--integrator" bake --table E --model ggx-glass --integrator qmc -o "${OUT}/bad.exr")
expect_error_matching("--table" bake --table dfg --model ggx-glass -o "${OUT}/bad.exr")
expect_error_matching("--range: the ior axis" bake --table E --model ggx-glass --range ior=0.5:1
                      -o "${OUT}/bad.exr")
expect_error_matching("--range: the ior axis" bake --table E --model ggx-glass --range ior=1:1000
                      -o "${OUT}/bad.exr")
expect_error_matching("--range" bake --table E --model ggx-glass --range ior=nan:2
                      -o "${OUT}/bad.exr")
expect_error_matching("--size" bake --table E --model ggx-glass --size 8x8 -o "${OUT}/bad.exr")
expect_error_matching("--warp" bake --table E --model ggx-glass --warp ior=sqrt -o "${OUT}/bad.exr")
expect_error_matching("--warp" bake --table E --model ggx-glass --warp mu=fresnel-z -o "${OUT}/bad.exr")
expect_error_matching("--inverse" bake --table E --model ggx --inverse -o "${OUT}/bad.exr")
expect_error_matching("--range: no ior axis" bake --table E --model ggx --range ior=1:2 -o "${OUT}/bad.exr")
# Other containers and the shader lookups: the header names the dielectric
# Fresnel and the ior slices, the GLSL lookup inverts the fresnel-z warp.
run_tool(TRUE out err bake --table E --model ggx-glass --size 2x2x2 --range ior=1.3:1.8 --tolerance 1e-5
         -o "${OUT}/glass.h" --shader glsl)
file(READ "${OUT}/glass.h" header)
file(READ "${OUT}/glass.glsl" glsl)
foreach(want "brdfbake.fresnel: dielectric" "slices of 2 rows stacked vertically over ior")
  string(FIND "${header}" "${want}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "glass.h lacks '${want}'")
  endif()
endforeach()
string(FIND "${glsl}" "sqrt(abs(ior - 1.0) / (ior + 1.0))" at)
if(at EQUAL -1)
  message(FATAL_ERROR "glass.glsl does not invert the fresnel-z warp:\n${glsl}")
endif()
# The generalized Schlick factor s over an exponent or an ior axis: the
# slices named in the summary, the schlick-z warp inverted by the lookup,
# and what it refuses.
run_tool(TRUE out err bake --table gen_schlick_s --size 3x3x4 --tolerance 1e-5 -o "${OUT}/gs.h" --shader glsl)
if(NOT out MATCHES "wrote .*gen_schlick_s ggx 3x12 \\(4 exponent slices of 3 rows\\)")
  message(FATAL_ERROR "bake --table gen_schlick_s: '${out}'")
endif()
file(READ "${OUT}/gs.glsl" glsl)
string(FIND "${glsl}" "5.0 / (exponent + 5.0)" at)
if(at EQUAL -1)
  message(FATAL_ERROR "gs.glsl does not invert the schlick-z warp:\n${glsl}")
endif()
run_tool(TRUE out err bake --table gen_schlick_ior_s --size 3x3x2 --range ior=1.2:2 --tolerance 1e-5
         -o "${OUT}/gsi.exr")
if(NOT out MATCHES "wrote .*gen_schlick_ior_s ggx 3x6 \\(2 ior slices of 3 rows\\)")
  message(FATAL_ERROR "bake --table gen_schlick_ior_s: '${out}'")
endif()
expect_error_matching("--model: gen_schlick_s is the Fresnel factor of a GGX" bake --table gen_schlick_s
                      --model beckmann -o "${OUT}/bad.exr")
expect_error_matching("--range: the exponent axis" bake --table gen_schlick_s --range exponent=inf:0
                      --warp exponent=linear -o "${OUT}/bad.exr")
expect_error_matching("--range: no exponent axis" bake --table gen_schlick_ior_s --range exponent=1:2
                      -o "${OUT}/bad.exr")
expect_error_matching("--complement" bake --table gen_schlick_s --complement -o "${OUT}/bad.exr")
expect_error_matching("--size" bake --table gen_schlick_s --size 8x8 -o "${OUT}/bad.exr")
expect_error_matching("report: gen_schlick_s has one integrator" report --table gen_schlick_s --size 4x4x4
                      -o "${OUT}/bad.csv")
file(GLOB leftovers "${OUT}/bad*" "${OUT}/.brdfbake-*")
if(leftovers)
  message(FATAL_ERROR "files left behind: ${leftovers}")
endif()
message(STATUS "glass cli: all checks passed")
