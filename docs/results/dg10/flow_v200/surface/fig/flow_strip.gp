# flow_strip.gp, written by granpen. The data are in flow_strip.dat beside it.
# granpen plot flow: v_z of the grains 0.5-1.5 cm from the rod shaft (data/sims/dg10/dg10_flow/dg10_mu0.3_s1_v200_g981_D2.0.flow/surface/flow_strip.csv) against depth.
# Run in this folder: `gnuplot flow_strip.gp` makes flow_strip.png and flow_strip.svg;
# `gnuplot -e "formats='png'" flow_strip.gp` makes only the PNG.
if (!exists("formats")) formats = "png svg"
data = "flow_strip.dat"
do for [fmt in formats] {
  if (fmt eq "png") {
    set terminal pngcairo enhanced size 800,700 font "sans,12" background rgb "white"
  } else {
    if (fmt ne "svg") { print "unknown format ", fmt, " (png or svg)"; exit status 1 }
    set terminal svg enhanced size 800,700 font "sans,12" background rgb "white"
  }
  set output "flow_strip." . fmt
  reset
  set encoding utf8
  set multiplot title "Vertical velocity of the near-shaft strip against depth" font ",14"

  # ---- panel 1
  set origin 0,0
  set size 1,0.94
  set xlabel "v_z of the strip (cm/s; > 0 up)"
  set ylabel "z − z_s (cm; height above the bed surface)"
  set grid lc rgb "#d0d0d0"
  unset key
  set arrow 1 from first 0, graph 0 to first 0, graph 1 nohead lw 1.5 dt 3 lc rgb "#404040"
  set label 1 "v_z = 0" at first 0, graph 0.96 left offset char 0.4,0 textcolor rgb "#404040"
  set samples 400
  plot data index 0 using 1:2 with linespoints lw 2 dt 1 lc rgb "#1f77b4" pt 7 ps 0.9 notitle
  unset multiplot
  unset multiplot
  set output
}
