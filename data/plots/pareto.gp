# Run time against error from `fragsim bench --out FILE`: every configuration as a labelled point,
# the Pareto front (no other configuration both faster and more accurate) as a line.
#
#   gnuplot -e "csv='bench/time_vs_error.csv'; out='bench/pareto.png'" data/plots/pareto.gp
#
# x: compute time (physics + strategy) per simulated second; y: mean position error against the
# reference run while fragments are in flight (the reference itself, error 0, is drawn on the
# x axis's floor). Rows with pareto = 1 make the front.

if (!exists("csv")) exit error "pareto.gp: set the CSV file, e.g. gnuplot -e \"csv='t.csv'; out='t.png'\" pareto.gp"
if (!exists("out")) out = csv . ".png"
if (system(sprintf("test -r '%s'; echo $?", csv)) ne "0") exit error "pareto.gp: needs " . csv

# The smallest nonzero flight error sets the log axis's floor; the reference sits on it.
ymin = real(system(sprintf("awk -F, 'NR==1{for(i=1;i<=NF;i++)c[$i]=i;next} \
  {v=$c[\"flight_error_mean_m\"]+0; if(v>0&&(m==\"\"||v<m))m=v} END{print (m==\"\"?1e-3:m)}' '%s'", csv)))
floor = ymin / 3.0
title_info = system(sprintf("awk -F, 'NR==2{print $c}' c=1 '%s'", csv))

if (strstrt(GPVAL_TERMINALS, " pngcairo ") > 0) {
  set terminal pngcairo size 1100,700 enhanced font "DejaVu Sans,12" linewidth 1
} else {
  set terminal png size 1100,700 enhanced font "DejaVu Sans,12"
}
set output out
set datafile separator comma
set title "Run time against error (fragsim bench)" font ",14"
set xlabel "compute time per simulated second (s): physics + strategy, median"
set ylabel "mean position error in flight vs reference (m)"
set logscale xy
set format y "10^{%L}"
set xtics add (0.02, 0.05, 0.2, 0.3, 0.5, 2, 3, 5)
set grid back lt 1 lw 1 lc rgb "#dcdcdc"
set key bottom left box opaque
# Tight x range: points at the same error sit a few percent apart in time; labels are slanted.
set autoscale xfix
set offsets graph 0.06, graph 0.12, graph 0.45, graph 0.1

gcol(g) = g eq "reference" ? "#000000" : g eq "default" ? "#D55E00" : g eq "dt" ? "#0072B2" : \
          g eq "solver" ? "#009E73" : g eq "predictor" ? "#CC79A7" : g eq "replan" ? "#E69F00" : \
          g eq "skip" ? "#56B4E9" : "#555555"
groups = "reference default dt solver predictor replan skip custom"
do for [i = 1:words(groups)] { set linetype 10 + i lc rgb gcol(word(groups, i)) pt 7 ps 1.6 }
gidx(g) = g eq "reference" ? 11 : g eq "default" ? 12 : g eq "dt" ? 13 : g eq "solver" ? 14 : \
          g eq "predictor" ? 15 : g eq "replan" ? 16 : g eq "skip" ? 17 : 18
err(v) = v != v ? NaN : v > 0 ? v : floor
# The front's points sorted by time, as one unbroken curve.
front = sprintf("< awk -F, 'NR==1{for(i=1;i<=NF;i++)c[$i]=i;next} $c[\"pareto\"]==1{print $c[\"compute_s_per_sim_s\"] \",\" $c[\"flight_error_mean_m\"]}' '%s' | sort -g", csv)

plot csv using "compute_s_per_sim_s":(err(column("flight_error_mean_m"))):(gidx(strcol("group"))) \
       with points pt 7 ps 1.6 lc variable notitle, \
     front using 1:(err($2)) with lines lw 2 dt 2 lc rgb "#333333" title "Pareto front", \
     csv using "compute_s_per_sim_s":(err(column("flight_error_mean_m"))):(strcol("config")) \
       with labels rotate by 60 offset 0.4, 0.8 left font ",10" notitle, \
     NaN with points pt 7 ps 1.6 lc rgb gcol("dt") title "step size", \
     NaN with points pt 7 ps 1.6 lc rgb gcol("solver") title "solver", \
     NaN with points pt 7 ps 1.6 lc rgb gcol("predictor") title "predictor", \
     NaN with points pt 7 ps 1.6 lc rgb gcol("replan") title "replanning", \
     NaN with points pt 7 ps 1.6 lc rgb gcol("skip") title "skips", \
     NaN with points pt 7 ps 1.6 lc rgb gcol("default") title "the scene's default", \
     NaN with points pt 7 ps 1.6 lc rgb gcol("reference") title "reference (error 0, drawn on the floor)"
unset output
