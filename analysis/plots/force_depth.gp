# F against depth for several force traces (granpen-trace v1, cgs).
#   gnuplot -e "files='a.csv b.csv'; out='force_depth.png'" force_depth.gp
# Titles come from each file's v0 header key; F is shown in newtons.
if (!exists("files")) { print "give files='a.csv b.csv ...'"; exit 1 }
if (!exists("out")) { out = 'force_depth.png' }
v0_of(f) = system(sprintf("sed -n 's/^# v0 = //p' '%s' | head -1", f))
set terminal pngcairo size 900,600 font ",12"
set output out
set datafile separator ","
set datafile commentschars "#"
set datafile columnheaders
set title "Rod drag against depth (tiny preset)"
set xlabel "tip depth z below the bed surface (cm)"
set ylabel "drag force F (N)"
set key top left box opaque
set grid
set xzeroaxis
plot for [f in files] f using (column("z")):(column("F")*1e-5) with lines lw 1.5 \
     title sprintf("v_0 = %s cm/s", v0_of(f))
