file(REMOVE_RECURSE
  "CMakeFiles/brdfbake_cli.dir/tools/brdfbake.cc.o"
  "CMakeFiles/brdfbake_cli.dir/tools/brdfbake.cc.o.d"
  "bin/brdfbake"
  "bin/brdfbake.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang CXX)
  include(CMakeFiles/brdfbake_cli.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
