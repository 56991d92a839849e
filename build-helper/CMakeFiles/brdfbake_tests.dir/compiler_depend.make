# Empty compiler generated dependencies file for brdfbake_tests.
# This may be replaced when dependencies are built.
