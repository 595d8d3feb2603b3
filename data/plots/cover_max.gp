# The occlusion bound's trade-off from a sweep of edge-min.cover_max (docs/visibility.md):
#   fragsim sweep --scene data/scenes/front.ini --vary edge-min.cover_max=1,0.9,0.8,0.7,0.6,0.5,0.4,0.3 \
#     --strategies none,edge-min --out docs/cover_max_front.csv
#   gnuplot -e "csv='docs/cover_max_front.csv'; out='docs/img/cover_max_front.png'" data/plots/cover_max.gp
#
# left:  central occlusion (max and mean over the steps) and the near misses kept (share of the
#        `none` run's), against the bound, with the bound itself (a measured max on or under it
#        meets it)
# right: mean deviation from the `none` run and the total impulse
# The bound tightens to the right (x reversed); cover_max = 1 is off: edge-min as before.

if (!exists("csv")) exit error "cover_max.gp: set the CSV, e.g. gnuplot -e \"csv='docs/cover_max_front.csv'; out='cover.png'\" cover_max.gp"
if (!exists("out")) out = csv . ".png"
if (system(sprintf("test -r '%s'; echo $?", csv)) ne "0") exit error "cover_max.gp: cannot read " . csv

# One row per edge-min run: cover_max, central max %, central mean %, deviation m, near misses
# kept %, impulse N s, near-plane fragments + camera hits; sorted by cover_max.
table = sprintf("< awk -F, 'NR==1{for(i=1;i<=NF;i++)c[$i]=i;next} \
  $c[\"strategy\"]==\"none\"{nm=$c[\"near_misses\"]; next} \
  {r[NR]=$c[\"edge-min.cover_max\"] \" \" 100*$c[\"central_occlusion_max\"] \" \" 100*$c[\"central_occlusion_mean\"] \" \" $c[\"deviation_mean_m\"] \" \" $c[\"near_misses\"] \" \" $c[\"impulse_Ns\"] \" \" $c[\"near_fragments\"]+$c[\"camera_hit_fragments\"]} \
  END{for(k in r){split(r[k],v,\" \"); printf \"%%s %%s %%s %%s %%s %%s %%s\\n\", v[1], v[2], v[3], v[4], (nm>0?100*v[5]/nm:0), v[6], v[7]}}' '%s' | sort -g", csv)
scene = system(sprintf("awk -F, 'NR==1{for(i=1;i<=NF;i++)c[$i]=i;next} NR==2{print $c[\"scene\"]}' '%s'", csv))

if (strstrt(GPVAL_TERMINALS, " pngcairo ") > 0) {
  set terminal pngcairo size 1000,600 enhanced font "DejaVu Sans,10" linewidth 1
} else {
  set terminal png size 1000,600 enhanced font "DejaVu Sans,10"
}
set output out
set termoption noenhanced
set grid back lt 1 lw 1 lc rgb "#dcdcdc"
set xrange [1.02:0.28] reverse
set xtics 0.1
set xlabel "edge-min.cover_max (1 = off)"

set multiplot layout 1,2 title sprintf("edge-min.cover_max on %s: what the occlusion bound costs", scene)
set ylabel "% of the central region / of none's near misses"
set yrange [0:110]
set key bottom left box opaque
plot x * 100 with lines dt 2 lw 1.5 lc rgb "#777777" title "the bound", \
     table using 1:2 with linespoints pt 7 lw 2 lc rgb "#D55E00" title "central occlusion, max", \
     table using 1:3 with linespoints pt 5 lw 2 lc rgb "#E69F00" title "central occlusion, mean", \
     table using 1:5 with linespoints pt 9 lw 2 lc rgb "#0072B2" title "near misses kept"

set ylabel "mean deviation (m)"
set y2label "impulse (N s)"
set yrange [0:*]
set y2range [0:*]
set ytics nomirror
set y2tics
set key top left box opaque
plot table using 1:4 with linespoints pt 7 lw 2 lc rgb "#009E73" title "mean deviation (m)", \
     table using 1:6 axes x1y2 with linespoints pt 5 lw 2 lc rgb "#CC79A7" title "impulse (N s)", \
     table using 1:($7 > 0 ? $4 : NaN) with points pt 6 ps 2.5 lc rgb "#000000" \
       title "near-plane or camera hits > 0"
unset multiplot
