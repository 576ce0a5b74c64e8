# Luding (1998) Fig. 13: snapshots of the falling column of run 0; grey = collision frequency N_c
# over the last 1 ms, black N_c = 0, white N_c >= 1e4 1/s (the paper's scale). Heights above the
# removed floor. A dashed line marks an arch found by the detector (table timeline, arch_y).
# Variables set by granrepro: datadir, outbase.
set datafile separator "\t"
files = system("ls ".datadir."/snapshot_t*.tsv")
n = words(files)
tl = datadir.'/timeline.tsv'
do for [fmt in "png pdf"] {
  if (fmt eq "png") { set terminal pngcairo size 240*n+120,900 enhanced font "Sans,10" }
  else { set terminal pdfcairo size (1.6*n+0.8)in,6in enhanced font "Sans,8" }
  set output outbase.'.'.fmt
  set multiplot layout 1,n margins 0.05,0.93,0.07,0.93 spacing 0.012,0 title "falling column, N = 1562, L = 20.2 d, ε = 0.9, μ = 0.5, β_0 = 0.2 (run 0); grey: N_c over the last 1 ms"
  set palette defined (0 "black", 1 "white")
  set cbrange [0:1e4]
  set style fill solid 1.0 noborder
  set object 1 rectangle from graph 0,0 to graph 1,1 behind fillcolor rgb "#6f93b8" fillstyle solid 0.6
  set size ratio -1
  set xrange [-0.5:20.7]
  set xtics 0,10,20
  unset colorbox
  do for [k=1:n] {
    f = word(files, k)
    tt = substr(f, strstrt(f, "snapshot_t")+10, strstrt(f, ".tsv")-1)
    # the column's current extent: from its lowest to its highest centre
    stats f using 2 skip 1 nooutput
    set yrange [STATS_min-2:STATS_min+84]
    ay = system(sprintf("awk -F'\\t' 'NR>1 && ($1-%s)^2<1e-10 {print $8}' %s", tt, tl))
    unset arrow
    if (ay ne "" && ay ne "nan" && ay ne "NaN") { set arrow 1 from 0, real(ay) to 20.2, real(ay) nohead dt 2 lw 2 lc rgb "#D55E00" front }
    set arrow 2 from 0, graph 0 to 0, graph 1 nohead lw 2 lc rgb "black" front
    set arrow 3 from 20.2, graph 0 to 20.2, graph 1 nohead lw 2 lc rgb "black" front
    if (k == n) { set colorbox vertical user origin screen 0.945,0.25 size screen 0.012,0.5; set cbtics ("0" 0, "5e3" 5e3, "≥1e4" 1e4); set cblabel "N_c [1/s]" }
    set title sprintf("t = %s s", tt)
    set xlabel "x/d"
    if (k == 1) { set ylabel "y/d (above the removed floor)" } else { unset ylabel }
    plot f using 1:2:(0.5):($3 > 1e4 ? 1e4 : $3) skip 1 with circles lc palette notitle
  }
  unset multiplot
  unset output
}
