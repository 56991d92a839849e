# CMake generated Testfile for 
# Source directory: /work/main
# Build directory: /work/main/build-helper
# 
# This file includes the relevant testing commands required for 
# testing this directory and lists subdirectories to be tested as well.
include("/work/main/build-helper/brdfbake_tests[1]_include.cmake")
add_test([=[cli]=] "/usr/bin/cmake" "-DBRDFBAKE=/work/main/build-helper/bin/brdfbake" "-P" "/work/main/tests/cli_test.cmake")
set_tests_properties([=[cli]=] PROPERTIES  _BACKTRACE_TRIPLES "/work/main/CMakeLists.txt;82;add_test;/work/main/CMakeLists.txt;0;")
