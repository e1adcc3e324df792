# CMakeGraphVizOptions for docs/architecture/diagram.sh: the libraries and executables of
# the package and the post-processor, not the tests and tools
set(GRAPHVIZ_GRAPH_NAME "granpen")
set(GRAPHVIZ_GRAPH_HEADER "node [fontname=Helvetica, fontsize=11]; rankdir=BT; ranksep=0.45; nodesep=0.25;")
set(GRAPHVIZ_GENERATE_PER_TARGET FALSE)
set(GRAPHVIZ_GENERATE_DEPENDERS FALSE)
set(GRAPHVIZ_CUSTOM_TARGETS FALSE)
set(GRAPHVIZ_IGNORE_TARGETS "^test_" "^fuzz_" "^GTest" "gtest" "^granpen_test_main$" "^lammps_agree$"
  "^trace_agree$" "^fake_lmp$" "_bench$" "^granpen_analysis$" "^MPI::" "^Threads::" "^dl$" "^-" "^/")
