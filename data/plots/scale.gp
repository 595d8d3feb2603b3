# The physics scale curve from scripts/scale_curve.sh's CSV, log-log:
#   left:  ODE time per step (median, bar up to the 95th percentile) against fragments, one line
#          per configuration, with the 60 Hz frame budget (16.7 ms)
#   right: peak memory (ru_maxrss) of each point's process
#
#   gnuplot -e "csv='scale_curve.csv'; out='scale_curve.png'" data/plots/scale.gp
#
# Input columns: fragments, config, ms_per_step_median, ms_per_step_p95, peak_rss_mib (a point
# with empty times, over scale_curve.sh's time limit, is left out).

if (!exists("csv")) exit error "scale.gp: set the CSV, e.g. gnuplot -e \"csv='scale_curve.csv'; out='scale_curve.png'\" scale.gp"
if (!exists("out")) out = "scale_curve.png"
if (system(sprintf("test -r '%s'; echo $?", csv)) ne "0") exit error "scale.gp: cannot read " . csv

if (strstrt(GPVAL_TERMINALS, "pngcairo") > 0) {
  set terminal pngcairo size 1000,600 font "sans,10"
} else {
  set terminal png size 1000,600
}
set output out
set datafile separator ","
set termoption noenhanced
set key top left box opaque
set grid xtics ytics mxtics mytics lc "#dddddd"
set logscale xy
set xrange [700:140000]
set xlabel "fragments"
set format x "%.0s%c"

configs = "ballistic ground collisions"
label(c) = c eq "ballistic" ? "ballistic (no ground, no pairs)" : \
           c eq "ground" ? "ground contacts, no pairs (exact solver)" : \
           "full collisions (QuickStep, 20 it.)"
colour(c) = c eq "ballistic" ? "#0072B2" : c eq "ground" ? "#E69F00" : "#D55E00"
# Keeps one configuration's rows (others become NaN, which gnuplot skips).
pick(c, col) = strcol(2) eq c ? column(col) : NaN

set multiplot layout 1,2 title "fragsim physics: ODE 0.16.2, one core (median over the steps from t = 1 s)"
set ylabel "ms per step (median; bar: 95th percentile)"
set yrange [0.1:30000]
budget = 1000.0 / 60
set label 1 "60 Hz budget, 16.7 ms" at 800, budget * 1.25 tc "#555555"
plot for [c in configs] csv every ::1 using 1:(pick(c, 3)):(pick(c, 3)):(pick(c, 4)) \
       with yerrorlines lw 2 pt 7 ps 0.8 lc rgb colour(c) title label(c), \
     budget with lines dt 2 lc "#555555" notitle
unset label 1
set key bottom right
set ylabel "peak memory, MiB (ru_maxrss)"
set yrange [1:3000]
plot for [c in configs] csv every ::1 using 1:(pick(c, 5)) \
       with linespoints lw 2 pt 7 ps 0.8 lc rgb colour(c) title label(c)
unset multiplot
