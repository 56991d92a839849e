# Empty compiler generated dependencies file for brdfbake_bench.
# This may be replaced when dependencies are built.
