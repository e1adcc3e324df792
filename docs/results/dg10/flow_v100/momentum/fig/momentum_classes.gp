# momentum_classes.gp, written by granpen. The data are in momentum_classes.dat beside it.
# granpen plot momentum: the classes of data/sims/dg10/dg10_flow/dg10_mu0.3_s1_v100_g981_D2.0.flow/momentum/momentum_classes.csv against t~; log axes when a quantity spans more than two decades
# (then zero values are not drawn).
# Run in this folder: `gnuplot momentum_classes.gp` makes momentum_classes.png and momentum_classes.svg;
# `gnuplot -e "formats='png'" momentum_classes.gp` makes only the PNG.
if (!exists("formats")) formats = "png svg"
data = "momentum_classes.dat"
do for [fmt in formats] {
  if (fmt eq "png") {
    set terminal pngcairo enhanced size 1500,600 font "sans,12" background rgb "white"
  } else {
    if (fmt ne "svg") { print "unknown format ", fmt, " (png or svg)"; exit status 1 }
    set terminal svg enhanced size 1500,600 font "sans,12" background rgb "white"
  }
  set output "momentum_classes." . fmt
  reset
  set encoding utf8
  set multiplot title "Grains moving up, by vertical-speed class (r > R)" font ",14"

  # ---- panel 1: (a) upward momentum of each class
  set origin 0,0
  set size 0.37,0.94
  set title "(a) upward momentum of each class"
  set xlabel "t̃ = (z / v_0) √(g / D)"
  set ylabel "summed upward momentum Σ m v_z (g cm/s)"
  set grid lc rgb "#d0d0d0"
  set logscale y
  unset key
  set arrow 1 from first 1, graph 0 to first 1, graph 1 nohead lw 1.5 dt 3 lc rgb "#404040"
  set label 1 "t̃ = 1" at first 1, graph 0.96 left offset char 0.4,0 textcolor rgb "#404040"
  set format y "10^{%T}"
  set samples 400
  plot data index 0 using 1:2 with linespoints lw 2 dt 1 lc rgb "#d62728" pt 7 ps 0.7 notitle, \
       data index 1 using 1:2 with linespoints lw 2 dt 1 lc rgb "#ff7f0e" pt 7 ps 0.7 notitle, \
       data index 2 using 1:2 with linespoints lw 2 dt 1 lc rgb "#1f77b4" pt 7 ps 0.7 notitle, \
       data index 3 using 1:2 with linespoints lw 2 dt 1 lc rgb "#7f7f7f" pt 7 ps 0.7 notitle

  # ---- panel 2: (b) grains in each class
  reset
  set encoding utf8
  set origin 0.37,0
  set size 0.37,0.94
  set title "(b) grains in each class"
  set xlabel "t̃ = (z / v_0) √(g / D)"
  set ylabel "grains"
  set grid lc rgb "#d0d0d0"
  set logscale y
  set key at screen 0.75, screen 0.9 left top Left reverse
  set key spacing 1.25
  set arrow 1 from first 1, graph 0 to first 1, graph 1 nohead lw 1.5 dt 3 lc rgb "#404040"
  set label 1 "t̃ = 1" at first 1, graph 0.96 left offset char 0.4,0 textcolor rgb "#404040"
  set format y "10^{%T}"
  set samples 400
  plot data index 4 using 1:2 with linespoints lw 2 dt 1 lc rgb "#d62728" pt 7 ps 0.7 title "fast: v_z ≥ v_0/10", \
       data index 5 using 1:2 with linespoints lw 2 dt 1 lc rgb "#ff7f0e" pt 7 ps 0.7 title "intermediate: v_0/80 ≤ v_z < v_0/10", \
       data index 6 using 1:2 with linespoints lw 2 dt 1 lc rgb "#1f77b4" pt 7 ps 0.7 title "slow: v_0/320 < v_z < v_0/80", \
       data index 7 using 1:2 with linespoints lw 2 dt 1 lc rgb "#7f7f7f" pt 7 ps 0.7 title "noise: v_0/640 < v_z ≤ v_0/320"
  unset multiplot
  unset multiplot
  set output
}
