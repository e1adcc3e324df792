# ratio.gp, written by granpen. The data are in ratio.dat beside it.
# granpen plot ratio: the binned F/F_z curves of granpen collapse (bins of t~ of width 0.25, z >= 0.2 cm), against z (bin centre t~ converted back to z)
# and against t~; the band 1 +- 0.2; k_z from alpha = 33.14.
# Run in this folder: `gnuplot ratio.gp` makes ratio.png and ratio.svg;
# `gnuplot -e "formats='png'" ratio.gp` makes only the PNG.
if (!exists("formats")) formats = "png svg"
data = "ratio.dat"
do for [fmt in formats] {
  if (fmt eq "png") {
    set terminal pngcairo enhanced size 1450,620 font "sans,12" background rgb "white"
  } else {
    if (fmt ne "svg") { print "unknown format ", fmt, " (png or svg)"; exit status 1 }
    set terminal svg enhanced size 1450,620 font "sans,12" background rgb "white"
  }
  set output "ratio." . fmt
  reset
  set encoding utf8
  set multiplot title "F over its depth term F_z: t̃* = 0.5 ± 0 (2 of 4 traces; their mean: 0.75), spread 0.534 against z, 0.312 against t̃" font ",14"

  # ---- panel 1: (a) against depth
  set origin 0,0
  set size 0.38,0.94
  set title "(a) against depth"
  set xlabel "rod tip depth z (cm)"
  set ylabel "F / F_z   (F_z = α μ ρ_g g D² z)"
  set grid lc rgb "#d0d0d0"
  set logscale y
  set yrange [0.5:17.38097067]
  unset key
  set object 10 rectangle from graph 0, first 0.8 to graph 1, first 1.2 behind fillcolor rgb "#808080" fillstyle transparent solid 0.18 noborder
  set ytics ("0.5" 0.5, "1" 1, "2" 2, "5" 5, "10" 10)
  set mytics 10
  set autoscale xfix
  set samples 400
  plot data index 0 using 1:2 with lines lw 1.8 dt 1 lc rgb "#1f77b4" notitle, \
       data index 1 using 1:2 with lines lw 1.8 dt 1 lc rgb "#8b191a" notitle, \
       data index 2 using 1:2 with lines lw 1.8 dt 1 lc rgb "#e88889" notitle, \
       data index 3 using 1:2 with lines lw 1.8 dt 1 lc rgb "#2ca02c" notitle

  # ---- panel 2: (b) against rescaled time
  reset
  set encoding utf8
  set origin 0.38,0
  set size 0.38,0.94
  set title "(b) against rescaled time"
  set xlabel "t̃ = (z / v_0) √(g / D)"
  set ylabel "F / F_z   (F_z = α μ ρ_g g D² z)"
  set grid lc rgb "#d0d0d0"
  set logscale y
  set yrange [0.5:17.38097067]
  set key at screen 0.77, screen 0.9 left top Left reverse
  set key spacing 1.25
  set object 10 rectangle from graph 0, first 0.8 to graph 1, first 1.2 behind fillcolor rgb "#808080" fillstyle transparent solid 0.18 noborder
  set arrow 1 from first 1, graph 0 to first 1, graph 1 nohead lw 1.5 dt 3 lc rgb "#404040"
  set label 1 "t̃ = 1 (paper)" at first 1, graph 0.96 left offset char 0.4,0 textcolor rgb "#404040"
  set ytics ("0.5" 0.5, "1" 1, "2" 2, "5" 5, "10" 10)
  set mytics 10
  set samples 400
  plot data index 8 using 1:3:4 with filledcurves fillcolor rgb "#000000" fillstyle transparent solid 0.22 noborder notitle, \
       keyentry with filledcurves fillcolor rgb "#808080" fillstyle transparent solid 0.36 noborder title "1 ± 0.2", \
       data index 4 using 1:2 with lines lw 1.8 dt 1 lc rgb "#1f77b4" title "v_0 = 40 cm/s", \
       data index 5 using 1:2 with lines lw 1.8 dt 1 lc rgb "#8b191a" title "v_0 = 100 cm/s, D = 2 cm, seed 1", \
       data index 6 using 1:2 with lines lw 1.8 dt 1 lc rgb "#e88889" title "v_0 = 100 cm/s, D = 1 cm, seed 1", \
       data index 7 using 1:2 with lines lw 1.8 dt 1 lc rgb "#2ca02c" title "v_0 = 200 cm/s", \
       data index 8 using 1:2 with lines lw 3 dt 1 lc rgb "#000000" title "mean of the runs ± se"
  unset multiplot
  unset multiplot
  set output
}
