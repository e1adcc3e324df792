# code_lines.sh: sourced by the architecture checks that read C++ code line by line
# (io_reads_writes.sh, scaling_once.sh, cli_vs_core.sh), so that they agree on what code is.
#   code_lines ROOT EXCLUDE DIR...
# prints "FILE:LINE: CODE" for every line of code of the .cpp and .h files under ROOT/DIR
# (each DIR that exists), sorted by file: comments (// and /* */, also over lines) and the
# text of string literals blanked, blank lines left out; FILE relative to ROOT. A file whose
# path matches the extended regular expression EXCLUDE is left out ("" excludes none).
# Needs only sh, find, sort, grep and awk.
code_lines() {
  cl_root=$1 cl_exclude=$2
  shift 2
  for cl_dir in "$@"; do [ -d "$cl_root/$cl_dir" ] && find "$cl_root/$cl_dir" \( -name '*.cpp' -o -name '*.h' \); done |
    { if [ -n "$cl_exclude" ]; then grep -v -E "$cl_exclude"; else cat; fi; } | sort | while read -r f; do
      awk -v name="${f#"$cl_root"/}" '
        { l = $0
          if (inc) { if (l ~ /\*\//) { sub(/.*\*\//, "", l); inc = 0 } else next }
          gsub(/"([^"\\]|\\.)*"/, "\"\"", l)
          while (l ~ /\/\*/) { if (l ~ /\/\*.*\*\//) sub(/\/\*([^*]|\*+[^*\/])*\*+\//, "", l); else { sub(/\/\*.*/, "", l); inc = 1 } }
          sub(/\/\/.*/, "", l)
          if (l ~ /[^ \t]/) print name ":" FNR ": " l }' "$f"
    done
}
