# Fragment paths of `none` and `edge` (thesis figs. 4.4 / 4.5): side view (z, y) and top view
# (z, x), each a two-panel PNG, with the fragments that were ever `edge` candidates highlighted
# and the camera path drawn on top.
#
#   gnuplot -e "dir='out'; outdir='out/plots'" data/plots/paths.gp
#
# Inputs:  dir/trajectories.csv (fragsim compare --trajectories), dir/camera.csv
# Outputs: outdir/paths_none_edge_side.png, outdir/paths_none_edge_top.png
# Optional -e variables:
#   tmpdir='...'          existing scratch folder (scripts/plot.sh passes one and removes it);
#                         without it the script makes one with mktemp and removes it at the end
#   zmin, zmax, ymax, xmax  view window in metres (default: framed on the object and the camera)
#   full=1                frame every fragment and the camera path instead (same window in both panels)

if (!exists("dir")) exit error "paths.gp: set the CSV folder, e.g. gnuplot -e \"dir='out'; outdir='out/plots'\" paths.gp"
if (!exists("outdir")) outdir = dir . "/plots"
traj = dir . "/trajectories.csv"
cam = dir . "/camera.csv"
if (system(sprintf("test -r '%s' && test -r '%s'; echo $?", traj, cam)) ne "0") \
    exit error sprintf("paths.gp: needs %s and %s", traj, cam)
system(sprintf("mkdir -p '%s'", outdir))

own_tmp = !exists("tmpdir")
if (own_tmp) tmpdir = system("mktemp -d")

# ---- split trajectories.csv into one file per strategy and class, a blank line between fragments
$SPLIT << EOD
BEGIN { FS = ","; nw = split(want, w, " "); for (i = 1; i <= nw; i++) wanted[w[i]] = 1; maxf = -1 }
FNR == 1 {
  for (i = 1; i <= NF; i++) col[$i] = i
  split("strategy step fragment x_m y_m z_m candidate", need, " ")
  for (i = 1; i in need; i++) if (!(need[i] in col)) { print "missing column " need[i] > "/dev/stderr"; bad = 1; exit 1 }
  next
}
{
  s = $col["strategy"]; f = $col["fragment"] + 0
  if (s == "edge" && $col["candidate"] + 0 != 0) cand[f] = 1
  if (!(s in wanted)) next
  have[s] = 1
  if (f > maxf) maxf = f
  k = ++n[s, f]
  x = $col["x_m"] + 0; y = $col["y_m"] + 0; z = $col["z_m"] + 0
  if (!nb++) { x0 = x1 = x; y0 = y1 = y; z0 = z1 = z }
  if (x < x0) x0 = x; if (x > x1) x1 = x; if (y < y0) y0 = y; if (y > y1) y1 = y
  if (z < z0) z0 = z; if (z > z1) z1 = z
  row[s, f, k] = $col["x_m"] "," $col["y_m"] "," $col["z_m"]
  if (first == "") first = s
  if (s == first && $col["step"] + 0 == 0) { ox += $col["x_m"]; oy += $col["y_m"]; oz += $col["z_m"]; on++ }
}
END {
  if (bad) exit 1
  nc = 0; for (f in cand) nc++
  meta = out "/meta.txt"
  printf "%d %d", nc, maxf + 1 > meta
  printf " %g %g %g", (on ? ox / on : 0), (on ? oy / on : 0), (on ? oz / on : 0) > meta
  for (i = 1; i <= nw; i++) {
    s = w[i]; nr = 0; ncd = 0
    if (s in have) {
      rest = out "/" s "_rest.dat"; cf = out "/" s "_cand.dat"
      printf "" > rest; printf "" > cf
      for (f = 0; f <= maxf; f++) {
        if (!((s, f) in n)) continue
        if (f in cand) { file = cf; ncd++ } else { file = rest; nr++ }
        for (k = 1; k <= n[s, f]; k++) print row[s, f, k] > file
        print "" > file
      }
      close(rest); close(cf)
    }
    printf " %d %d %d", (s in have), nr, ncd > meta
  }
  print "" > meta
  printf "%.10g %.10g %.10g %.10g %.10g %.10g\n", x0, x1, y0, y1, z0, z1 > (out "/bounds.txt")
}
EOD
$CAMSTART << EOD
# first strategy's camera: start, and the last stretch it moved along (for the direction arrow)
BEGIN { FS = "," }
FNR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; next }
first == "" { first = $col["strategy"] }
$col["strategy"] != first { exit }
{
  p = $col["eye_x_m"] " " $col["eye_y_m"] " " $col["eye_z_m"]
  if (start == "") { start = p; last = p; prev = p }
  else if (p != last) { prev = last; last = p }
}
END { if (start == "") print "0 0 0 0 0 0 0 0 0"; else print start, prev, last }
EOD
set print tmpdir . "/split.awk"
print $SPLIT
set print tmpdir . "/camstart.awk"
print $CAMSTART
unset print

