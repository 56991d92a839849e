
# Consider dependencies only in project.
set(CMAKE_DEPENDS_IN_PROJECT_ONLY OFF)

# The set of languages for which implicit dependencies are needed:
set(CMAKE_DEPENDS_LANGUAGES
  )

# The set of dependency files which are needed:
set(CMAKE_DEPENDS_DEPENDENCY_FILES
  "/work/main/tests/azimuthal_test.cc" "CMakeFiles/brdfbake_tests.dir/tests/azimuthal_test.cc.o" "gcc" "CMakeFiles/brdfbake_tests.dir/tests/azimuthal_test.cc.o.d"
  "/work/main/tests/bake_test.cc" "CMakeFiles/brdfbake_tests.dir/tests/bake_test.cc.o" "gcc" "CMakeFiles/brdfbake_tests.dir/tests/bake_test.cc.o.d"
  "/work/main/tests/brdf_test.cc" "CMakeFiles/brdfbake_tests.dir/tests/brdf_test.cc.o" "gcc" "CMakeFiles/brdfbake_tests.dir/tests/brdf_test.cc.o.d"
  "/work/main/tests/cancellation_test.cc" "CMakeFiles/brdfbake_tests.dir/tests/cancellation_test.cc.o" "gcc" "CMakeFiles/brdfbake_tests.dir/tests/cancellation_test.cc.o.d"
  "/work/main/tests/cli_fuzz_test.cc" "CMakeFiles/brdfbake_tests.dir/tests/cli_fuzz_test.cc.o" "gcc" "CMakeFiles/brdfbake_tests.dir/tests/cli_fuzz_test.cc.o.d"
  "/work/main/tests/ellipsoid_test.cc" "CMakeFiles/brdfbake_tests.dir/tests/ellipsoid_test.cc.o" "gcc" "CMakeFiles/brdfbake_tests.dir/tests/ellipsoid_test.cc.o.d"
  "/work/main/tests/fresnel_test.cc" "CMakeFiles/brdfbake_tests.dir/tests/fresnel_test.cc.o" "gcc" "CMakeFiles/brdfbake_tests.dir/tests/fresnel_test.cc.o.d"
  "/work/main/tests/ggx_beckmann_test.cc" "CMakeFiles/brdfbake_tests.dir/tests/ggx_beckmann_test.cc.o" "gcc" "CMakeFiles/brdfbake_tests.dir/tests/ggx_beckmann_test.cc.o.d"
  "/work/main/tests/grid_test.cc" "CMakeFiles/brdfbake_tests.dir/tests/grid_test.cc.o" "gcc" "CMakeFiles/brdfbake_tests.dir/tests/grid_test.cc.o.d"
  "/work/main/tests/model_test.cc" "CMakeFiles/brdfbake_tests.dir/tests/model_test.cc.o" "gcc" "CMakeFiles/brdfbake_tests.dir/tests/model_test.cc.o.d"
  "/work/main/tests/property_test.cc" "CMakeFiles/brdfbake_tests.dir/tests/property_test.cc.o" "gcc" "CMakeFiles/brdfbake_tests.dir/tests/property_test.cc.o.d"
  "/work/main/tests/report_test.cc" "CMakeFiles/brdfbake_tests.dir/tests/report_test.cc.o" "gcc" "CMakeFiles/brdfbake_tests.dir/tests/report_test.cc.o.d"
  "/work/main/tests/sel_test.cc" "CMakeFiles/brdfbake_tests.dir/tests/sel_test.cc.o" "gcc" "CMakeFiles/brdfbake_tests.dir/tests/sel_test.cc.o.d"
  "/work/main/tests/simd_beckmann_std_test.cc" "CMakeFiles/brdfbake_tests.dir/tests/simd_beckmann_std_test.cc.o" "gcc" "CMakeFiles/brdfbake_tests.dir/tests/simd_beckmann_std_test.cc.o.d"
  "/work/main/tests/simd_extra_test.cc" "CMakeFiles/brdfbake_tests.dir/tests/simd_extra_test.cc.o" "gcc" "CMakeFiles/brdfbake_tests.dir/tests/simd_extra_test.cc.o.d"
  "/work/main/tests/simd_ggx_test.cc" "CMakeFiles/brdfbake_tests.dir/tests/simd_ggx_test.cc.o" "gcc" "CMakeFiles/brdfbake_tests.dir/tests/simd_ggx_test.cc.o.d"
  "/work/main/tests/stability_test.cc" "CMakeFiles/brdfbake_tests.dir/tests/stability_test.cc.o" "gcc" "CMakeFiles/brdfbake_tests.dir/tests/stability_test.cc.o.d"
  "/work/main/tests/std_lambda_precision_test.cc" "CMakeFiles/brdfbake_tests.dir/tests/std_lambda_precision_test.cc.o" "gcc" "CMakeFiles/brdfbake_tests.dir/tests/std_lambda_precision_test.cc.o.d"
  "/work/main/tests/std_test.cc" "CMakeFiles/brdfbake_tests.dir/tests/std_test.cc.o" "gcc" "CMakeFiles/brdfbake_tests.dir/tests/std_test.cc.o.d"
  )

# Targets to which this target links.
set(CMAKE_TARGET_LINKED_INFO_FILES
  "/work/main/build-helper/CMakeFiles/brdfbake.dir/DependInfo.cmake"
  )

# Fortran module output directory.
set(CMAKE_Fortran_TARGET_MODULE_DIR "")
