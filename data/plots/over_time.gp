# Per-step metrics of every strategy over time, from steps.csv:
#   occlusion.png           share of the viewport (and of its central region) covered by fragments, %
#   near_intersections.png  fragments meeting the near rectangle per step, one panel per strategy
#   near_m.png              near clip distance over time (only `near-plane` moves it)
#
#   gnuplot -e "dir='out'; outdir='out/plots'" data/plots/over_time.gp
#
# Input: dir/steps.csv (fragsim compare --csv DIR); dir/summary.csv and dir/config.ini are read
# for the scene's name and the central region's size when present.

if (!exists("dir")) exit error "over_time.gp: set the CSV folder, e.g. gnuplot -e \"dir='out'; outdir='out/plots'\" over_time.gp"
if (!exists("outdir")) outdir = dir . "/plots"
steps = dir . "/steps.csv"
if (system(sprintf("test -r '%s'; echo $?", steps)) ne "0") exit error "over_time.gp: needs " . steps
system(sprintf("mkdir -p '%s'", outdir))

# one line per strategy, in file order: name, total near intersections, max per step, min and max near_m
stats_txt = system(sprintf("awk -F, 'NR==1{for(i=1;i<=NF;i++)c[$i]=i;next} \
  {s=$c[\"strategy\"]; if(!(s in n)){o[++k]=s; lo[s]=hi[s]=$c[\"near_m\"]+0} n[s]++; v=$c[\"near_intersections\"]+0; \
   tot[s]+=v; if(v>mx[s])mx[s]=v; m=$c[\"near_m\"]+0; if(m<lo[s])lo[s]=m; if(m>hi[s])hi[s]=m; tl=$c[\"t_s\"]+0; if(tl>tmax)tmax=tl} \
  END{for(i=1;i<=k;i++)printf \"%%s %%d %%d %%.10g %%.10g \", o[i], tot[o[i]], mx[o[i]]+0, lo[o[i]], hi[o[i]]; printf \"%%.10g\", tmax}' '%s'", steps))
nstrat = (words(stats_txt) - 1) / 5
if (nstrat < 1) exit error "over_time.gp: no rows in " . steps
sname(i) = word(stats_txt, 5 * (i - 1) + 1)
stot(i) = int(word(stats_txt, 5 * (i - 1) + 2))
smax(i) = int(word(stats_txt, 5 * (i - 1) + 3))
snlo(i) = real(word(stats_txt, 5 * (i - 1) + 4))
snhi(i) = real(word(stats_txt, 5 * (i - 1) + 5))
tmax = real(word(stats_txt, words(stats_txt)))

scene = system(sprintf("awk -F, 'NR==1{for(i=1;i<=NF;i++)if($i==\"scene\")c=i;next} c{print $c; exit}' '%s/summary.csv' 2>/dev/null", dir))
if (scene eq "") scene = system(sprintf("basename '%s'", dir))
cshare = system(sprintf("awk -F= '$1 ~ /^[ \\t]*central_share[ \\t]*$/{gsub(/[ \\t]/,\"\",$2); print $2; exit}' '%s/config.ini' 2>/dev/null", dir))
clabel = cshare eq "" ? "central region" : sprintf("central region (middle %g %% of width and height)", 100 * real(cshare))

# ---- style: one colour per strategy, shared by every figure (see README.md)
scol(s) = s eq "none" ? "#0072B2" : s eq "wall" ? "#E69F00" : s eq "deflect-all" ? "#009E73" : \
          s eq "near-plane" ? "#CC79A7" : s eq "edge" ? "#D55E00" : "#555555"
# identical curves (near-plane's occlusion is none's) would hide each other: earlier strategies
# are drawn wider, so every curve stays visible as a coloured edge around the ones on top of it
lwof(i) = 1.5 + 1.1 * (nstrat - i)
if (strstrt(GPVAL_TERMINALS, " pngcairo ") > 0) {
  set terminal pngcairo size 1000,600 enhanced font "DejaVu Sans,12" linewidth 1
} else {
  set terminal png size 1000,600 enhanced font "DejaVu Sans,12"
}
set datafile separator comma
sel(s, col) = strcol("strategy") eq s ? column(col) : NaN
pct(s, col) = strcol("strategy") eq s ? 100 * column(col) : NaN

