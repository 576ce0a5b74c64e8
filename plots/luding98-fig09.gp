# Luding (1998) Fig. 9: N = 784, L = 50, r = fig9_r (0.6), t_c as in the key (-log10 t_c in the paper's
# inset). Top row: single runs (seed 0), as the paper shows them; bottom row: the geometric mean
# over the seeds with its standard error shaded (the claims use it). Drawing the two in separate
# rows keeps five single runs from hiding five means. (a, c) K/K0 against t; (b, d) K/K0
# against C/N with the paper's power laws (C/N)^-2.5 and (C/N)^-7 as guides.
# Variables set by granrepro: datadir, outbase.
# Parameters set by granrepro: fig9_r, fig9_t_c
set datafile separator "\t"
set datafile missing "NaN"
tlist = fig9_t_c
n = words(tlist)
# Five t_c in distinct hues (no two oranges) and dash types, so that every curve can be told apart
# in print and by colour-blind readers.
colors = "#000000 #0072B2 #009E73 #D55E00 #CC79A7 #56B4E9 #E69F00"
col(k) = word(colors, (k-1)%7+1)
run(k) = datadir.'/run_r'.fig9_r.'_tc'.word(tlist, k).'.tsv'
mt(k) = datadir.'/mean_t_r'.fig9_r.'_tc'.word(tlist, k).'.tsv'
mc(k) = datadir.'/mean_cn_r'.fig9_r.'_tc'.word(tlist, k).'.tsv'
lab(k) = sprintf("t_c = %s s", word(tlist, k))
# K/K0 of a seed mean, and the edges of its +-1 standard-error band (the mean is of log10 K). One
# seed has no standard error (NaN): the band then has zero width rather than no points, which
# gnuplot would warn about.
kmean(dummy) = 10**column("log10_K_over_K0")
sem(dummy) = (s = column("log10_K_over_K0_sem"), s == s ? s : 0)
klo(dummy) = 10**(column("log10_K_over_K0") - sem(0))
khi(dummy) = 10**(column("log10_K_over_K0") + sem(0))
# Both rows share their axes, taken from the single runs (which reach further than the means).
# (Accumulated inside `using (..., 0)`; K = 0 or NaN is left out, as the log axis cannot show it.)
tmax = 0
kmin = 1
do for [k=1:n] {
  stats run(k) using (t = column("t"), K = column("K_over_K0"), tmax = (t > tmax ? t : tmax), \
                      kmin = (K > 0 && K < kmin ? K : kmin), 0) nooutput
}
set print $guide25
print sprintf("10\t0.4\n100\t%g", 0.4*10**-2.5)
set print $guide7
print sprintf("100\t%g\n%g\t%g", 0.4*10**-2.5, 10**2.5, 0.4*10**-2.5*10**-3.5)
unset print
do for [fmt in "png pdf"] {
  if (fmt eq "png") { set terminal pngcairo size 1400,1000 enhanced font "Sans,11" }
  else { set terminal pdfcairo size 10in,7.2in enhanced font "Sans,9" }
  set output outbase.'.'.fmt
  set multiplot layout 2,2
  set grid lc rgb "#dddddd"
  set logscale xy
  set format x "10^{%L}"
  set format y "10^{%L}"
  set ylabel "K/K_0"
  set yrange [10**floor(log10(kmin)):1.5]
  set style fill transparent solid 0.15 noborder

  # Top row: seed 0, as in the paper.
  set key bottom left box opaque
  set xlabel "t [s]"
  set xrange [1e-3:10**ceil(log10(tmax))]
  set title "(a) r = ".fig9_r.", single runs (seed 0): K against t"
  plot for [k=1:n] run(k) using "t":"K_over_K0" with lines lw 1.5 lc rgb col(k) title lab(k)
  unset key
  set xlabel "C/N"
  set xrange [0.1:*]
  set title "(b) the runs of (a) against C/N; dashed: (C/N)^{-2.5}, dotted: (C/N)^{-7}"
  # The guides are straight lines in log-log axes, drawn through two points each (a function
  # sampled over a sub-range of a log axis makes gnuplot warn about the linked axis mapping):
  # (C/N)^-2.5 from (10, 0.4) to C/N = 100, then (C/N)^-7 for half a decade.
  plot for [k=1:n] run(k) using "C_over_N":"K_over_K0" with lines lw 1.5 lc rgb col(k) notitle, \
       $guide25 using 1:2 with lines lw 1.5 dt 2 lc rgb "black" notitle, \
       $guide7 using 1:2 with lines lw 1.5 dt 3 lc rgb "black" notitle

  # Bottom row: the seed means the claims judge.
  set key bottom left box opaque
  set xlabel "t [s]"
  set xrange [1e-3:10**ceil(log10(tmax))]
  set title "(c) r = ".fig9_r.", geometric mean over the seeds, ±1 standard error shaded"
  plot for [k=1:n] mt(k) using "t":(klo(0)):(khi(0)) with filledcurves lc rgb col(k) notitle, \
       for [k=1:n] mt(k) using "t":(kmean(0)) with lines lw 2 lc rgb col(k) title lab(k)
  unset key
  set xlabel "C/N"
  set xrange [0.1:*]
  set title "(d) the means of (c) against C/N; guides as in (b)"
  plot for [k=1:n] mc(k) using "C_over_N":(klo(0)):(khi(0)) with filledcurves lc rgb col(k) notitle, \
       for [k=1:n] mc(k) using "C_over_N":(kmean(0)) with lines lw 2 lc rgb col(k) notitle, \
       $guide25 using 1:2 with lines lw 1.5 dt 2 lc rgb "black" notitle, \
       $guide7 using 1:2 with lines lw 1.5 dt 3 lc rgb "black" notitle
  unset multiplot
  unset output
}
