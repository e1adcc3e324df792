# awk -f compare_ave_time.awk A B
# Two fix ave/time mode-vector files of the same run on different decompositions: the
# same number of lines, and in the first block (early in the run, before the granular
# dynamics has grown round-off into visible differences) every value within 1e-6 relative
# (1e-6 absolute below 1). Exit 1 with the first difference.
FNR == NR { a[FNR] = $0; na = FNR
            if ($0 ~ /^[0-9]+ [0-9]+$/) { if (!start) start = FNR + 1; else if (!stop) stop = FNR - 1 }
            next }
{ b[FNR] = $0; nb = FNR }
END {
  if (na != nb || na < 10) { printf "line counts differ or too few: %d vs %d\n", na, nb; exit 1 }
  n = 0
  if (!stop) stop = na
  for (k = start; k <= stop; k++) {
    nx = split(a[k], x, " "); ny = split(b[k], y, " ")
    if (nx != ny) { printf "line %d: %d vs %d fields\n", k, nx, ny; exit 1 }
    for (c = 1; c <= nx; c++) {
      d = x[c] - y[c]; if (d < 0) d = -d
      s = x[c] < 0 ? -x[c] : x[c]; if (s < 1) s = 1
      if (d > 1e-6 * s) { printf "line %d column %d: %s vs %s\n", k, c, x[c], y[c]; exit 1 }
      n++
    }
  }
  printf "compared %d values of the first block (lines %d-%d): agree\n", n, start, stop
}
