# Luding (1998) Fig. 3: normalised P(b/d) of the ED run of Fig. 2 in successive time windows
# [t_begin, t_end) (impact_parameter_windows.tsv; columns P_t<begin> of impact_parameter_ed.tsv).
# The early windows all lie at P = 1 (molecular chaos, Sec. 3.2), so each window has its own
# symbol and dash type, the first three are shifted sideways by up to 0.012 b/d so that their
# error bars stay apart (as in Fig. 4), and, when a late window's grazing peak (P > 2) squashes
# the rest, an inset enlarges the first three windows around P = 1.
# Variables set by granrepro: datadir, outbase, tables.
# Parameters set by granrepro: n_side, rho, r
set datafile separator "\t"
f = datadir.'/impact_parameter_ed.tsv'
w = datadir.'/impact_parameter_windows.tsv'
stats f skip 1 nooutput
ncol = STATS_columns
nwin = (ncol - 1)/2
N = int(n_side)**2
# The label of window k (row k of the windows table).
stats w using (0) skip 1 nooutput  # every row, whatever it holds
array wl[STATS_records]
do for [k=1:|wl|] {
  stats w using (wl[k] = sprintf("%g s ≤ t < %g s", column(1), column(2)), 0) skip 1 every ::(k-1)::(k-1) nooutput
}
wlabel(k) = wl[k]
colors = "#0072B2 #D55E00 #009E73 #CC79A7 #E69F00 #56B4E9 #000000"
# open circle, open square, open triangle, then filled ones: told apart in grey print as well
points = "6 4 8 7 5 9 13"
dashes = "1 2 4 5 1 2 4"
col(k) = word(colors, (k-1)%7+1)
pt(k) = int(word(points, (k-1)%7+1))
dt(k) = int(word(dashes, (k-1)%7+1))
nshift = (nwin < 3 ? nwin : 3)
# The largest P of any window decides whether the main axis still resolves P = 1 +- a few %.
# (Accumulated inside `using (..., 0)`, so that a window without collisions, all NaN, is no error.)
pmax = 0
do for [k=1:nwin] {
  stats f using (v = column(2*k), pmax = (v > pmax ? v : pmax), 0) skip 1 nooutput
}
inset = (pmax > 2)
# Sideways shift of window k: the first nshift spread symmetrically over +-0.012 b/d (bins are
# 0.05 wide); the later windows, already apart in P, stay at the bin centres.
shift(k) = (k <= nshift && nshift > 1) ? 0.012*(2.0*(k-1)/(nshift-1) - 1) : 0
do for [fmt in "png pdf"] {
  if (fmt eq "png") { set terminal pngcairo size 800,600 enhanced font "Sans,11" }
  else { set terminal pdfcairo size 5.5in,4.1in enhanced font "Sans,10" }
  set output outbase.'.'.fmt
  set multiplot
  # the inset's settings from the previous format are undone here
  set origin 0, 0
  set size 1, 1
  set xtics autofreq font ""
  set ytics autofreq font ""
  set xlabel "b/d"
  set ylabel "P(b/d)"
  set xrange [0:1]
  set yrange [*:*]
  set grid lc rgb "#dddddd"
  set key top left box opaque
  set title sprintf("impact parameter, ED, N = %d, ρ = %s, r = %s, collisions in the time windows given", N, rho, r) font "" offset 0,0
  plot for [k=1:nwin] f using ($1 + shift(k)):(column(2*k)):(column(2*k+1)) skip 1 with yerrorlines \
       lw 1.5 dt dt(k) pt pt(k) ps 0.8 lc rgb col(k) title wlabel(k)
  # Inset, drawn in the empty space left of the grazing peak: the first three windows, P = 1
  # within their Poisson error bars.
  if (inset) {
    set origin 0.38, 0.36
    set size 0.46, 0.48
    set object 1 rectangle from graph 0,0 to graph 1,1 behind fillcolor rgb "white" fillstyle solid noborder
    unset xlabel
    unset ylabel
    set yrange [0.9:1.1]
    set ytics 0.05 font ",9"
    set xtics 0.2 font ",9"
    set title sprintf("first %d windows, enlarged", nshift) font ",10" offset 0,-0.6
    unset key
    set arrow 1 from 0, first 1 to 1, first 1 nohead dt 3 lc rgb "black"
    plot for [k=1:nshift] f using ($1 + shift(k)):(column(2*k)):(column(2*k+1)) skip 1 with yerrorlines \
         lw 1.2 dt dt(k) pt pt(k) ps 0.9 lc rgb col(k) notitle
    unset arrow 1
    unset object 1
  }
  unset multiplot
  unset output
}
