# granpen plot and the figure library (io/plot_writer.h): unit tests on synthetic
# traces and tables, the command run in-process (its sources compiled in). Included
# from tests/unit/CMakeLists.txt.
add_executable(test_plot test_plot.cpp ${PROJECT_SOURCE_DIR}/analysis/cli/plot_cmd.cpp
  ${PROJECT_SOURCE_DIR}/analysis/cli/args.cpp
  ${PROJECT_SOURCE_DIR}/analysis/cli/ensemble_args.cpp
  ${PROJECT_SOURCE_DIR}/analysis/cli/subcommand.cpp)
target_include_directories(test_plot PRIVATE ${PROJECT_SOURCE_DIR}/analysis/cli)
target_link_libraries(test_plot PRIVATE granpen_analysis CLI11::CLI11 GTest::gtest_main)
target_compile_definitions(test_plot PRIVATE GRANPEN_PLOT_TEST_DIR="${CMAKE_CURRENT_BINARY_DIR}/plot_test"
  GRANPEN_BENCH_TRACES="${PROJECT_SOURCE_DIR}/data/sims/v0_bench")
gtest_discover_tests(test_plot PROPERTIES LABELS unit)

# the front end on the committed bench sweep, scripts and data only (no gnuplot needed)
add_test(NAME cli_plot_bench_peak_scripts COMMAND granpen-cli plot peak ${PROJECT_SOURCE_DIR}/data/sims/v0_bench
  --out ${CMAKE_CURRENT_BINARY_DIR}/plot_cli --no-run)
set_tests_properties(cli_plot_bench_peak_scripts PROPERTIES LABELS "unit;cli"
  PASS_REGULAR_EXPRESSION "wrote [^\n]*peak\\.gp and [^\n]*peak\\.dat \\(not run: --no-run\\)")
