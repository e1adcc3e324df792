# flow_surface.gp, written by granpen. The data are in flow_surface.dat beside it.
# granpen plot flow: v_z of the near-shaft strip's top grain layer per frame (data/sims/dg10/dg10_flow/dg10_mu0.3_s1_v200_g981_D2.0.flow/surface/flow_surface.csv) against t~ = (z/v0) sqrt(g/D); the paper sees it cross 0 at t~ = 1.
# Run in this folder: `gnuplot flow_surface.gp` makes flow_surface.png and flow_surface.svg;
# `gnuplot -e "formats='png'" flow_surface.gp` makes only the PNG.
if (!exists("formats")) formats = "png svg"
data = "flow_surface.dat"
do for [fmt in formats] {
  if (fmt eq "png") {
    set terminal pngcairo enhanced size 900,620 font "sans,12" background rgb "white"
  } else {
    if (fmt ne "svg") { print "unknown format ", fmt, " (png or svg)"; exit status 1 }
    set terminal svg enhanced size 900,620 font "sans,12" background rgb "white"
  }
  set output "flow_surface." . fmt
  reset
  set encoding utf8
  set multiplot title "Surface flux next to the rod: no sign change" font ",14"

  # ---- panel 1
  set origin 0,0
  set size 1,0.94
  set xlabel "t̃ = (z/v_0) √(g/D)"
  set ylabel "v_z of the surface grains (cm/s; > 0 up)"
  set grid lc rgb "#d0d0d0"
  set key bottom left
  set key spacing 1.25
  set arrow 1 from first 1, graph 0 to first 1, graph 1 nohead lw 1.5 dt 3 lc rgb "#404040"
  set label 1 "t̃ = 1 (paper)" at first 1, graph 0.96 left offset char 0.4,0 textcolor rgb "#404040"
  set samples 400
  plot data index 0 using 1:2 with linespoints lw 2 dt 1 lc rgb "#1f77b4" pt 7 ps 0.9 title "top grain layer, 0.5–1.5 cm from the shaft", \
       0 with lines lw 1 dt 1 lc rgb "#404040" notitle
  unset multiplot
  unset multiplot
  set output
}