strategies = "none edge"
rc = system(sprintf("awk -v out='%s' -v want='%s' -f '%s/split.awk' '%s'; echo $?", \
                    tmpdir, strategies, tmpdir, traj))
if (rc ne "0") { if (own_tmp) { system(sprintf("rm -rf '%s'", tmpdir)) }; exit error "paths.gp: could not read " . traj }
meta = system(sprintf("cat '%s/meta.txt'", tmpdir))
camstart = system(sprintf("awk -f '%s/camstart.awk' '%s'", tmpdir, cam))
ncand = int(word(meta, 1)); nfrag = int(word(meta, 2))
obx = real(word(meta, 3)); oby = real(word(meta, 4)); obz = real(word(meta, 5))
# per strategy i: present, fragments never candidates, fragments ever candidates
has(i) = int(word(meta, 6 + 3 * (i - 1)))
nrest(i) = int(word(meta, 7 + 3 * (i - 1)))
ncd(i) = int(word(meta, 8 + 3 * (i - 1)))
bounds = system(sprintf("cat '%s/bounds.txt'", tmpdir))
cx0 = real(word(camstart, 1)); cy0 = real(word(camstart, 2)); cz0 = real(word(camstart, 3))
nstrat = 0
do for [i = 1:words(strategies)] { nstrat = nstrat + has(i) }
if (nstrat == 0) {
  if (own_tmp) { system(sprintf("rm -rf '%s'", tmpdir)) }
  print sprintf("paths.gp: neither none nor edge in %s, paths figures not written", traj)
  exit
}

scene = system(sprintf("awk -F, 'NR==1{for(i=1;i<=NF;i++)if($i==\"scene\")c=i;next} c{print $c; exit}' '%s/summary.csv' 2>/dev/null", dir))
if (scene eq "") scene = system(sprintf("basename '%s'", dir))

# ---- style: one colour per strategy, shared by every figure (see README.md)
scol(s) = s eq "none" ? "#0072B2" : s eq "wall" ? "#E69F00" : s eq "deflect-all" ? "#009E73" : \
          s eq "near-plane" ? "#CC79A7" : s eq "edge" ? "#D55E00" : "#555555"
# semi-transparent variant for the many thin path lines (ARGB, 0x99 = 60 % transparent)
sfaint(s) = "#99" . scol(s)[2:7]
candcol = "#7B2CBF"   # fragments that were ever edge candidates (no strategy uses this colour)
if (strstrt(GPVAL_TERMINALS, " pngcairo ") > 0) {
  set terminal pngcairo size 1000,600 enhanced font "DejaVu Sans,11" linewidth 1
} else {
  set terminal png size 1000,600 enhanced font "DejaVu Sans,11"
}
set datafile separator comma
camz(s) = strcol("strategy") eq s ? column("eye_z_m") : NaN

# ---- layout: the two panels one above the other on a shared z axis, legends on the right;
# each panel's ranges are widened so that one metre is as long on both axes (equal scale)
W = 1000; H = 600
pl = 0.075; pr = 0.765; ptop = 0.905; pbot = 0.095; gap = 0.075
ph_screen = nstrat > 1 ? (ptop - pbot - gap) / 2 : ptop - pbot
pw_px = (pr - pl) * W; ph_px = ph_screen * H

min(a, b) = a < b ? a : b
max(a, b) = a > b ? a : b
span = abs(obz - cz0) > 1 ? abs(obz - cz0) : 1
if (!exists("zmin")) zmin = (obz < cz0 ? obz : cz0) - 0.5 * span
if (!exists("zmax")) zmax = (obz > cz0 ? obz : cz0) + 0.3 * span
if (!exists("ymax")) ymax = (oby > cy0 ? oby : cy0) + 0.45 * span
if (!exists("xmax")) xmax = 0.6 * span
ylo = (oby < cy0 ? oby : cy0) - 0.3 * span
ylo = ylo > -0.4 ? -0.4 : ylo
if (exists("full")) {   # every fragment and the camera path
  zmin = min(real(word(bounds, 5)), min(cz0, real(word(camstart, 9)))) - 0.5
  zmax = max(real(word(bounds, 6)), max(cz0, real(word(camstart, 9)))) + 0.5
  ymax = max(real(word(bounds, 4)), cy0) + 0.5
  ylo = min(ylo, real(word(bounds, 3)) - 0.3)
  xmax = max(max(abs(real(word(bounds, 1))), abs(real(word(bounds, 2)))), abs(cx0)) + 0.5
}
# camera direction arrow at the end of its path (last stretch it moved along)
czp = real(word(camstart, 6)); cze = real(word(camstart, 9))
# many fragments: thinner, more transparent lines so the bundle stays readable
dense = nfrag > 300
lw_rest = dense ? 0.5 : 0.7
lw_cand = dense ? 0.7 : 1.2
lc_cand = dense ? "#707B2CBF" : candcol

