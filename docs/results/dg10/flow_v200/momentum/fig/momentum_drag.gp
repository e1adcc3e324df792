# momentum_drag.gp, written by granpen. The data are in momentum_drag.dat beside it.
# granpen plot momentum: F against mu g M(v_z > v0/320) (data/sims/dg10/dg10_flow/dg10_mu0.3_s1_v200_g981_D2.0.flow/momentum/momentum_drag.csv), the 1:1 line and the fit through the origin
# (compare_drag, as granpen momentum).
# Run in this folder: `gnuplot momentum_drag.gp` makes momentum_drag.png and momentum_drag.svg;
# `gnuplot -e "formats='png'" momentum_drag.gp` makes only the PNG.
if (!exists("formats")) formats = "png svg"
data = "momentum_drag.dat"
do for [fmt in formats] {
  if (fmt eq "png") {
    set terminal pngcairo enhanced size 980,680 font "sans,12" background rgb "white"
  } else {
    if (fmt ne "svg") { print "unknown format ", fmt, " (png or svg)"; exit status 1 }
    set terminal svg enhanced size 980,680 font "sans,12" background rgb "white"
  }
  set output "momentum_drag." . fmt
  reset
  set encoding utf8
  set multiplot title "Drag against μ g M of the moving grains: k = 2.45 ± 0.36 (paper: about 1)" font ",14"

  # ---- panel 1
  set origin 0,0
  set size 1,0.94
  set xlabel "μ g M(v_z > v_0/320) (10^{6} dyne)"
  set ylabel "drag force F (10^{6} dyne)"
  set grid lc rgb "#d0d0d0"
  set xrange [0:0.4668612438]
  set yrange [0:1.905797733]
  set key outside right top Left reverse
  set key spacing 1.25
  set samples 400
  plot data index 0 using 1:2 with points pt 9 ps 1.2 lc rgb "#ff7f0e" title "t̃ < 1", \
       x with lines lw 1.5 dt 2 lc rgb "#404040" title "1:1 (paper)", \
       2.447957362*x with lines lw 1.5 dt 1 lc rgb "#000000" title "fit F = k μ g M, k = 2.45 ± 0.36"
  unset multiplot
  unset multiplot
  set output
}
