#!/usr/bin/env bash
# The fuzz tests' driver (ctest label `fuzz`, tests/fuzz/fuzz_tests.cmake).
#   run_fuzz.sh build SRC_DIR BUILD_DIR CLANGXX     configure and build the fuzzers with clang++
#   run_fuzz.sh run SRC_DIR BUILD_DIR TARGET SECONDS  run fuzz_TARGET from the committed corpus
#   run_fuzz.sh run SRC_DIR BUILD_DIR TARGET runs:N   the same for a fixed number of inputs
# Exit 77 (ctest: skipped) with a message when clang++ or libFuzzer is not there.
set -uo pipefail
mode=$1 src=$2 bin=$3
skip() { echo "fuzz tests skipped: $*"; exit 77; }

case "$mode" in
  build)
    cxx=${4:-}
    [ -n "$cxx" ] && command -v "$cxx" >/dev/null 2>&1 \
      || skip "no clang++ found (install clang and libclang-rt-dev for libFuzzer; CMake option GRANPEN_FUZZ)"
    mkdir -p "$bin"
    # libFuzzer's runtime is a separate package from clang itself
    printf '#include <cstdint>\n#include <cstddef>\nextern "C" int LLVMFuzzerTestOneInput(const uint8_t *, size_t) { return 0; }\n' \
      > "$bin/probe.cpp"
    "$cxx" -fsanitize=fuzzer,address,undefined "$bin/probe.cpp" -o "$bin/probe" >"$bin/probe.log" 2>&1 \
      || { cat "$bin/probe.log"; skip "$cxx cannot link -fsanitize=fuzzer (libFuzzer runtime missing: libclang-rt-dev)"; }
    cmake -S "$src" -B "$bin" -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_BUILD_TYPE=RelWithDebInfo >"$bin/configure.log" 2>&1 \
      || { cat "$bin/configure.log"; echo "fuzz: configure failed"; exit 1; }
    cmake --build "$bin" -j 2 || { echo "fuzz: build failed"; exit 1; }
    echo "fuzz: built $bin/fuzz_dump_reader $bin/fuzz_trace_reader $bin/fuzz_instrument_reader $bin/fuzz_cli_options with $cxx"
    ;;
  run)
    target=$4 budget=$5
    kind=${target%_reader} kind=${kind%_options}    # dump_reader -> dump, cli_options -> cli
    case "$budget" in
      runs:*) limit=(-runs="${budget#runs:}") ;;
      *) limit=(-max_total_time="$budget") ;;
    esac
    exe="$bin/fuzz_$target"
    [ -x "$exe" ] || skip "$exe was not built (see the fuzz_build test)"
    work="$bin/corpus/$kind" art="$bin/artifacts"
    mkdir -p "$work" "$art"
    dict=()
    [ -f "$src/$kind.dict" ] && dict=(-dict="$src/$kind.dict")
    # new inputs go to the first corpus directory (the build's), never into the source tree
    log="$bin/fuzz_$target.log"
    "$exe" "$work" "$src/corpus/$kind" "${dict[@]}" "${limit[@]}" -timeout=10 -rss_limit_mb=2048 \
      -max_len=16384 -print_final_stats=1 -artifact_prefix="$art/$target-" >"$log" 2>&1
    rc=$?
    grep -E '^INFO: seed|^INFO: +[0-9]+ files found|INITED|^Done|^stat::(number_of_executed_units|average_exec_per_sec|new_units_added|peak_rss_mb)' "$log"
    if [ "$rc" != 0 ]; then
      tail -60 "$log"
      echo "fuzz_$target found a failure (exit $rc): the input is in $art/$target-*."
      echo "Copy it into $src/regressions/$kind/ (the unit tests FuzzRegressions.* and CliOptionsFuzz.* replay it) and fix the code."
      exit 1
    fi
    ;;
  *) echo "usage: $0 build|run ..."; exit 2 ;;
esac
