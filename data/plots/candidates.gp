# Candidates per step of the `edge` strategy (thesis fig. 4.3).
#
#   gnuplot -e "dir='out'; outdir='out/plots'" data/plots/candidates.gp
#
# Input:  dir/steps.csv (fragsim compare --csv DIR)
# Output: outdir/candidates.png (not written, with a note, if steps.csv has no `edge` rows)

if (!exists("dir")) exit error "candidates.gp: set the CSV folder, e.g. gnuplot -e \"dir='out'; outdir='out/plots'\" candidates.gp"
if (!exists("outdir")) outdir = dir . "/plots"
steps = dir . "/steps.csv"
if (system(sprintf("test -r '%s'; echo $?", steps)) ne "0") exit error "candidates.gp: needs " . steps
system(sprintf("mkdir -p '%s'", outdir))

# edge rows: count, first step and its count, step of the maximum, first step with none left, dt
info = system(sprintf("awk -F, 'NR==1{for(i=1;i<=NF;i++)c[$i]=i;next} \
  $c[\"strategy\"]==\"edge\"{s=$c[\"step\"]+0; v=$c[\"candidates\"]+0; n++; \
    if(n==1){s0=s;v0=v;dt=(s?$c[\"t_s\"]/s:0)} if(v>mx){mx=v;smx=s} if(v==0&&z==\"\"&&n>1)z=s; if(v>0)z=\"\"; last=s; lv=v} \
  END{if(z==\"\")z=-1; printf \"%%d %%d %%d %%d %%d %%s %%.10g %%d %%d\", n, s0, v0, mx, smx, z, dt, last, lv}' '%s'", steps))
if (int(word(info, 1)) == 0) {
  print sprintf("candidates.gp: no edge rows in %s, candidates.png not written", steps)
  exit
}
s0 = int(word(info, 2)); v0 = int(word(info, 3)); vmax = int(word(info, 4)); smax = int(word(info, 5))
szero = int(word(info, 6)); dt = real(word(info, 7)); slast = int(word(info, 8)); vlast = int(word(info, 9))

scene = system(sprintf("awk -F, 'NR==1{for(i=1;i<=NF;i++)if($i==\"scene\")c=i;next} c{print $c; exit}' '%s/summary.csv' 2>/dev/null", dir))
if (scene eq "") scene = system(sprintf("basename '%s'", dir))

scol(s) = s eq "none" ? "#0072B2" : s eq "wall" ? "#E69F00" : s eq "deflect-all" ? "#009E73" : \
          s eq "near-plane" ? "#CC79A7" : s eq "edge" ? "#D55E00" : "#555555"
if (strstrt(GPVAL_TERMINALS, " pngcairo ") > 0) {
  set terminal pngcairo size 1000,600 enhanced font "DejaVu Sans,12" linewidth 1
} else {
  set terminal png size 1000,600 enhanced font "DejaVu Sans,12"
}
set output outdir . "/candidates.png"
set datafile separator comma

set title sprintf("Edge strategy: candidate fragments per step, scene %s", scene) font ",14"
set xlabel "simulation step"
set ylabel "candidates (fragments)"
set grid back lt 1 lw 1 lc rgb "#dcdcdc"
set key top right box opaque width 1.5 height 0.5
set xrange [0:slast + 1]
set yrange [0:(vmax > 0 ? vmax * 1.12 + 1 : 1)]
if (vmax <= 10) set ytics 1
set mxtics 2
if (dt > 0) {
  set x2label "time (s)"
  set link x2 via x * dt inverse x / dt
  set x2tics 0.25 nomirror
  set xtics nomirror
}
set label 1 sprintf("%d at step %d", v0, s0) at s0, v0 offset 1.2, 0.6 left front
zlabel = sprintf("none left from step %d (t = %.2f s)", szero, szero * dt)
if (szero > 0) {
  set label 2 zlabel at szero, 0 offset 0, 1.2 right front point pt 7 ps 1.2 lc rgb scol("edge")
} else {
  set label 2 sprintf("%d left at the last step (%d)", vlast, slast) at slast, vlast offset 0, 1.2 right front
}
if (vmax == 0) { set label 2 "no candidates in this run" at graph 0.5, graph 0.5 center front }
edge(col) = strcol("strategy") eq "edge" ? column(col) : NaN
plot steps using (edge("step")):(edge("candidates")) with steps lw 2.5 lc rgb scol("edge") title "edge"
unset output
