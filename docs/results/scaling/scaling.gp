# scaling.gp, written by granpen. The data are in scaling.dat beside it.
# granpen plot scaling: each quantity of docs/results/scaling.csv against D/d_g with its error bars, and the paper's value (a red line, with its band when it has an error); the dotted line: the paper's own D/d_g.
# Run in this folder: `gnuplot scaling.gp` makes scaling.png and scaling.svg;
# `gnuplot -e "formats='png'" scaling.gp` makes only the PNG.
if (!exists("formats")) formats = "png svg"
data = "scaling.dat"
do for [fmt in formats] {
  if (fmt eq "png") {
    set terminal pngcairo enhanced size 1300,2400 font "sans,12" background rgb "white"
  } else {
    if (fmt ne "svg") { print "unknown format ", fmt, " (png or svg)"; exit status 1 }
    set terminal svg enhanced size 1300,2400 font "sans,12" background rgb "white"
  }
  set output "scaling." . fmt
  reset
  set encoding utf8
  set multiplot title "Against the grain size ratio D/d_g: granpen (blue, ± its error), the paper's value (red; shaded: its error), the paper's D/d_g (dotted)" font ",14"

  # ---- panel 1: phi\_0   (paper: 0.61)
  set origin 0,0.7833333333
  set size 0.5,0.1566666667
  set title "phi\\_0   (paper: 0.61)"
  set xlabel "D/d_g"
  set ylabel "phi\\_0"
  set grid lc rgb "#d0d0d0"
  set xrange [4:11]
  set yrange [0.575105848:0.612584752]
  unset key
  set arrow 1 from first 10, graph 0 to first 10, graph 1 nohead lw 1.5 dt 3 lc rgb "#404040"
  set label 1 "paper" at first 10, graph 0.96 left offset char 0.4,0 textcolor rgb "#404040"
  set samples 400
  plot data index 0 using 1:2:3 with yerrorlines lw 2 dt 1 lc rgb "#1f77b4" pt 7 ps 1.2 title "granpen", \
       0.61 with lines lw 1.5 dt 2 lc rgb "#d62728" title "paper: 0.61"

  # ---- panel 2: peak exponent (v\_c to 10 v\_c)   (paper: 2)
  reset
  set encoding utf8
  set origin 0.5,0.7833333333
  set size 0.5,0.1566666667
  set title "peak exponent (v\\_c to 10 v\\_c)   (paper: 2)"
  set xlabel "D/d_g"
  set ylabel "peak exponent (v\\_c to 10 v\\_c)"
  set grid lc rgb "#d0d0d0"
  set xrange [4:11]
  set yrange [1.3597544:2.0474256]
  unset key
  set arrow 1 from first 10, graph 0 to first 10, graph 1 nohead lw 1.5 dt 3 lc rgb "#404040"
  set label 1 "paper" at first 10, graph 0.96 left offset char 0.4,0 textcolor rgb "#404040"
  set samples 400
  plot data index 1 using 1:2:3 with yerrorlines lw 2 dt 1 lc rgb "#1f77b4" pt 7 ps 1.2 title "granpen", \
       2 with lines lw 1.5 dt 2 lc rgb "#d62728" title "paper: 2"

  # ---- panel 3: peak exponent (means above v_c)   (paper: 2)
  reset
  set encoding utf8
  set origin 0,0.6266666667
  set size 0.5,0.1566666667
  set title "peak exponent (means above v_c)   (paper: 2)"
  set xlabel "D/d_g"
  set ylabel "peak exponent (means above v_c)"
  set grid lc rgb "#d0d0d0"
  set xrange [4:11]
  set yrange [1.51508:2.03592]
  unset key
  set arrow 1 from first 10, graph 0 to first 10, graph 1 nohead lw 1.5 dt 3 lc rgb "#404040"
  set label 1 "paper" at first 10, graph 0.96 left offset char 0.4,0 textcolor rgb "#404040"
  set samples 400
  plot data index 2 using 1:2:3 with yerrorlines lw 2 dt 1 lc rgb "#1f77b4" pt 7 ps 1.2 title "granpen", \
       2 with lines lw 1.5 dt 2 lc rgb "#d62728" title "paper: 2"

  # ---- panel 4: peak v_0^2 coefficient c_2/(ρ_g D^2)   (no paper value)
  reset
  set encoding utf8
  set origin 0.5,0.6266666667
  set size 0.5,0.1566666667
  set title "peak v_0^2 coefficient c_2/(ρ_g D^2)   (no paper value)"
  set xlabel "D/d_g"
  set ylabel "value"
  set grid lc rgb "#d0d0d0"
  set xrange [4:11]
  set yrange [4.032:6.352]
  unset key
  set arrow 1 from first 10, graph 0 to first 10, graph 1 nohead lw 1.5 dt 3 lc rgb "#404040"
  set label 1 "paper" at first 10, graph 0.96 left offset char 0.4,0 textcolor rgb "#404040"
  set samples 400
  plot data index 3 using 1:2:3 with yerrorlines lw 2 dt 1 lc rgb "#1f77b4" pt 7 ps 1.2 title "granpen"

  # ---- panel 5: peak crossover c_1/c_2   (no paper value)
  reset
  set encoding utf8
  set origin 0,0.47
  set size 0.5,0.1566666667
  set title "peak crossover c_1/c_2   (no paper value)"
  set xlabel "D/d_g"
  set ylabel "peak crossover c_1/c_2 (cm/s)"
  set grid lc rgb "#d0d0d0"
  set xrange [4:11]
  set yrange [28.0484:187.2816]
  unset key
  set arrow 1 from first 10, graph 0 to first 10, graph 1 nohead lw 1.5 dt 3 lc rgb "#404040"
  set label 1 "paper" at first 10, graph 0.96 left offset char 0.4,0 textcolor rgb "#404040"
  set samples 400
  plot data index 4 using 1:2:3 with yerrorlines lw 2 dt 1 lc rgb "#1f77b4" pt 7 ps 1.2 title "granpen"

  # ---- panel 6: alpha(D = 1 cm) / alpha(D = 2 cm)   (paper: 1)
  reset
  set encoding utf8
  set origin 0.5,0.47
  set size 0.5,0.1566666667
  set title "alpha(D = 1 cm) / alpha(D = 2 cm)   (paper: 1)"
  set xlabel "D/d_g"
  set ylabel "alpha(D = 1 cm) / alpha(D = 2 cm)"
  set grid lc rgb "#d0d0d0"
  set xrange [4:11]
  set yrange [0.9498408:1.6771492]
  unset key
  set arrow 1 from first 10, graph 0 to first 10, graph 1 nohead lw 1.5 dt 3 lc rgb "#404040"
  set label 1 "paper" at first 10, graph 0.96 left offset char 0.4,0 textcolor rgb "#404040"
  set samples 400
  plot data index 5 using 1:2:3 with yerrorlines lw 2 dt 1 lc rgb "#1f77b4" pt 7 ps 1.2 title "granpen", \
       1 with lines lw 1.5 dt 2 lc rgb "#d62728" title "paper: 1"

  # ---- panel 7: λ_{vz} / D (90 and 100 cm/s)   (paper: 0.98 ± 0.15)
  reset
  set encoding utf8
  set origin 0,0.3133333333
  set size 0.5,0.1566666667
  set title "λ_{vz} / D (90 and 100 cm/s)   (paper: 0.98 ± 0.15)"
  set xlabel "D/d_g"
  set ylabel "λ_{vz} / D (90 and 100 cm/s)"
  set grid lc rgb "#d0d0d0"
  set xrange [4:11]
  set yrange [0.3039475788:1.191189068]
  unset key
  set object 10 rectangle from graph 0, first 0.83 to graph 1, first 1.13 behind fillcolor rgb "#d62728" fillstyle transparent solid 0.18 noborder
  set arrow 1 from first 10, graph 0 to first 10, graph 1 nohead lw 1.5 dt 3 lc rgb "#404040"
  set label 1 "paper" at first 10, graph 0.96 left offset char 0.4,0 textcolor rgb "#404040"
  set samples 400
  plot keyentry with filledcurves fillcolor rgb "#d62728" fillstyle transparent solid 0.36 noborder title "paper: 0.98 ± 0.15", \
       data index 6 using 1:2:3 with yerrorlines lw 2 dt 1 lc rgb "#1f77b4" pt 7 ps 1.2 title "granpen", \
       0.98 with lines lw 1.5 dt 2 lc rgb "#d62728" notitle

  # ---- panel 8: φ at r = R for I → 0 (90 and 100 cm/s)   (paper: 0.57)
  reset
  set encoding utf8
  set origin 0.5,0.3133333333
  set size 0.5,0.1566666667
  set title "φ at r = R for I → 0 (90 and 100 cm/s)   (paper: 0.57)"
  set xlabel "D/d_g"
  set ylabel "value"
  set grid lc rgb "#d0d0d0"
  set xrange [4:11]
  set yrange [0.4923950775:0.5757485128]
  unset key
  set arrow 1 from first 10, graph 0 to first 10, graph 1 nohead lw 1.5 dt 3 lc rgb "#404040"
  set label 1 "paper" at first 10, graph 0.96 left offset char 0.4,0 textcolor rgb "#404040"
  set samples 400
  plot data index 7 using 1:2:3 with yerrorlines lw 2 dt 1 lc rgb "#1f77b4" pt 7 ps 1.2 title "granpen", \
       0.57 with lines lw 1.5 dt 2 lc rgb "#d62728" title "paper: 0.57"

  # ---- panel 9: dφ/dI at r = R (90 and 100 cm/s)   (paper: -0.35)
  reset
  set encoding utf8
  set origin 0,0.1566666667
  set size 0.5,0.1566666667
  set title "dφ/dI at r = R (90 and 100 cm/s)   (paper: -0.35)"
  set xlabel "D/d_g"
  set ylabel "dφ/dI at r = R (90 and 100 cm/s)"
  set grid lc rgb "#d0d0d0"
  set xrange [4:11]
  set yrange [-0.3734201804:-0.03382756443]
  unset key
  set arrow 1 from first 10, graph 0 to first 10, graph 1 nohead lw 1.5 dt 3 lc rgb "#404040"
  set label 1 "paper" at first 10, graph 0.96 left offset char 0.4,0 textcolor rgb "#404040"
  set samples 400
  plot data index 8 using 1:2:3 with yerrorlines lw 2 dt 1 lc rgb "#1f77b4" pt 7 ps 1.2 title "granpen", \
       -0.35 with lines lw 1.5 dt 2 lc rgb "#d62728" title "paper: -0.35"

  # ---- panel 10: φ at the face / far below (90 and 100 cm/s)   (paper: 0.97)
  reset
  set encoding utf8
  set origin 0.5,0.1566666667
  set size 0.5,0.1566666667
  set title "φ at the face / far below (90 and 100 cm/s)   (paper: 0.97)"
  set xlabel "D/d_g"
  set ylabel "value"
  set grid lc rgb "#d0d0d0"
  set xrange [4:11]
  set yrange [0.91168:0.97432]
  unset key
  set arrow 1 from first 10, graph 0 to first 10, graph 1 nohead lw 1.5 dt 3 lc rgb "#404040"
  set label 1 "paper" at first 10, graph 0.96 left offset char 0.4,0 textcolor rgb "#404040"
  set samples 400
  plot data index 9 using 1:2:3 with yerrorlines lw 2 dt 1 lc rgb "#1f77b4" pt 7 ps 1.2 title "granpen", \
       0.97 with lines lw 1.5 dt 2 lc rgb "#d62728" title "paper: 0.97"

  # ---- panel 11: drag / (μ g M) (90 and 100 cm/s)   (paper: 1)
  reset
  set encoding utf8
  set origin 0,0
  set size 0.5,0.1566666667
  set title "drag / (μ g M) (90 and 100 cm/s)   (paper: 1)"
  set xlabel "D/d_g"
  set ylabel "drag / (μ g M) (90 and 100 cm/s)"
  set grid lc rgb "#d0d0d0"
  set xrange [4:11]
  set yrange [0.940331708:1.805521942]
  unset key
  set arrow 1 from first 10, graph 0 to first 10, graph 1 nohead lw 1.5 dt 3 lc rgb "#404040"
  set label 1 "paper" at first 10, graph 0.96 left offset char 0.4,0 textcolor rgb "#404040"
  set samples 400
  plot data index 10 using 1:2:3 with yerrorlines lw 2 dt 1 lc rgb "#1f77b4" pt 7 ps 1.2 title "granpen", \
       1 with lines lw 1.5 dt 2 lc rgb "#d62728" title "paper: 1"
  unset multiplot
  unset multiplot
  set output
}
