# Luding (1998) Fig. 13: snapshots of the falling column of run 0; grey = collision frequency N_c
# over the last 1 ms, black N_c = 0, white N_c >= 1e4 1/s (the paper's scale). Heights above the
# removed floor. Marks (table marks): the black bar on the wall is the initiating disk of the
# first arch (the paper's black bar), ringed in red; disks of the arch the detector finds in that
# frame are ringed in orange; a visible crack (a wall-to-wall gap >= crack_opening, any shape) is
# drawn as a red line along its course, and each title gives the widest wall-to-wall gap.
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
  set multiplot layout 1,n margins 0.05,0.93,0.07,0.86 spacing 0.012,0 title "falling column, N = 1562, L = 20.2 d, ε = 0.9, μ = 0.5, β_0 = 0.2 (run 0); grey: N_c over the last 1 ms\nblack bar / red ring: initiating disk; orange rings: arch found in the frame; red line: visible crack"
  set palette defined (0 "black", 1 "white")
  set cbrange [0:1e4]
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
    if (k == n) { set colorbox vertical user origin screen 0.945,0.25 size screen 0.012,0.5; set cbtics ("0" 0, "5e3" 5e3, "≥1e4" 1e4); set cblabel "N_c [1/s]" }
    set title sprintf("t = %s s\nwidest gap %.2f d", tt, op)
    set xlabel "x/d"
    if (k == 1) { set ylabel "y/d (above the removed floor)" } else { unset ylabel }
    stats f using ($4 > 0 ? 1 : 0) skip 1 nooutput
    n_arch = int(STATS_sum)
    cmd = "plot f using 1:2:(0.5):($3 > 1e4 ? 1e4 : $3) skip 1 with circles lc palette notitle"
    if (n_arch > 0) { cmd = cmd.", f using 1:($4 > 0 ? $2 : 1/0):(0.5) skip 1 with circles fs empty border lc rgb '#E69F00' lw 1.5 notitle" }
    if (px == px) { cmd = cmd.sprintf(", '+' using (%g):(%g):(0.55) every ::0::0 with circles fs empty border lc rgb '#D55E00' lw 2.5 notitle", px, py) }
    if (vis) { cmd = cmd.", cf using 1:2 skip 1 with lines lw 3 lc rgb '#D55E00' notitle" }
    eval cmd
  }
  unset multiplot
  unset output
}
