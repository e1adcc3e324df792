# force.gp, written by granpen. The data are in force.dat beside it.
# granpen plot force: F against the tip depth z for each v0 (mean of the runs at each v0, band: their min..max), F in 10^{6} dyne;
# beside it, enlarged: the transient peak region 0 < z < 0.7 R, dots at the peaks.
# Run in this folder: `gnuplot force.gp` makes force.png and force.svg;
# `gnuplot -e "formats='png'" force.gp` makes only the PNG.
if (!exists("formats")) formats = "png svg"
data = "force.dat"
do for [fmt in formats] {
  if (fmt eq "png") {
    set terminal pngcairo enhanced size 1250,720 font "sans,12" background rgb "white"
  } else {
    if (fmt ne "svg") { print "unknown format ", fmt, " (png or svg)"; exit status 1 }
    set terminal svg enhanced size 1250,720 font "sans,12" background rgb "white"
  }
  set output "force." . fmt
  reset
  set encoding utf8
  set multiplot title "Drag force against depth" font ",14"

  # ---- panel 1
  set origin 0,0
  set size 0.64,0.94
  set xlabel "rod tip depth z below the bed surface (cm)"
  set ylabel "drag force F (10^{6} dyne)"
  set grid lc rgb "#d0d0d0"
  set key at screen 0.65, screen 0.9 left top Left reverse
  set key spacing 1.25
  set key title "lines: mean of the runs at each v_0\nbands: their range"
  set offsets 0, 0, graph 0.04, 0
  set autoscale xfix
  set object 2 rectangle from first 0, graph 0 to first 0.7, graph 1 behind fillcolor rgb "#e8e8e8" fillstyle solid 1.0 noborder
  set label 2 "z < 0.7 R" at first 0.35, graph 0.975 center textcolor rgb "#606060"
  set samples 400
  plot data index 0 using 1:3:4 with filledcurves fillcolor rgb "#1f77b4" fillstyle transparent solid 0.22 noborder notitle, \
       data index 1 using 1:3:4 with filledcurves fillcolor rgb "#d62728" fillstyle transparent solid 0.22 noborder notitle, \
       data index 2 using 1:3:4 with filledcurves fillcolor rgb "#2ca02c" fillstyle transparent solid 0.22 noborder notitle, \
       data index 3 using 1:3:4 with filledcurves fillcolor rgb "#ff7f0e" fillstyle transparent solid 0.22 noborder notitle, \
       data index 0 using 1:2 with lines lw 2 dt 1 lc rgb "#1f77b4" title "v_0 = 40 cm/s (3 runs)", \
       data index 1 using 1:2 with lines lw 2 dt 1 lc rgb "#d62728" title "v_0 = 80 cm/s (3 runs)", \
       data index 2 using 1:2 with lines lw 2 dt 1 lc rgb "#2ca02c" title "v_0 = 140 cm/s (3 runs)", \
       data index 3 using 1:2 with lines lw 2 dt 1 lc rgb "#ff7f0e" title "v_0 = 200 cm/s (3 runs)"

  # ---- panel 2: peak region z < 0.7 R = 0.7 cm (dots: each run's peak)
  reset
  set encoding utf8
  set origin 0.655,0.04
  set size 0.335,0.6225
  set object 1 rectangle from screen 0.655,0.04 to screen 0.99,0.6625 behind fillcolor rgb "white" fillstyle solid 1.0 border lc rgb "#a0a0a0"
  set tics font ",10"
  set title font ",10"
  set xlabel font ",10"
  set ylabel font ",10"
  set title "peak region z < 0.7 R = 0.7 cm\n(dots: each run's peak)"
  set xlabel "z (cm)"
  set ylabel "F (10^{6} dyne)"
  set grid lc rgb "#d0d0d0"
  set xrange [-0.105:0.7]
  set yrange [0:*]
  unset key
  set mxtics 2
  set tics font ",11"
  set title font ",11"
  set xlabel font ",11"
  set ylabel font ",11"
  set samples 400
  plot data index 4 using 1:3:4 with filledcurves fillcolor rgb "#1f77b4" fillstyle transparent solid 0.22 noborder notitle, \
       data index 6 using 1:3:4 with filledcurves fillcolor rgb "#d62728" fillstyle transparent solid 0.22 noborder notitle, \
       data index 8 using 1:3:4 with filledcurves fillcolor rgb "#2ca02c" fillstyle transparent solid 0.22 noborder notitle, \
       data index 10 using 1:3:4 with filledcurves fillcolor rgb "#ff7f0e" fillstyle transparent solid 0.22 noborder notitle, \
       data index 4 using 1:2 with lines lw 2 dt 1 lc rgb "#1f77b4" notitle, \
       data index 5 using 1:2 with points pt 7 ps 1.3 lc rgb "#1f77b4" notitle, \
       data index 6 using 1:2 with lines lw 2 dt 1 lc rgb "#d62728" notitle, \
       data index 7 using 1:2 with points pt 7 ps 1.3 lc rgb "#d62728" notitle, \
       data index 8 using 1:2 with lines lw 2 dt 1 lc rgb "#2ca02c" notitle, \
       data index 9 using 1:2 with points pt 7 ps 1.3 lc rgb "#2ca02c" notitle, \
       data index 10 using 1:2 with lines lw 2 dt 1 lc rgb "#ff7f0e" notitle, \
       data index 11 using 1:2 with points pt 7 ps 1.3 lc rgb "#ff7f0e" notitle
  unset multiplot
  unset multiplot
  set output
}
