file(REMOVE_RECURSE
  "CMakeFiles/brdfbake_bench.dir/bench/bench.cc.o"
  "CMakeFiles/brdfbake_bench.dir/bench/bench.cc.o.d"
  "bin/brdfbake_bench"
  "bin/brdfbake_bench.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/brdfbake_bench.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
