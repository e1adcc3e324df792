# Fuzz tests of the readers and the CLI's option parsers (ctest label `fuzz`): fuzz_build
# configures and builds tests/fuzz with clang++ (-fsanitize=fuzzer,address,undefined) into
# build/fuzz; then fuzz_dump_reader and fuzz_trace_reader each run GRANPEN_FUZZ_SECONDS
# from the committed corpus, and fuzz_cli_options a fixed GRANPEN_FUZZ_CLI_RUNS inputs. Without clang++ or libFuzzer they are skipped (ctest "Skipped",
# with the reason in the output), not failed. Included from tests/CMakeLists.txt.
set(GRANPEN_FUZZ AUTO CACHE STRING "Fuzz tests of the readers with clang++/libFuzzer: AUTO (when clang++ is found), ON (required), OFF")
set_property(CACHE GRANPEN_FUZZ PROPERTY STRINGS AUTO ON OFF)
set(GRANPEN_FUZZ_SECONDS 30 CACHE STRING "Seconds each reader fuzz test runs")
set(GRANPEN_FUZZ_CLI_RUNS 50000 CACHE STRING "Inputs the CLI option-parser fuzz test runs")

if(NOT GRANPEN_FUZZ STREQUAL "OFF")
  if(CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    set(GRANPEN_FUZZ_CLANGXX ${CMAKE_CXX_COMPILER} CACHE FILEPATH "clang++ for the fuzz targets")
  else()
    find_program(GRANPEN_FUZZ_CLANGXX NAMES clang++ clang++-19 clang++-18 clang++-17 clang++-16 clang++-15 clang++-14
      DOC "clang++ for the fuzz targets")
  endif()
  if(NOT GRANPEN_FUZZ_CLANGXX)
    if(GRANPEN_FUZZ STREQUAL "ON")
      message(FATAL_ERROR "GRANPEN_FUZZ=ON but no clang++ found (set GRANPEN_FUZZ_CLANGXX)")
    endif()
    message(STATUS "granpen: no clang++, the fuzz tests will report themselves skipped")
    set(fuzz_cxx "")
  else()
    message(STATUS "granpen: fuzz tests with ${GRANPEN_FUZZ_CLANGXX}")
    set(fuzz_cxx ${GRANPEN_FUZZ_CLANGXX})
  endif()
  set(fuzz_src ${CMAKE_CURRENT_LIST_DIR})
  set(fuzz_bin ${CMAKE_BINARY_DIR}/fuzz)
  add_test(NAME fuzz_build COMMAND ${fuzz_src}/run_fuzz.sh build ${fuzz_src} ${fuzz_bin} "${fuzz_cxx}")
  set_tests_properties(fuzz_build PROPERTIES LABELS fuzz FIXTURES_SETUP fuzz_binaries SKIP_RETURN_CODE 77
    TIMEOUT 600 PROCESSORS 2)
  foreach(target dump_reader trace_reader instrument_reader)
    add_test(NAME fuzz_${target} COMMAND ${fuzz_src}/run_fuzz.sh run ${fuzz_src} ${fuzz_bin} ${target} ${GRANPEN_FUZZ_SECONDS})
    math(EXPR fuzz_timeout "${GRANPEN_FUZZ_SECONDS} + 120")
    set_tests_properties(fuzz_${target} PROPERTIES LABELS fuzz FIXTURES_REQUIRED fuzz_binaries SKIP_RETURN_CODE 77
      TIMEOUT ${fuzz_timeout})
  endforeach()
  add_test(NAME fuzz_cli_options COMMAND ${fuzz_src}/run_fuzz.sh run ${fuzz_src} ${fuzz_bin} cli_options
    runs:${GRANPEN_FUZZ_CLI_RUNS})
  set_tests_properties(fuzz_cli_options PROPERTIES LABELS fuzz FIXTURES_REQUIRED fuzz_binaries SKIP_RETURN_CODE 77
    TIMEOUT 300)
endif()