# ---- occlusion.png: whole viewport above, central region below, shared time axis
set output outdir . "/occlusion.png"
set multiplot title sprintf("Screen occlusion by fragments over time, scene %s", scene) font ",14"
set lmargin at screen 0.08; set rmargin at screen 0.82
set grid back lt 1 lw 1 lc rgb "#dcdcdc"
set xrange [0:tmax]
set yrange [0:*<100]
set offsets 0, 0, graph 0.06, 0
set key at screen 0.84, screen 0.86 left top Left reverse samplen 2.5 spacing 1.2 title "strategy" font ",11"
set tmargin at screen 0.88; set bmargin at screen 0.53
set format x ""
set ylabel "viewport covered (%)"
set label 1 "whole viewport" at graph 0.99, graph 0.92 right front font ",11"
plot for [i = 1:nstrat] steps using "t_s":(pct(sname(i), "occlusion")) with lines lw lwof(i) \
     lc rgb scol(sname(i)) title sname(i)
set tmargin at screen 0.47; set bmargin at screen 0.12
set format x "%g"
set xlabel "time after the explosion (s)"
set ylabel "central region covered (%)"
set label 1 clabel at graph 0.99, graph 0.92 right front font ",11"
unset key
plot for [i = 1:nstrat] steps using "t_s":(pct(sname(i), "central_occlusion")) with lines lw lwof(i) \
     lc rgb scol(sname(i)) notitle
unset multiplot
unset output
reset

# ---- near_intersections.png: one strip per strategy on a common count scale
set datafile separator comma
set output outdir . "/near_intersections.png"
allmax = 1
do for [i = 1:nstrat] { if (smax(i) > allmax) { allmax = smax(i) } }
ptop = 0.89; pbot = 0.11; pgap = 0.018
ph = (ptop - pbot - (nstrat - 1) * pgap) / nstrat
set multiplot title sprintf("Near-plane intersections per step (fragments meeting the near rectangle), scene %s", scene) font ",14"
set lmargin at screen 0.09; set rmargin at screen 0.80
set grid back lt 1 lw 1 lc rgb "#dcdcdc"
set xrange [0:tmax]
set yrange [0:allmax * 1.25]
set ytics 0, (allmax <= 4 ? 1 : ceil(allmax / 3.0)), allmax font ",10"
set style fill solid 0.6 noborder
unset key
do for [i = 1:nstrat] {
  set tmargin at screen ptop - (i - 1) * (ph + pgap)
  set bmargin at screen ptop - (i - 1) * (ph + pgap) - ph
  if (i == nstrat) {
    set format x "%g"
    set xlabel "time after the explosion (s)"
  } else {
    set format x ""
    unset xlabel
  }
  if (i == (nstrat + 1) / 2) { set ylabel "fragments per step" offset -1, 0 } else { unset ylabel }
  set label 1 sprintf("%s", sname(i)) at screen 0.815, screen ptop - (i - 1) * (ph + pgap) - 0.35 * ph left \
      textcolor rgb scol(sname(i)) font ",12"
  set label 2 sprintf("%d fragment-step%s", stot(i), stot(i) == 1 ? "" : "s") \
      at screen 0.815, screen ptop - (i - 1) * (ph + pgap) - 0.7 * ph left font ",10"
  if (stot(i) == 0) {
    set label 3 "no intersections" at graph 0.5, graph 0.5 center front textcolor rgb "#777777" font ",10"
  } else {
    unset label 3
  }
  plot steps using "t_s":(sel(sname(i), "near_intersections")) with impulses lw 3 lc rgb scol(sname(i))
}
unset multiplot
unset output
reset

# ---- near_m.png: near clip distance, log scale
set datafile separator comma
set output outdir . "/near_m.png"
nlo = snlo(1); nhi = snhi(1)
do for [i = 1:nstrat] { nlo = snlo(i) < nlo ? snlo(i) : nlo; nhi = snhi(i) > nhi ? snhi(i) : nhi }
if (nlo <= 0) nlo = 1e-4
set title sprintf("Near clip distance over time, scene %s", scene) font ",14"
set xlabel "time after the explosion (s)"
set ylabel "near distance (m)"
set logscale y
set yrange [nlo / 1.6 : nhi * 1.6]
set format y "%g"
set ytics add (0.01, 0.02, 0.05, 0.1, 0.2, 0.5)
set mytics 10
set grid xtics ytics mytics back lt 1 lw 1 lc rgb "#d4d4d4", lt 1 lw 1 lc rgb "#eeeeee"
set xrange [0:tmax]
set key outside right top Left reverse samplen 2.5 spacing 1.2 title "strategy" font ",11"
if (nlo == nhi) { set label 1 sprintf("every strategy keeps the near plane at %g m", nlo) at graph 0.5, graph 0.6 center front }
plot for [i = 1:nstrat] steps using "t_s":(sel(sname(i), "near_m")) with steps lw lwof(i) \
     lc rgb scol(sname(i)) title sprintf("%s (min %.3g m)", sname(i), snlo(i))
unset output
