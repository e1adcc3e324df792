# ratio.gp, written by granpen. The data are in ratio.dat beside it.
# granpen plot ratio: the binned F/F_z curves of granpen collapse (bins of t~ of width 0.25, z >= 0.2 cm), against z (bin centre t~ converted back to z)
# and against t~; the band 1 +- 0.2; k_z from alpha = 31.37.
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
  set multiplot title "F over its depth term F_z: t̃* = 1.1 ± 0.49 (5 of 14 traces; their mean: not reached), spread 0.689 against z, 0.214 against t̃" font ",14"

  # ---- panel 1: (a) against depth
  set origin 0,0
  set size 0.38,0.94
  set title "(a) against depth"
  set xlabel "rod tip depth z (cm)"
  set ylabel "F / F_z   (F_z = α μ ρ_g g D² z)"
  set grid lc rgb "#d0d0d0"
  set logscale y
  set yrange [0.5:27.92944057]
  unset key
  set object 10 rectangle from graph 0, first 0.8 to graph 1, first 1.2 behind fillcolor rgb "#808080" fillstyle transparent solid 0.18 noborder
  set ytics ("0.5" 0.5, "1" 1, "2" 2, "5" 5, "10" 10, "20" 20)
  set mytics 10
  set autoscale xfix
  set samples 400
  plot data index 0 using 1:2 with lines lw 1.8 dt 1 lc rgb "#144d75" notitle, \
       data index 1 using 1:2 with lines lw 1.8 dt 1 lc rgb "#84b4d6" notitle, \
       data index 2 using 1:2 with lines lw 1.8 dt 1 lc rgb "#8b191a" notitle, \
       data index 3 using 1:2 with lines lw 1.8 dt 1 lc rgb "#e88889" notitle, \
       data index 4 using 1:2 with lines lw 1.8 dt 1 lc rgb "#1d681d" notitle, \
       data index 5 using 1:2 with lines lw 1.8 dt 1 lc rgb "#227a22" notitle, \
       data index 6 using 1:2 with lines lw 1.8 dt 1 lc rgb "#278d27" notitle, \
       data index 7 using 1:2 with lines lw 1.8 dt 1 lc rgb "#2c9f2c" notitle, \
       data index 8 using 1:2 with lines lw 1.8 dt 1 lc rgb "#43aa43" notitle, \
       data index 9 using 1:2 with lines lw 1.8 dt 1 lc rgb "#5bb55b" notitle, \
       data index 10 using 1:2 with lines lw 1.8 dt 1 lc rgb "#73c073" notitle, \
       data index 11 using 1:2 with lines lw 1.8 dt 1 lc rgb "#8bcb8b" notitle, \
       data index 12 using 1:2 with lines lw 1.8 dt 1 lc rgb "#a65309" notitle, \
       data index 13 using 1:2 with lines lw 1.8 dt 1 lc rgb "#ffb97a" notitle

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
  set yrange [0.5:27.92944057]
  set key at screen 0.77, screen 0.9 left top Left reverse
  set key spacing 1.25
  set object 10 rectangle from graph 0, first 0.8 to graph 1, first 1.2 behind fillcolor rgb "#808080" fillstyle transparent solid 0.18 noborder
  set arrow 1 from first 1, graph 0 to first 1, graph 1 nohead lw 1.5 dt 3 lc rgb "#404040"
  set label 1 "t̃ = 1 (paper)" at first 1, graph 0.96 left offset char 0.4,0 textcolor rgb "#404040"
  set ytics ("0.5" 0.5, "1" 1, "2" 2, "5" 5, "10" 10, "20" 20)
  set mytics 10
  set samples 400
  plot data index 28 using 1:3:4 with filledcurves fillcolor rgb "#000000" fillstyle transparent solid 0.22 noborder notitle, \
       keyentry with filledcurves fillcolor rgb "#808080" fillstyle transparent solid 0.36 noborder title "1 ± 0.2", \
       data index 14 using 1:2 with lines lw 1.8 dt 1 lc rgb "#144d75" title "v_0 = 30 cm/s (2 runs)", \
       data index 15 using 1:2 with lines lw 1.8 dt 1 lc rgb "#84b4d6" notitle, \
       data index 16 using 1:2 with lines lw 1.8 dt 1 lc rgb "#8b191a" title "v_0 = 60 cm/s (2 runs)", \
       data index 17 using 1:2 with lines lw 1.8 dt 1 lc rgb "#e88889" notitle, \
       data index 18 using 1:2 with lines lw 1.8 dt 1 lc rgb "#1d681d" title "v_0 = 90 cm/s (8 runs)", \
       data index 19 using 1:2 with lines lw 1.8 dt 1 lc rgb "#227a22" notitle, \
       data index 20 using 1:2 with lines lw 1.8 dt 1 lc rgb "#278d27" notitle, \
       data index 21 using 1:2 with lines lw 1.8 dt 1 lc rgb "#2c9f2c" notitle, \
       data index 22 using 1:2 with lines lw 1.8 dt 1 lc rgb "#43aa43" notitle, \
       data index 23 using 1:2 with lines lw 1.8 dt 1 lc rgb "#5bb55b" notitle, \
       data index 24 using 1:2 with lines lw 1.8 dt 1 lc rgb "#73c073" notitle, \
       data index 25 using 1:2 with lines lw 1.8 dt 1 lc rgb "#8bcb8b" notitle, \
       data index 26 using 1:2 with lines lw 1.8 dt 1 lc rgb "#a65309" title "v_0 = 240 cm/s (2 runs)", \
       data index 27 using 1:2 with lines lw 1.8 dt 1 lc rgb "#ffb97a" notitle, \
       data index 28 using 1:2 with lines lw 3 dt 1 lc rgb "#000000" title "mean of the runs ± se"
  unset multiplot
  unset multiplot
  set output
}
