# Luding (1998) Fig. 14: P(N_c) over the last 5 ms of run 0. (a) before arches, semi-log, with the
# exponential Eq. (21); (b) after, log-log, with the power law Eq. (22).
# The points are one run (run 0), so the lines drawn through them are run 0's: thin dashed, each
# time fitted alone (table fits_per_time); thick black, the fit pooled over the panel's four times
# (table fits, A_run0 / B_run0). The value `granrepro check` compares with the paper (claims
# A_rate, B_rate) is the pooled fit's median over seeds: a thick grey dashed line, named as such,
# and in the panel title in both readings of the paper's unit (1e3 1/s, or collisions per Δt).
# The keys sit in the empty lower left corner, with the fitted values only (no repeated words).
# The paper's own values, drawn as its lines: (a) Eq. (21) with A = 1, (b) Eq. (22) with B = 14
# (Section 5 and the caption of Fig. 14; the paper prints no unit), in the 10^3 s^-1 reading of the
# project (experiments/pipe-arching.toml [readings.rate_unit], calibrated on claim A_rate): A = 1e3
# 1/s, B = 14e3 1/s. Thin grey dashes, named "paper: ..." in the key; our seed median is
# dash-dotted purple, so that the two stay apart. A script reads no claim: the same numbers are in
# expected/pipe-arching.toml, claim A_rate (paper = 1000.0) and claim B_rate (its statement: B = 14,
# 1e3 1/s, i.e. 14e3 1/s).
paper_A = 1.0e3
paper_B = 14.0e3
# Variables set by granrepro: datadir, outbase, tables.
set datafile separator "\t"
set datafile missing "NaN"
# The pnc_t<time> tables, in time order (granrepro lists them so): four before arches, then after.
pnc = ''
do for [i=1:words(tables)] { if (strstrt(word(tables, i), 'pnc_t') == 1) { pnc = pnc.' '.word(tables, i) } }
n = words(pnc)
file(k) = datadir.'/'.word(pnc, k).'.tsv'
fits = datadir.'/fits.tsv'
pt = datadir.'/fits_per_time.tsv'
stats fits using (A = column(1), B = column(5), A0 = column(3), B0 = column(7), ns = int(column(9)), dt = column(10), 0) skip 1 every ::0::0 nooutput
# Row k of fits_per_time: time k's own fit and its error.
array vals[n]
array errs[n]
do for [k=1:n] {
  stats pt using (vals[k] = column(2), errs[k] = column(3), 0) skip 1 every ::(k-1)::(k-1) nooutput
}
colors = "#0072B2 #D55E00 #009E73 #CC79A7"
points = "7 5 9 11"
Pe(x, a) = exp(-x/a)/a
Pp(x, b) = b/(b+x)**2
tl(k) = word(pnc, k)[6:]
val(k) = vals[k]
err(k) = errs[k]
g4(x) = gprintf("%.4g", x)
do for [fmt in "png pdf"] {
  if (fmt eq "png") { set terminal pngcairo size 1300,560 enhanced font "Sans,11" }
  else { set terminal pdfcairo size 9.8in,4.2in enhanced font "Sans,9" }
  set output outbase.'.'.fmt
  set multiplot layout 1,2
  set grid lc rgb "#dddddd"
  set key bottom left box opaque font ",9" samplen 2 spacing 1.0 width -2
  set xlabel "N_c [1/s]"
  set ylabel "P(N_c) [s]"
  unset logscale x
  set format x "%g"
  set logscale y
  set format y "10^{%L}"
  set xrange [0:8000]
  set yrange [1e-8:1e-2]
  set title sprintf("(a) before arches (semi-log), run 0\nchecked: A = %s s^{-1} = %s × 10^3 s^{-1} = %s per Δt (median over %d seeds)", g4(A), gprintf("%.2f", A/1e3), gprintf("%.2f", A*dt), ns)
  set key title "run 0, A [s^{-1}]"
  plot for [k=1:4] file(k) using 1:($2>0?$2:1/0):3 skip 1 with yerrorbars pt int(word(points,k)) ps 0.8 \
         lc rgb word(colors,k) title sprintf("%s s: %s ± %s", tl(k), g4(val(k)), g4(err(k))), \
       for [k=1:4] Pe(x, val(k)) with lines lw 1 dt 2 lc rgb word(colors,k) notitle, \
       Pe(x, A0) with lines lw 2.5 lc rgb "black" title sprintf("Eq. (21), pooled: %s", g4(A0)), \
       Pe(x, A) with lines lw 2 dt 4 lc rgb "#7B3294" title sprintf("median over %d seeds: %s", ns, g4(A)), \
       Pe(x, paper_A) with lines lw 2.5 dt 2 lc rgb "#999999" title "paper: A = 1 × 10^3 (Sec. 5)"
  set logscale xy
  set format x "10^{%L}"
  set xrange [100:1e6]
  set yrange [1e-10:1e-2]
  set title sprintf("(b) after arches (log-log), run 0\nchecked: B = %s s^{-1} = %s × 10^3 s^{-1} = %s per Δt (median over %d seeds)", g4(B), gprintf("%.2f", B/1e3), gprintf("%.2f", B*dt), ns)
  set key title "run 0, B [s^{-1}]"
  plot for [k=5:n] file(k) using 1:($2>0?$2:1/0):3 skip 1 with yerrorbars pt int(word(points,k-4)) ps 0.8 \
         lc rgb word(colors,k-4) title sprintf("%s s: %s ± %s", tl(k), g4(val(k)), g4(err(k))), \
       for [k=5:n] Pp(x, val(k)) with lines lw 1 dt 2 lc rgb word(colors,k-4) notitle, \
       (B0 == B0 ? Pp(x, B0) : 1/0) with lines lw 2.5 lc rgb "black" title sprintf("Eq. (22), pooled: %s", g4(B0)), \
       Pp(x, B) with lines lw 2 dt 4 lc rgb "#7B3294" title sprintf("median over %d seeds: %s", ns, g4(B)), \
       Pp(x, paper_B) with lines lw 2.5 dt 2 lc rgb "#999999" title "paper: B = 14 × 10^3 (Sec. 5)"
  unset multiplot
  unset output
}
