# flow_annulus.gp, written by granpen. The data are in flow_annulus.dat beside it.
# granpen plot flow: means over the annulus (data/sims/dg10/dg10_flow/dg10_mu0.3_s1_v200_g981_D2.0.flow/surface/flow_annulus.csv) against t~ = (z/v0) sqrt(g/D).
# Run in this folder: `gnuplot flow_annulus.gp` makes flow_annulus.png and flow_annulus.svg;
# `gnuplot -e "formats='png'" flow_annulus.gp` makes only the PNG.
if (!exists("formats")) formats = "png svg"
data = "flow_annulus.dat"
do for [fmt in formats] {
  if (fmt eq "png") {
    set terminal pngcairo enhanced size 1500,520 font "sans,12" background rgb "white"
  } else {
    if (fmt ne "svg") { print "unknown format ", fmt, " (png or svg)"; exit status 1 }
    set terminal svg enhanced size 1500,520 font "sans,12" background rgb "white"
  }
  set output "flow_annulus." . fmt
  reset
  set encoding utf8
  set multiplot title "Annulus r = 2–3 cm about the rod, against rescaled time" font ",14"

  # ---- panel 1: (a) packing fraction φ
  set origin 0,0
  set size 0.3333333333,0.94
  set title "(a) packing fraction φ"
  set xlabel "t̃ = (z / v_0) √(g / D)"
  set ylabel "φ"
  set grid lc rgb "#d0d0d0"
  unset key
  set arrow 1 from first 1, graph 0 to first 1, graph 1 nohead lw 1.5 dt 3 lc rgb "#404040"
  set label 1 "t̃ = 1" at first 1, graph 0.96 left offset char 0.4,0 textcolor rgb "#404040"
  set samples 400
  plot data index 0 using 1:2 with linespoints lw 2 dt 1 lc rgb "#1f77b4" pt 7 ps 0.8 notitle

  # ---- panel 2: (b) vertical velocity v_z
  reset
  set encoding utf8
  set origin 0.3333333333,0
  set size 0.3333333333,0.94
  set title "(b) vertical velocity v_z"
  set xlabel "t̃ = (z / v_0) √(g / D)"
  set ylabel "v_z (cm/s; > 0 up)"
  set grid lc rgb "#d0d0d0"
  unset key
  set arrow 1 from first 1, graph 0 to first 1, graph 1 nohead lw 1.5 dt 3 lc rgb "#404040"
  set label 1 "t̃ = 1" at first 1, graph 0.96 left offset char 0.4,0 textcolor rgb "#404040"
  set xzeroaxis lt 1 lw 1 lc rgb "#606060"
  set samples 400
  plot data index 1 using 1:2 with linespoints lw 2 dt 1 lc rgb "#d62728" pt 7 ps 0.8 notitle

  # ---- panel 3: (c) granular temperature T
  reset
  set encoding utf8
  set origin 0.6666666667,0
  set size 0.3333333333,0.94
  set title "(c) granular temperature T"
  set xlabel "t̃ = (z / v_0) √(g / D)"
  set ylabel "T (cm^2/s^2)"
  set grid lc rgb "#d0d0d0"
  unset key
  set arrow 1 from first 1, graph 0 to first 1, graph 1 nohead lw 1.5 dt 3 lc rgb "#404040"
  set label 1 "t̃ = 1" at first 1, graph 0.96 left offset char 0.4,0 textcolor rgb "#404040"
  set samples 400
  plot data index 2 using 1:2 with linespoints lw 2 dt 1 lc rgb "#2ca02c" pt 7 ps 0.8 notitle
  unset multiplot
  unset multiplot
  set output
}
