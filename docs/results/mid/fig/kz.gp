# kz.gp, written by granpen. The data are in kz.dat beside it.
# granpen plot kz: k_z of each trace (granpen fit's linear fit of F on z over the window) with its
# standard error, against v0; runs of one v0 drawn side by side (x scaled by 1.04 per run);
# k_z in 10^{5} dyne/cm.
# Run in this folder: `gnuplot kz.gp` makes kz.png and kz.svg;
# `gnuplot -e "formats='png'" kz.gp` makes only the PNG.
if (!exists("formats")) formats = "png svg"
data = "kz.dat"
do for [fmt in formats] {
  if (fmt eq "png") {
    set terminal pngcairo enhanced size 1050,620 font "sans,12" background rgb "white"
  } else {
    if (fmt ne "svg") { print "unknown format ", fmt, " (png or svg)"; exit status 1 }
    set terminal svg enhanced size 1050,620 font "sans,12" background rgb "white"
  }
  set output "kz." . fmt
  reset
  set encoding utf8
  set multiplot title "Depth coefficient against speed (fit over z ≥ 3 cm; bars: standard errors)" font ",14"

  # ---- panel 1
  set origin 0,0
  set size 1,0.94
  set xlabel "rod speed v_0 (cm/s)"
  set ylabel "depth coefficient k_z (10^{5} dyne/cm)"
  set grid lc rgb "#d0d0d0"
  set logscale x
  set xrange [22.22222222:324]
  set yrange [0:*]
  set key outside right top Left reverse
  set key spacing 1.25
  set key title "runs of one v_0 side by side"
  set object 10 rectangle from graph 0, first 0.6620726883 to graph 1, first 1.560243469 behind fillcolor rgb "#606060" fillstyle transparent solid 0.18 noborder
  set xtics (30, 60, 90, 240)
  set mxtics 10
  set offsets 0, 0, graph 0.1, 0
  set samples 400
  plot keyentry with filledcurves fillcolor rgb "#606060" fillstyle transparent solid 0.36 noborder title "mean ± sd over the 8 traces", \
       data index 0 using 1:2:3 with yerrorbars lw 1.5 dt 1 lc rgb "#1f77b4" pt 7 ps 1.4 title "v_0 = 30 cm/s (2 runs)", \
       data index 1 using 1:2:3 with yerrorbars lw 1.5 dt 1 lc rgb "#d62728" pt 7 ps 1.4 title "v_0 = 60 cm/s (2 runs)", \
       data index 2 using 1:2:3 with yerrorbars lw 1.5 dt 1 lc rgb "#2ca02c" pt 7 ps 1.4 title "v_0 = 90 cm/s (2 runs)", \
       data index 3 using 1:2:3 with yerrorbars lw 1.5 dt 1 lc rgb "#ff7f0e" pt 7 ps 1.4 title "v_0 = 240 cm/s (2 runs)", \
       1.111158079 with lines lw 1.5 dt 2 lc rgb "#404040" title "mean k_z = 1.11×10^{5} dyne/cm"
  unset multiplot
  unset multiplot
  set output
}
