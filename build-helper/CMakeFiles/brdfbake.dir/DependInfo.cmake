
# Consider dependencies only in project.
set(CMAKE_DEPENDS_IN_PROJECT_ONLY OFF)

# The set of languages for which implicit dependencies are needed:
set(CMAKE_DEPENDS_LANGUAGES
  )

# The set of dependency files which are needed:
set(CMAKE_DEPENDS_DEPENDENCY_FILES
  "/work/main/src/azimuthal.cc" "CMakeFiles/brdfbake.dir/src/azimuthal.cc.o" "gcc" "CMakeFiles/brdfbake.dir/src/azimuthal.cc.o.d"
  "/work/main/src/bake.cc" "CMakeFiles/brdfbake.dir/src/bake.cc.o" "gcc" "CMakeFiles/brdfbake.dir/src/bake.cc.o.d"
  "/work/main/src/batch_beckmann_std.cc" "CMakeFiles/brdfbake.dir/src/batch_beckmann_std.cc.o" "gcc" "CMakeFiles/brdfbake.dir/src/batch_beckmann_std.cc.o.d"
  "/work/main/src/batch_extra.cc" "CMakeFiles/brdfbake.dir/src/batch_extra.cc.o" "gcc" "CMakeFiles/brdfbake.dir/src/batch_extra.cc.o.d"
  "/work/main/src/batch_ggx.cc" "CMakeFiles/brdfbake.dir/src/batch_ggx.cc.o" "gcc" "CMakeFiles/brdfbake.dir/src/batch_ggx.cc.o.d"
  "/work/main/src/batch_sampling.cc" "CMakeFiles/brdfbake.dir/src/batch_sampling.cc.o" "gcc" "CMakeFiles/brdfbake.dir/src/batch_sampling.cc.o.d"
  "/work/main/src/eval.cc" "CMakeFiles/brdfbake.dir/src/eval.cc.o" "gcc" "CMakeFiles/brdfbake.dir/src/eval.cc.o.d"
  "/work/main/src/exr.cc" "CMakeFiles/brdfbake.dir/src/exr.cc.o" "gcc" "CMakeFiles/brdfbake.dir/src/exr.cc.o.d"
  "/work/main/src/grid.cc" "CMakeFiles/brdfbake.dir/src/grid.cc.o" "gcc" "CMakeFiles/brdfbake.dir/src/grid.cc.o.d"
  "/work/main/src/model.cc" "CMakeFiles/brdfbake.dir/src/model.cc.o" "gcc" "CMakeFiles/brdfbake.dir/src/model.cc.o.d"
  "/work/main/src/report.cc" "CMakeFiles/brdfbake.dir/src/report.cc.o" "gcc" "CMakeFiles/brdfbake.dir/src/report.cc.o.d"
  "/work/main/src/stability.cc" "CMakeFiles/brdfbake.dir/src/stability.cc.o" "gcc" "CMakeFiles/brdfbake.dir/src/stability.cc.o.d"
  "/work/main/src/targets.cc" "CMakeFiles/brdfbake.dir/src/targets.cc.o" "gcc" "CMakeFiles/brdfbake.dir/src/targets.cc.o.d"
  )

# Targets to which this target links.
set(CMAKE_TARGET_LINKED_INFO_FILES
  )

# Fortran module output directory.
set(CMAKE_Fortran_TARGET_MODULE_DIR "")
