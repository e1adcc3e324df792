# LAMMPS dump reader (analysis/io/dump_reader): unit tests, the reader against a real
# LAMMPS run, the benchmark driver of bench/dump_read.sh, and the fuzz tests of the
# readers (tests/fuzz). Included from CMakeLists.txt.
add_executable(test_dump_reader test_dump_reader.cpp)
target_include_directories(test_dump_reader PRIVATE ${PROJECT_SOURCE_DIR}/tests/fuzz)    # fuzz_bodies.h
target_link_libraries(test_dump_reader PRIVATE granpen_analysis ZLIB::ZLIB GTest::gtest_main)
target_compile_definitions(test_dump_reader PRIVATE GRANPEN_FUZZ_DIR="${PROJECT_SOURCE_DIR}/tests/fuzz")
gtest_discover_tests(test_dump_reader TEST_FILTER "-DumpLammps.*" PROPERTIES LABELS unit)

# dumps of a small deck (3 frames of 384 grains: plain %.17g, gzip with shuffled and
# scaled columns, LAMMPS's default %g) and LAMMPS's own sums and values, read back
if(GRANPEN_HAVE_LMP)
  set(GRANPEN_DUMP_DIR ${CMAKE_CURRENT_BINARY_DIR}/dump_lammps)
  file(MAKE_DIRECTORY ${GRANPEN_DUMP_DIR})
  add_test(NAME dump_lammps_run COMMAND $<TARGET_FILE:lmp_granpen> -in ${CMAKE_CURRENT_SOURCE_DIR}/dump_small.lmp
    -var dir ${GRANPEN_DUMP_DIR} -log ${GRANPEN_DUMP_DIR}/log.lammps)
  set_tests_properties(dump_lammps_run PROPERTIES LABELS "unit;lammps" FIXTURES_SETUP dump_lammps TIMEOUT 120
    ENVIRONMENT "OMP_NUM_THREADS=1;OMPI_ALLOW_RUN_AS_ROOT=1;OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1"
    PASS_REGULAR_EXPRESSION "granpen dump_small: done")
  add_test(NAME dump_reader_lammps COMMAND test_dump_reader --gtest_filter=DumpLammps.*)
  set_tests_properties(dump_reader_lammps PROPERTIES LABELS "unit;lammps" FIXTURES_REQUIRED dump_lammps
    ENVIRONMENT "GRANPEN_DUMP_LAMMPS_DIR=${GRANPEN_DUMP_DIR}" PASS_REGULAR_EXPRESSION "\\[  PASSED  \\] 1 test")
endif()

# bench/dump_read.sh's driver
add_executable(dump_read_bench ${PROJECT_SOURCE_DIR}/bench/dump_read_bench.cpp)
target_link_libraries(dump_read_bench PRIVATE granpen_analysis)
# bench/voronoi_frame.sh's driver (analysis/core/voronoi_volumes against compute voronoi/atom)
add_executable(voronoi_frame_bench ${PROJECT_SOURCE_DIR}/bench/voronoi_frame_bench.cpp)
target_link_libraries(voronoi_frame_bench PRIVATE granpen_analysis)

include(${PROJECT_SOURCE_DIR}/tests/fuzz/fuzz_tests.cmake)
