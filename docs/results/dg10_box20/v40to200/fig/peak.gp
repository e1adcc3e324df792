# peak.gp, written by granpen. The data are in peak.dat beside it.
# granpen plot peak: the transient peak (max F over 0 < z < 0.7 R) of each trace against v0, log-log;
# the power law fitted by granpen collapse (least squares of ln F_peak on ln v0) and a v0^2 guide.
# Run in this folder: `gnuplot peak.gp` makes peak.png and peak.svg;
# `gnuplot -e "formats='png'" peak.gp` makes only the PNG.
if (!exists("formats")) formats = "png svg"
data = "peak.dat"
do for [fmt in formats] {
  if (fmt eq "png") {
    set terminal pngcairo enhanced size 1050,650 font "sans,12" background rgb "white"
  } else {
    if (fmt ne "svg") { print "unknown format ", fmt, " (png or svg)"; exit status 1 }
    set terminal svg enhanced size 1050,650 font "sans,12" background rgb "white"
  }
  set output "peak." . fmt
  reset
  set encoding utf8
  set multiplot title "Transient peak against speed: exponent 1.61 ± 0.14 (95%; paper: 2)" font ",14"

  # ---- panel 1
  set origin 0,0
  set size 1,0.94
  set xlabel "rod speed v_0 (cm/s)"
  set ylabel "peak force F_{peak} (dyne), max over 0 < z < 0.7 R"
  set grid lc rgb "#d0d0d0"
  set logscale x
  set logscale y
  set xrange [29.62962963:270]
  set yrange [83276.41992:8227252.438]
  set key outside right top Left reverse
  set key spacing 1.25
  set xtics (40, 80, 140, 200)
  set mxtics 10
  set ytics ("10^{5}" 100000, "2×10^{5}" 200000, "5×10^{5}" 500000, "10^{6}" 1000000, "2×10^{6}" 2000000, "5×10^{6}" 5000000)
  set mytics 10
  set samples 400
  plot data index 0 using 1:2 with points pt 7 ps 1.6 lc rgb "#1f77b4" title "v_0 = 40 cm/s (3 runs)", \
       data index 1 using 1:2 with points pt 7 ps 1.6 lc rgb "#d62728" title "v_0 = 80 cm/s (3 runs)", \
       data index 2 using 1:2 with points pt 7 ps 1.6 lc rgb "#2ca02c" title "v_0 = 140 cm/s (3 runs)", \
       data index 3 using 1:2 with points pt 7 ps 1.6 lc rgb "#ff7f0e" title "v_0 = 200 cm/s (3 runs)", \
       595.2915347*x**1.609519257 with lines lw 2 dt 1 lc rgb "#000000" title "fit: F_{peak} ∝ v_0^{1.61 ± 0.14} (95%)", \
       99.63775217*x**2 with lines lw 1.5 dt 2 lc rgb "#808080" title "∝ v_0^2 guide (paper)"
  unset multiplot
  unset multiplot
  set output
}
