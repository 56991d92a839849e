file(REMOVE_RECURSE
  "CMakeFiles/brdfbake.dir/src/azimuthal.cc.o"
  "CMakeFiles/brdfbake.dir/src/azimuthal.cc.o.d"
  "CMakeFiles/brdfbake.dir/src/bake.cc.o"
  "CMakeFiles/brdfbake.dir/src/bake.cc.o.d"
  "CMakeFiles/brdfbake.dir/src/batch_beckmann_std.cc.o"
  "CMakeFiles/brdfbake.dir/src/batch_beckmann_std.cc.o.d"
  "CMakeFiles/brdfbake.dir/src/batch_extra.cc.o"
  "CMakeFiles/brdfbake.dir/src/batch_extra.cc.o.d"
  "CMakeFiles/brdfbake.dir/src/batch_ggx.cc.o"
  "CMakeFiles/brdfbake.dir/src/batch_ggx.cc.o.d"
  "CMakeFiles/brdfbake.dir/src/batch_sampling.cc.o"
  "CMakeFiles/brdfbake.dir/src/batch_sampling.cc.o.d"
  "CMakeFiles/brdfbake.dir/src/eval.cc.o"
  "CMakeFiles/brdfbake.dir/src/eval.cc.o.d"
  "CMakeFiles/brdfbake.dir/src/exr.cc.o"
  "CMakeFiles/brdfbake.dir/src/exr.cc.o.d"
  "CMakeFiles/brdfbake.dir/src/grid.cc.o"
  "CMakeFiles/brdfbake.dir/src/grid.cc.o.d"
  "CMakeFiles/brdfbake.dir/src/model.cc.o"
  "CMakeFiles/brdfbake.dir/src/model.cc.o.d"
  "CMakeFiles/brdfbake.dir/src/report.cc.o"
  "CMakeFiles/brdfbake.dir/src/report.cc.o.d"
  "CMakeFiles/brdfbake.dir/src/stability.cc.o"
  "CMakeFiles/brdfbake.dir/src/stability.cc.o.d"
  "CMakeFiles/brdfbake.dir/src/targets.cc.o"
  "CMakeFiles/brdfbake.dir/src/targets.cc.o.d"
  "libbrdfbake.a"
  "libbrdfbake.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/brdfbake.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
