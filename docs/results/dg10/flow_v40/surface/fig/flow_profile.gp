# flow_profile.gp, written by granpen. The data are in flow_profile.dat beside it.
# granpen plot flow: v_z and phi below the rod face (data/sims/dg10/dg10_flow/dg10_mu0.3_s1_v40_g981_D2.0.flow/surface/flow_profile_below.csv), |v_z| on a log axis with the weighted
# exponential fit of the library (fit_exponential, as granpen flow); (c) the same fit over each window of D/2 (local_exponential_fits).
# Run in this folder: `gnuplot flow_profile.gp` makes flow_profile.png and flow_profile.svg;
# `gnuplot -e "formats='png'" flow_profile.gp` makes only the PNG.
if (!exists("formats")) formats = "png svg"
data = "flow_profile.dat"
do for [fmt in formats] {
  if (fmt eq "png") {
    set terminal pngcairo enhanced size 1900,560 font "sans,12" background rgb "white"
  } else {
    if (fmt ne "svg") { print "unknown format ", fmt, " (png or svg)"; exit status 1 }
    set terminal svg enhanced size 1900,560 font "sans,12" background rgb "white"
  }
  set output "flow_profile." . fmt
  reset
  set encoding utf8
  set multiplot title "Flow below the rod face: λ_{vz} = 0.779 cm = 0.39 D (paper: 0.98 D ± 0.15)" font ",14"

  # ---- panel 1: (a) |v_z| below the face
  set origin 0,0
  set size 0.3333333333,0.94
  set title "(a) |v_z| below the face"
  set xlabel "z − z_{tip} (cm; below the rod face)"
  set ylabel "|v_z| (cm/s)"
  set grid lc rgb "#d0d0d0"
  set logscale y
  set yrange [0.1631606632:57.44962515]
  set key top left Left reverse
  set key spacing 1.25
  set ytics ("0.2" 0.2, "0.5" 0.5, "1" 1, "2" 2, "5" 5, "10" 10, "20" 20, "50" 50)
  set mytics 10
  set samples 400
  plot data index 0 using 1:2:3 with yerrorbars lw 2 dt 1 lc rgb "#1f77b4" pt 7 ps 1.2 title "|v_z| ± standard error", \
       data index 1 using 1:2 with lines lw 2 dt 1 lc rgb "#000000" title "fit |v_z| = 49.1 exp(z/λ), λ = 0.779 ± 0.02 cm"

  # ---- panel 2: (b) packing fraction below the face
  reset
  set encoding utf8
  set origin 0.3333333333,0
  set size 0.3333333333,0.94
  set title "(b) packing fraction below the face"
  set xlabel "z − z_{tip} (cm; below the rod face)"
  set ylabel "φ"
  set grid lc rgb "#d0d0d0"
  unset key
  set samples 400
  plot data index 2 using 1:2 with linespoints lw 2 dt 1 lc rgb "#2ca02c" pt 7 ps 1 notitle

  # ---- panel 3: (c) local decay length, windows of 1 cm
  reset
  set encoding utf8
  set origin 0.6666666667,0
  set size 0.3333333333,0.94
  set title "(c) local decay length, windows of 1 cm"
  set xlabel "z − z_{tip} (cm; the window's middle)"
  set ylabel "λ / D"
  set grid lc rgb "#d0d0d0"
  set xrange [-4:-0]
  set yrange [0:1.3]
  set key top left Left reverse
  set key spacing 1.25
  set object 10 rectangle from graph 0, first 0.83 to graph 1, first 1.13 behind fillcolor rgb "#808080" fillstyle transparent solid 0.18 noborder
  set samples 400
  plot keyentry with filledcurves fillcolor rgb "#808080" fillstyle transparent solid 0.36 noborder title "paper: 0.98 ± 0.15", \
       data index 3 using 1:2:3 with yerrorbars lw 2 dt 1 lc rgb "#1f77b4" pt 7 ps 1.2 title "λ / D of each window ± standard error", \
       0.389546 with lines lw 1.5 dt 2 lc rgb "#404040" title "the single fit: 0.39"
  unset multiplot
  unset multiplot
  set output
}
