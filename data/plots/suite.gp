# Robustness against deviation from `fragsim suite --out FILE`: one point per strategy (edge-min
# once per camera model), the share of its player-camera runs with zero near-plane fragments and
# zero camera hits against its mean deviation from `none` over the same runs.
#
#   gnuplot -e "csv='suite.csv'; out='suite.png'" data/plots/suite.gp
#
# Optional: modes='player,player-instant' (the rows counted; default the player modes; 'all' for
# every row). x is logarithmic; a mean deviation of 0 (none, near-plane) sits on the axis's floor.
# Best is the top left: always clean, paths barely changed.

if (!exists("csv")) exit error "suite.gp: set the CSV file, e.g. gnuplot -e \"csv='suite.csv'; out='suite.png'\" suite.gp"
if (!exists("out")) out = csv . ".png"
if (!exists("modes")) modes = "player,player-instant"
if (system(sprintf("test -r '%s'; echo $?", csv)) ne "0") exit error "suite.gp: cannot read " . csv

# Aggregated with awk, one line per point in the file's order: label,clean %,mean deviation,first
# strategy (for the colour).
# Strategies on the same point share one line and one label, "a = b", so labels do not overprint
# (the edge-min camera models coincide until they differ); labels alternate above and below.
agg = sprintf("awk -F, -v modes='%s' 'BEGIN{n=split(modes,m,\",\"); for(i=1;i<=n;i++) want[m[i]]=1} \
  NR==1{for(i=1;i<=NF;i++)c[$i]=i; if(!(\"strategy\" in c)||!(\"mode\" in c)||!(\"deviation_mean_m\" in c)) \
  {print \"missing columns\" > \"/dev/stderr\"; exit 1}; next} \
  modes!=\"all\" && !($c[\"mode\"] in want){next} \
  {s=$c[\"strategy\"]; if(!(s in runs)){order[++k]=s}; runs[s]++; \
   if($c[\"near_fragments\"]+$c[\"camera_hit_fragments\"]+(\"vanished_fragments\" in c ? $c[\"vanished_fragments\"] : 0)==0) clean[s]++; dev[s]+=$c[\"deviation_mean_m\"]} \
  END{for(i=1;i<=k;i++){s=order[i]; p=sprintf(\"%%.6g,%%.6g\", 100*clean[s]/runs[s], dev[s]/runs[s]); \
   if(!(p in name)){at[++q]=p; name[p]=s; first[p]=s; continue}; \
   t=s; if(index(s, \"edge-min/\")==1 && index(first[p], \"edge-min/\")==1) t=substr(s, 10); \
   name[p]=name[p] \" = \" t}; \
   for(i=1;i<=q;i++) print name[at[i]] \",\" at[i] \",\" first[at[i]]}' '%s'", modes, csv)
points = system(agg)
if (strlen(points) == 0) exit error "suite.gp: no rows of modes " . modes . " in " . csv
data = "< " . agg

# The smallest nonzero mean deviation sets the log axis's floor.
dmin = real(system(agg . " | awk -F, '$3>0&&(m==\"\"||$3<m){m=$3} END{print (m==\"\"?1e-3:m)}'"))
floor = dmin / 3.0
dev(v) = v > 0 ? v : floor
runs = system(sprintf("awk -F, -v modes='%s' 'BEGIN{n=split(modes,m,\",\"); for(i=1;i<=n;i++) want[m[i]]=1} \
  NR==1{for(i=1;i<=NF;i++)c[$i]=i; next} (modes==\"all\"||($c[\"mode\"] in want)) && $c[\"strategy\"]==\"none\"{r++} \
  END{print r+0}' '%s'", modes, csv))

if (strstrt(GPVAL_TERMINALS, " pngcairo ") > 0) {
  set terminal pngcairo size 1300,600 enhanced font "DejaVu Sans,11" linewidth 1
} else {
  set terminal png size 1300,600 enhanced font "DejaVu Sans,11"
}
set output out
set datafile separator comma
set termoption noenhanced
set title sprintf("fragsim suite: robustness against deviation (%s runs of modes %s)", runs, modes)
set xlabel "mean deviation from none over those runs (m, log; 0 drawn at the floor)"
set ylabel "runs with zero near-plane fragments and camera hits (%)"
set logscale x
set yrange [-5:112]
set grid back lt 1 lw 1 lc rgb "#dcdcdc"
set offsets graph 0.08, graph 0.25, 0, 0
# One colour per strategy, as in the other figures; the edge-min camera models share one hue.
colour(s) = s eq "none" ? 0x0072B2 : s eq "wall" ? 0xE69F00 : s eq "deflect-all" ? 0x009E73 : \
            s eq "near-plane" ? 0xCC79A7 : s eq "edge" ? 0xD55E00 : \
            strstrt(s, "edge-min") == 1 ? 0x56B4E9 : 0x555555
set multiplot
# Left: every strategy.
set origin 0, 0
set size 0.62, 1
plot data using (dev($3)):2:(colour(strcol(4))) with points pt 7 ps 1.8 lc rgb variable notitle, \
     data every 2 using (dev($3)):2:1 with labels left offset 0.8, 0.9 font ",10" notitle, \
     data every 2::1 using (dev($3)):2:1 with labels left offset 0.8, -0.9 font ",10" notitle
# Right: the top of the chart, where the camera models of edge-min trade robustness for
# deviation a few percent apart (the left panel stacks their labels).
unset title
set origin 0.62, 0
set size 0.38, 1
set title "the top: clean in 85-100% of the runs"
set xlabel "mean deviation (m, log)"
set ylabel ""
set yrange [85:100.9]
set offsets graph 0.05, graph 0.45, 0, 0
plot data using (dev($3)):2:(colour(strcol(4))) with points pt 7 ps 1.8 lc rgb variable notitle, \
     data using (dev($3)):2:1 with labels left offset 0.8, 0.6 font ",9" notitle
unset multiplot
