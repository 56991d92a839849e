# Copyright 2026 the brdfbake authors.
# SPDX-License-Identifier: Apache-2.0
#
# Command-line contract: run as `cmake -DBRDFBAKE=path -P cli_test.cmake`.
# Each check runs the tool and asserts its exit status and output.

function(run_tool expect_ok out_var err_var)
  execute_process(COMMAND ${BRDFBAKE} ${ARGN}
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(expect_ok AND NOT rc EQUAL 0)
    message(FATAL_ERROR "brdfbake ${ARGN}: exit ${rc}, stderr: ${err}")
  endif()
  if(NOT expect_ok AND rc EQUAL 0)
    message(FATAL_ERROR "brdfbake ${ARGN}: expected a non-zero exit, got 0")
  endif()
  set(${out_var} "${out}" PARENT_SCOPE)
  set(${err_var} "${err}" PARENT_SCOPE)
endfunction()

function(expect_one_line_error)
  run_tool(FALSE out err ${ARGN})
  string(STRIP "${err}" err)
  string(FIND "${err}" "\n" nl)
  if(NOT nl EQUAL -1 OR err STREQUAL "")
    message(FATAL_ERROR "brdfbake ${ARGN}: expected a one-line error, got: '${err}'")
  endif()
  if(NOT out STREQUAL "")
    message(FATAL_ERROR "brdfbake ${ARGN}: expected no output on error, got: '${out}'")
  endif()
endfunction()

run_tool(TRUE out err --help)
if(NOT out MATCHES "eval" OR NOT out MATCHES "bake")
  message(FATAL_ERROR "--help does not list eval: ${out}")
endif()
run_tool(TRUE out err --version)
if(NOT out MATCHES "brdfbake [0-9]+\\.[0-9]+\\.[0-9]+" OR NOT out MATCHES "SIMD target in use")
  message(FATAL_ERROR "--version: ${out}")
endif()
run_tool(TRUE out err eval --help)
foreach(model ggx beckmann std ellipsoid sel)
  if(NOT out MATCHES "${model}")
    message(FATAL_ERROR "eval --help does not list model ${model}")
  endif()
endforeach()

# GGX Lambda at alpha = 1, mu = 0.5: (sqrt(1 + tan^2) - 1)/2 = (2 - 1)/2 = 0.5.
run_tool(TRUE out err eval --model ggx --alpha 1 --quantity Lambda --from 0.5 --to 0.5 --count 1)
if(NOT out MATCHES "^mu,theta_deg,Lambda\n0\\.5,60[.0-9]*,0\\.5[0-9]*\n$" AND
   NOT out MATCHES "^mu,theta_deg,Lambda\n0\\.5,60[.0-9]*,0\\.4999999[0-9]*\n$")
  message(FATAL_ERROR "eval Lambda: unexpected output '${out}'")
endif()

set(extra_ggx "")
set(extra_beckmann "")
set(extra_std --gamma 3)
set(extra_ellipsoid --theta-x 10)
foreach(model ggx beckmann std ellipsoid)
  run_tool(TRUE out err eval --model ${model} --roughness 0.5 ${extra_${model}}
           --quantity D,Lambda,G1,G2,brdf,pdf --fresnel conductor --count 21 --from 0.01 --mu-o 0.3)
  string(REGEX MATCHALL "\n" lines "${out}")
  list(LENGTH lines n)
  if(NOT n EQUAL 22)
    message(FATAL_ERROR "eval ${model}: expected 22 lines, got ${n}: ${out}")
  endif()
  if(out MATCHES "nan|inf")
    message(FATAL_ERROR "eval ${model}: non-finite output: ${out}")
  endif()
endforeach()
run_tool(TRUE out err eval --model sel --alpha-x 0.3 --alpha-y 0.6 --quantity K --count 5)
run_tool(TRUE out err eval --model std --gamma inf --quantity Lambda --sweep theta --from 0 --to 89 --count 4)

expect_one_line_error(frobnicate)
expect_one_line_error(eval --model phong)
expect_one_line_error(eval --alpha -1)
expect_one_line_error(eval --alpha abc)
expect_one_line_error(eval --model std --gamma 1.2)
expect_one_line_error(eval --quantity X)
expect_one_line_error(eval --count 0)
expect_one_line_error(eval --from 3)
expect_one_line_error(eval --fresnel metal)
expect_one_line_error(eval --fresnel schlick --f0 1,2)
expect_one_line_error(eval --masking none)
expect_one_line_error(eval --model sel --quantity D)
expect_one_line_error(eval --no-such-flag)
expect_one_line_error(eval --model ellipsoid --theta-y 120)

# bake: writes the file, prints the wall time and the error; bad input leaves no file.
set(out_dir "${CMAKE_CURRENT_BINARY_DIR}/cli_bake")
file(REMOVE_RECURSE "${out_dir}")
file(MAKE_DIRECTORY "${out_dir}")
run_tool(TRUE out err bake --table E --model ggx --size 8x8 -o "${out_dir}/E.exr")
if(NOT out MATCHES "baked in [0-9.]+ s, max abs error [0-9.]+e-[0-9]+" OR NOT EXISTS "${out_dir}/E.exr")
  message(FATAL_ERROR "bake E: unexpected output '${out}'")
endif()
run_tool(TRUE out err bake --table dfg --model beckmann --size 4x4 --pixel half --placement centers
         --warp roughness=square --integrator qmc --samples 256 -o "${out_dir}/dfg.exr")
run_tool(TRUE out err bake --table E_avg --model std --gamma 3 --size 4 --masking separable -o "${out_dir}/Eavg.exr")
run_tool(TRUE out err bake --table E --size 4x4 --complement --error-channel --integrator engine -o "${out_dir}/E1.exr")
expect_one_line_error(bake --table E)
expect_one_line_error(bake --table X -o "${out_dir}/bad.exr")
expect_one_line_error(bake --table E --model sel -o "${out_dir}/bad.exr")
expect_one_line_error(bake --table E --size 8 -o "${out_dir}/bad.exr")
expect_one_line_error(bake --table E --size 0x8 -o "${out_dir}/bad.exr")
expect_one_line_error(bake --table E --warp cubic -o "${out_dir}/bad.exr")
expect_one_line_error(bake --table E --pixel double -o "${out_dir}/bad.exr")
expect_one_line_error(bake --table E --size 4x4 -o "/nonexistent-dir/E.exr")
file(GLOB leftovers "${out_dir}/bad*" "${out_dir}/*.tmp*")
if(leftovers)
  message(FATAL_ERROR "bake left files behind: ${leftovers}")
endif()
message(STATUS "cli bake: all checks passed")

# eval --grid: SIMD grids to EXR, with a forced target.
run_tool(TRUE out err eval --grid slice --width 64 --height 32 --alpha 0.3 --target SSE4 -o "${out_dir}/slice.exr")
if(NOT out MATCHES "simd:SSE4" OR NOT EXISTS "${out_dir}/slice.exr")
  message(FATAL_ERROR "eval --grid --target SSE4: '${out}'")
endif()
run_tool(TRUE out err eval --grid hemisphere --model beckmann --mu-o 0.3 -o "${out_dir}/hemi.exr")
expect_one_line_error(eval --grid slice --target NEON -o "${out_dir}/bad.exr")
expect_one_line_error(eval --grid slice)
expect_one_line_error(eval --grid cube -o "${out_dir}/bad.exr")
message(STATUS "cli grid: all checks passed")

run_tool(TRUE out err stability --samples 200)
if(NOT out MATCHES "^region,model,quantity,kernel,samples,non_finite,max_rel_error,max_error_over_bound,within_bound\n"
   OR out MATCHES ",NO\n" OR NOT err MATCHES "0 non-finite outputs, 0 rows outside")
  message(FATAL_ERROR "stability: '${out}' '${err}'")
endif()
expect_one_line_error(stability --samples 0)
message(STATUS "cli stability: all checks passed")

# Reliability at the inputs that once broke it (see also tests/reliability_test.cc).
# Beyond the documented alpha bound (1e4): a one-line error, never NaN.
expect_one_line_error(eval --model ggx --alpha 1.4e154 --quantity D,Lambda,G1,G2,brdf,pdf --mu-o 0.5
                      --from 0.5 --to 0.5 --count 1)
expect_one_line_error(eval --model std --gamma 3 --alpha 1.4e154 --quantity pdf)
expect_one_line_error(eval --model sel --alpha-x 1 --alpha-y 1e154 --quantity K)
expect_one_line_error(eval --grid hemisphere --model ggx --alpha 2e19 -o "${out_dir}/bad.exr")
expect_one_line_error(eval --grid slice --model ellipsoid --alpha 1e39 -o "${out_dir}/bad.exr")
# At the bound: finite.
run_tool(TRUE out err eval --model ggx --alpha 1e4 --quantity D,Lambda,G1,G2,brdf,pdf --mu-o 0.5
         --from 0.01 --to 1 --count 11)
if(out MATCHES "nan|inf")
  message(FATAL_ERROR "eval at alpha 1e4: non-finite output: ${out}")
endif()
# gamma = 1.7e308 (beyond 2^1023): the Beckmann limit, E <= 1, an honest claim.
run_tool(TRUE out err bake --table E --model std --gamma 1.7e308 --size 6x6 -o "${out_dir}/E_huge_gamma.exr")
if(NOT out MATCHES "max abs error [0-9.]+e-0[6-9]")
  message(FATAL_ERROR "bake std gamma 1.7e308: '${out}'")
endif()
run_tool(TRUE out err eval --model std --gamma 8.98846567431158e307 --quantity Lambda,G2 --mu-o 0.5
         --from 0.5 --to 0.5 --count 1 --alpha 0.25)
run_tool(TRUE ref err eval --model beckmann --quantity Lambda,G2 --mu-o 0.5 --from 0.5 --to 0.5
         --count 1 --alpha 0.25)
if(NOT out STREQUAL ref)
  message(FATAL_ERROR "std at gamma 2^1023 is not Beckmann: '${out}' vs '${ref}'")
endif()
# --range: the axes recorded, the values at the clamped mu.
run_tool(TRUE out err bake --table E --size 4x4 --range mu=1e-4:1,roughness=0.1:0.9 --placement centers
         -o "${out_dir}/E_range.exr")
# report: a taken name is found before the work, and nothing is written.
file(MAKE_DIRECTORY "${out_dir}/report_taken/report.csv")
expect_one_line_error(report --table E --size 4x4 -o "${out_dir}/report_taken")
file(GLOB report_files "${out_dir}/report_taken/*")
list(LENGTH report_files n_report)
if(NOT n_report EQUAL 1)
  message(FATAL_ERROR "report wrote files before failing: ${report_files}")
endif()
# Sizes and warps of the wrong shape for the table.
expect_one_line_error(bake --table E_avg --size 16x64 -o "${out_dir}/bad.exr")
expect_one_line_error(bake --table E --size 8x8x8 -o "${out_dir}/bad.exr")
expect_one_line_error(bake --table E --warp mu=square,mu=sqrt -o "${out_dir}/bad.exr")
expect_one_line_error(bake --table dfg -o "${out_dir}/dfg.png")
file(GLOB leftovers "${out_dir}/bad*" "${out_dir}/dfg.png" "${out_dir}/.brdfbake-*")
if(leftovers)
  message(FATAL_ERROR "files left behind: ${leftovers}")
endif()
message(STATUS "cli reliability: all checks passed")

# Engine presets from the command line: each bakes into its directory with
# the files the engine loads (the layouts are checked in tests/engine_test.cc).
foreach(preset filament unreal hdrp godot bevy three cycles materialx enterprise-pbr)
  run_tool(TRUE out err bake --preset ${preset} -o "${out_dir}/preset_${preset}" --shader glsl)
  if(NOT out MATCHES "wrote ")
    message(FATAL_ERROR "bake --preset ${preset}: '${out}'")
  endif()
endforeach()
foreach(f preset_filament/dfg.h preset_unreal/PreIntegratedGF.dds preset_hdrp/preintegrated_fgd.exr
          preset_godot/dfg_lut.exr preset_bevy/dfg.ktx2 preset_three/DFGLUTData.js preset_cycles/ggx_tables.h
          preset_materialx/albedo_table.exr preset_enterprise-pbr/pbrlut.hpp preset_enterprise-pbr/GGX_E.exr
          preset_enterprise-pbr/GGX_E_avg.exr preset_three/DFGLUTData.glsl)
  if(NOT EXISTS "${out_dir}/${f}")
    message(FATAL_ERROR "preset output missing: ${f}")
  endif()
endforeach()
# A preset fixes its tables; other presets and formats are named in the error.
expect_one_line_error(bake --preset filament --size 64x64)
expect_one_line_error(bake --preset unity)
expect_one_line_error(bake --preset three --shader metal -o "${out_dir}/bad_preset")
# Containers chosen by the extension or by --format, with a shader beside.
run_tool(TRUE out err bake --table dfg --size 8x8 --pixel half -o "${out_dir}/dfg8.ktx2" --shader hlsl)
run_tool(TRUE out err bake --table E --size 8x8 --format header -o "${out_dir}/E8.h")
run_tool(TRUE out err bake --table dfg --size 8x8 --pixel unorm16 -o "${out_dir}/dfg8.dds")
run_tool(TRUE out err bake --table E_avg --size 8 -o "${out_dir}/Eavg8.js" --shader wgsl)
foreach(f dfg8.ktx2 dfg8.hlsl E8.h dfg8.dds Eavg8.js Eavg8.wgsl)
  if(NOT EXISTS "${out_dir}/${f}")
    message(FATAL_ERROR "container output missing: ${f}")
  endif()
endforeach()
message(STATUS "cli presets and containers: all checks passed")
