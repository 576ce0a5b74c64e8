# Luding (1998) Fig. 13: snapshots of the falling column of run 0; grey = collision frequency N_c
# over the last 1 ms. Heights above the removed floor. Grey levels: logarithmic, black N_c = 0
# (and one collision per ms, 1e3 1/s, near black), white N_c >= 1e5 1/s. The paper's linear scale
# (white at 1e4 1/s) saturates in our runs: after 0.05 s a quarter to a half of the disks reach
# 1e4 1/s (run 0 at paper scale: 26 % at 0.052 s, 47 % at 0.060 s), so half the column was white;
# with the white level at 1e5 1/s only the densest few per cent are white and an arch shows as a
# band. The paper's white level 1e4 1/s is a tick of the colour box. Marks (table marks): the black bar on the wall is the initiating disk of the
# first arch (the paper's black bar), ringed in red; disks of the arch the detector finds in that
# frame carry a small blue dot (a third of the disk: an arch of hundreds of disks, as at 0.070 s at
# paper scale, stays a dotted area through which the grey levels show; full-size orange rings made
# it one yellow blob); a visible crack (a wall-to-wall gap >= crack_opening, any shape) is
# drawn as a red line along its course; without one the widest gap's course is dashed; each title
# gives the widest wall-to-wall gap.
# Variables set by granrepro: datadir, outbase, tables.
set datafile separator "\t"
set datafile missing "NaN"
# The snapshot_t<time> tables, in time order (granrepro lists them so).
snaps = ''
do for [i=1:words(tables)] { if (strstrt(word(tables, i), 'snapshot_t') == 1) { snaps = snaps.' '.word(tables, i) } }
n = words(snaps)
mk = datadir.'/marks.tsv'
do for [fmt in "png pdf"] {
  if (fmt eq "png") { set terminal pngcairo size 240*n+120,900 enhanced font "Sans,10" }
  else { set terminal pdfcairo size (1.6*n+0.8)in,6in enhanced font "Sans,8" }
  set output outbase.'.'.fmt
  set multiplot layout 1,n margins 0.05,0.93,0.07,0.86 spacing 0.012,0 title "falling column, N = 1562, L = 20.2 d, ε = 0.9, μ = 0.5, β_0 = 0.2 (run 0); grey: N_c over the last 1 ms\nblack bar / red ring: initiating disk; blue dots: disks of the arch found in the frame; red line: visible crack (≥ 0.5 d), dashed: the widest gap when narrower"
  set palette defined (0 "black", 1 "white")
  # log10 N_c from 10^2.5 (black) to 10^5 (white): 1e3 1/s is dark grey, the paper's 1e4 1/s mid-grey
  set cbrange [2.5:5]
  set style fill solid 1.0 noborder
  set object 1 rectangle from graph 0,0 to graph 1,1 behind fillcolor rgb "#6f93b8" fillstyle solid 0.6
  set size ratio -1
  set xrange [-0.5:20.7]
  set xtics 0,10,20
  unset colorbox
  do for [k=1:n] {
    tt = word(snaps, k)[11:]
    f = datadir.'/snapshot_t'.tt.'.tsv'
    cf = datadir.'/crack_t'.tt.'.tsv'
    # this snapshot's marks (row k of the marks table)
    stats mk using (px = column(2), py = column(3), op = column(5), vis = int(column(6)), 0) skip 1 every ::(k-1)::(k-1) nooutput
    stats f using 2 skip 1 nooutput
    set yrange [STATS_min-2:STATS_min+84]
    unset arrow
    set arrow 2 from 0, graph 0 to 0, graph 1 nohead lw 2 lc rgb "black" front
    set arrow 3 from 20.2, graph 0 to 20.2, graph 1 nohead lw 2 lc rgb "black" front
    if (px == px) { xb = (px < 10.1 ? 0.0 : 20.2); set arrow 4 from xb, py-1.2 to xb, py+1.2 nohead lw 7 lc rgb "black" front }
    if (k == n) { set colorbox vertical user origin screen 0.945,0.25 size screen 0.012,0.5; set cbtics ("≤300" 2.5, "1e3" 3, "1e4" 4, "≥1e5" 5); set cblabel "N_c [1/s] (log; the paper's white is 1e4)" }
    set title sprintf("t = %s s\nwidest gap %.2f d", tt, op)
    set xlabel "x/d"
    if (k == 1) { set ylabel "y/d (above the removed floor)" } else { unset ylabel }
    stats f using ($4 > 0 ? 1 : 0) skip 1 nooutput
    n_arch = int(STATS_sum)
    cmd = "plot f using 1:2:(0.5):($3 > 0 ? log10($3) : 2.5) skip 1 with circles lc palette notitle"
    if (n_arch > 0) { cmd = cmd.", f using 1:($4 > 0 ? $2 : 1/0):(0.18) skip 1 with circles fs solid 1.0 noborder lc rgb '#1E88FF' notitle" }
    if (px == px) { cmd = cmd.sprintf(", '+' using (%g):(%g):(0.55) every ::0::0 with circles fs empty border lc rgb '#D55E00' lw 2.5 notitle", px, py) }
    if (vis) { cmd = cmd.", cf using 1:2 skip 1 with lines lw 3 lc rgb '#D55E00' notitle" }
    # no visible crack: the course of the widest wall-to-wall gap, thin and dashed, shows where the column is most open
    if (!vis && op == op) { cmd = cmd.", cf using 1:2 skip 1 with lines lw 1.2 dt 2 lc rgb '#D55E00' notitle" }
    eval cmd
  }
  unset multiplot
  unset output
}