do for [view = 1:2] {
  vname = view == 1 ? "side" : "top"
  if (view == 1) {
    v0 = ylo; v1 = ymax; cv = cy0; ov = oby
    cvp = real(word(camstart, 5)); cve = real(word(camstart, 8))
  } else {
    v0 = -xmax; v1 = xmax; cv = cx0; ov = obx
    cvp = real(word(camstart, 4)); cve = real(word(camstart, 7))
  }
  # pixels per metre, then widen the axis that has room to spare
  ppm = min(pw_px / (zmax - zmin), ph_px / (v1 - v0))
  zc = (zmin + zmax) / 2; z0 = zc - pw_px / ppm / 2; z1 = zc + pw_px / ppm / 2
  if (view == 1) { w0 = v0; w1 = v0 + ph_px / ppm } else { w0 = -ph_px / ppm / 2; w1 = ph_px / ppm / 2 }
  dl = sqrt((cze - czp)**2 + (cve - cvp)**2)
  alen = 0.4 * (z1 - z0) / 20

  set output sprintf("%s/paths_none_edge_%s.png", outdir, vname)
  set multiplot title sprintf("Fragment paths, %s view (%s), scene %s: %d fragments, %d ever edge candidates", \
      vname, view == 1 ? "z-y" : "z-x", scene, nfrag, ncand) font ",13"
  k = 0
  do for [i = 1:words(strategies)] {
    if (has(i)) {
      s = word(strategies, i)
      k = k + 1
      reset
      set datafile separator comma
      set style textbox opaque noborder margins 1, 1
      set lmargin at screen pl; set rmargin at screen pr
      set tmargin at screen ptop - (k - 1) * (ph_screen + gap)
      set bmargin at screen ptop - (k - 1) * (ph_screen + gap) - ph_screen
      set label 10 s at screen pr + 0.015, ptop - (k - 1) * (ph_screen + gap) - 0.01 left \
          font ",13" textcolor rgb scol(s)
      set key at screen pr + 0.012, ptop - (k - 1) * (ph_screen + gap) - 0.05 left top Left reverse \
          samplen 2.5 spacing 1.15 font ",9"
      set grid back lt 1 lw 1 lc rgb "#dcdcdc"
      set tics font ",10"
      set xrange [z0:z1]; set yrange [w0:w1]
      if (k == nstrat) { set xlabel "z (m)   (the camera looks toward -z)" font ",10" offset 0, 0.3 }
      set ylabel (view == 1 ? "height y (m)" : "lateral x (m)") font ",10"
      if (view == 1) { set arrow 1 from graph 0, first 0 to graph 1, first 0 nohead lc rgb "#888888" dt 2 back }
      set label 1 "camera start" at cz0, cv point pt 7 ps 1.5 lc rgb "black" offset 0, -1.3 center front boxed font ",9"
      set label 2 "object" at obz, ov point pt 4 ps 1.5 lc rgb "black" offset 0, -1.3 center front boxed font ",9"
      if (dl > 0) {
        set arrow 2 from cze - alen * (cze - czp) / dl, cve - alen * (cve - cvp) / dl to cze, cve \
            head filled size screen 0.015, 25 lc rgb "black" lw 2 front
      }
      vcol = view == 1 ? 2 : 1
      camv(s) = strcol("strategy") eq s ? column(view == 1 ? "eye_y_m" : "eye_x_m") : NaN
      plot for [j = 1:(nrest(i) > 0)] sprintf("%s/%s_rest.dat", tmpdir, s) using 3:vcol \
             with lines lw lw_rest lc rgb sfaint(s) title sprintf("other fragments (%d)", nrest(i)), \
           for [j = 1:(ncd(i) > 0)] sprintf("%s/%s_cand.dat", tmpdir, s) using 3:vcol \
             with lines lw lw_cand lc rgb lc_cand title sprintf("ever edge candidates (%d)", ncd(i)), \
           cam using (camz(s)):(camv(s)) with lines lw 4 lc rgb "black" title "camera path"
    }
  }
  unset multiplot
}
unset output

if (own_tmp) system(sprintf("rm -rf '%s'", tmpdir))
