# Compare two dumps of the same atoms (sorted by id): every value must agree within
# rtol * (largest magnitude of its column) (awk -v rtol=1e-9 -f compare_dumps.awk A B).
# With -v expect=differ, the dumps must differ beyond rtol instead (expect=same, or unset: agree).
FNR == 1 { file++ }
/^ITEM: ATOMS/ { atoms[file] = 1; next }
atoms[file] && NF > 1 {
  row[file]++
  for (c = 1; c <= NF; c++) {
    v[file, row[file], c] = $c
    if ($c < 0 ? -$c > big[c] : $c > big[c]) big[c] = $c < 0 ? -$c : $c
  }
  nf = NF
}
END {
  if (row[1] == 0 || row[1] != row[2]) { print "compare_dumps: different atom counts: " row[1] " and " row[2]; exit 1 }
  worst = 0
  for (r = 1; r <= row[1]; r++)
    for (c = 1; c <= nf; c++) {
      d = v[1, r, c] - v[2, r, c]; if (d < 0) d = -d
      rel = big[c] > 0 ? d / big[c] : 0
      if (rel > worst) { worst = rel; wr = r; wc = c }
    }
  printf "compare_dumps: largest relative difference %.3g (atom row %d, column %d), rtol %g\n", worst, wr, wc, rtol
  if (expect == "differ") exit (worst > rtol ? 0 : 1)
  exit (worst <= rtol ? 0 : 1)
}
