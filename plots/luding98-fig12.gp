# Luding (1998) Fig. 12: P(N_c), the distribution of collisions per unit time over the last
# Δt = t/2, at our instants nearest to the paper's C/N (fig12_selection.tsv: paper C/N, ours, t).
# Symbols: measured (error bars: counting). Lines: fits by binned maximum likelihood, same colour:
# (a) Eq. (20) Poisson (dotted) and Eq. (21) exponential (dashed) over the whole distribution;
# (b), (c) Eq. (22) power law (solid) and Eq. (21) (dashed) fitted to the tail N_c >= mean N_c
# only (as the paper reads these panels) and drawn only over the bins they were fitted to.
# Thin grey dashes, "paper: ..." in the keys: the paper's own lines, (a) Eq. (21) with A = 19 s^-1
# ("with the mean collision rate A = 19 s^-1 in Fig. 12(a)", Section 4.3 below Eq. (21), the curve
# at C/N = 39), (b) and (c) Eq. (22) with B = 8 s^-1 (Section 4.3 below Eq. (22), the curves for
# C/N > 70), drawn over the whole axis. A script reads no claim: the same numbers are in
# expected/cluster-growth.toml, claims exponential_A (paper = 19.0, 1/s, at C/N = 39) and powerlaw_B
# (paper = 8.0, 1/s, the tail N_c >= mean N_c for 70 <= C/N <= 1404).
# Variables: datadir, outbase.
paper_A = 19.0
paper_B = 8.0
Pe(x, a) = exp(-x/a)/a
Pp(x, b) = b/(b+x)**2
set datafile separator "\t"
set datafile missing "NaN"
sel = datadir.'/fig12_selection.tsv'
# lab(k): our C/N and t of row k+1 of the selection (the table of P(N_c) pnc_<k>).
stats sel using (0) skip 1 nooutput  # every row, whatever it holds
n = STATS_records
array labs[n]
do for [k=1:n] {
  stats sel using (labs[k] = sprintf("C/N = %.0f (t = %.3g s)", column(2), column(3)), 0) skip 1 every ::(k-1)::(k-1) nooutput
}
lab(k) = labs[k+1]
f(k) = datadir.'/pnc_'.k.'.tsv'
colors = "#0072B2 #D55E00 #009E73 #CC79A7 #E69F00 #56B4E9 #000000"
col(k) = word(colors, k%7+1)
# The smallest non-zero P(N_c) of each panel's tables: a paper line is drawn only above a tenth of
# it, so that it does not stretch the axis decades below the data.
array lows[3]
do for [p=1:3] {
  lows[p] = 1e300
  k0 = (p == 1 ? 0 : (p == 2 ? 2 : 4))
  k1 = (p == 1 ? 1 : (p == 2 ? 3 : n-1))
  do for [k=k0:k1] {
    stats f(k) using ($2 > 0 ? $2 : NaN) skip 1 nooutput
    if (STATS_records > 0 && STATS_min < lows[p]) { lows[p] = STATS_min }
  }
}
above(y, p) = (y >= lows[p]/10 ? y : NaN)
do for [fmt in "png pdf"] {
  if (fmt eq "png") { set terminal pngcairo size 1500,520 enhanced font "Sans,11" }
  else { set terminal pdfcairo size 11in,3.8in enhanced font "Sans,9" }
  set output outbase.'.'.fmt
  set multiplot layout 1,3
  set grid lc rgb "#dddddd"
  set logscale y
  set format y "10^{%L}"
  set xlabel "N_c [s^{-1}]"
  set ylabel "P(N_c) [s]"
  set key top right box opaque font ",9"
  set title "(a) Poisson Eq. (20), exponential Eq. (21)"
  plot for [k=0:1] f(k) using 1:2:3 skip 1 with yerrorbars pt 7 ps 0.6 lc rgb col(k) title lab(k), \
       f(0) using 1:4 skip 1 with lines lw 1.5 dt 3 lc rgb col(0) title "Eq. (20)", \
       f(1) using 1:5 skip 1 with lines lw 1.5 dt 2 lc rgb col(1) title "Eq. (21)", \
       above(Pe(x, paper_A), 1) with lines lw 2.5 dt 2 lc rgb "#999999" title "paper: Eq. (21), A = 19 s^{-1} (C/N = 39)"
  set title "(b) tail fits: Eq. (22) (solid), Eq. (21) (dashed)"
  plot for [k=2:3] f(k) using 1:2:3 skip 1 with yerrorbars pt 7 ps 0.6 lc rgb col(k) title lab(k), \
       for [k=2:3] f(k) using 1:"exponential_eq21_tail" skip 0 with lines lw 1.2 dt 2 lc rgb col(k) notitle, \
       for [k=2:3] f(k) using 1:"powerlaw_eq22_tail" skip 0 with lines lw 2 lc rgb col(k) notitle, \
       above(Pp(x, paper_B), 2) with lines lw 2.5 dt 2 lc rgb "#999999" title "paper: Eq. (22), B = 8 s^{-1} (C/N > 70)"
  set title "(c) late times, tail fits: Eq. (22) (solid), Eq. (21) (dashed)"
  plot for [k=4:n-1] f(k) using 1:2:3 skip 1 with yerrorbars pt 7 ps 0.6 lc rgb col(k) title lab(k), \
       for [k=4:n-1] f(k) using 1:"exponential_eq21_tail" skip 0 with lines lw 1.2 dt 2 lc rgb col(k) notitle, \
       for [k=4:n-1] f(k) using 1:"powerlaw_eq22_tail" skip 0 with lines lw 2 lc rgb col(k) notitle, \
       above(Pp(x, paper_B), 3) with lines lw 2.5 dt 2 lc rgb "#999999" title "paper: Eq. (22), B = 8 s^{-1} (C/N > 70)"
  unset multiplot
  unset output
}
