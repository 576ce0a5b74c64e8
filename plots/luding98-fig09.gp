# Luding (1998) Fig. 9: N = 784, L = 50, r = 0.6, t_c as in the key (-log10 t_c in the paper's
# inset). Thin lines: single runs (seed 0), as in the paper; thick: geometric mean over the
# seeds (the claims use it). (a) K/K0 against t; (b) K/K0 against C/N with the paper's power
# laws (C/N)^-2.5 and (C/N)^-7 as guides. Variables set by granrepro: datadir, outbase.
set datafile separator "\t"
set datafile missing "NaN"
summary = datadir.'/fig9_summary.tsv'
tlist = system("awk -F'\t' 'NR>1{printf \"%s \", $1}' ".summary)
n = words(tlist)
colors = "#0072B2 #D55E00 #009E73 #CC79A7 #E69F00 #56B4E9 #000000"
run(k) = datadir.'/run_r0.6_tc'.word(tlist, k).'.tsv'
mt(k) = datadir.'/mean_t_r0.6_tc'.word(tlist, k).'.tsv'
mc(k) = datadir.'/mean_cn_r0.6_tc'.word(tlist, k).'.tsv'
lab(k) = sprintf("t_c = %s s", word(tlist, k))
do for [fmt in "png pdf"] {
  if (fmt eq "png") { set terminal pngcairo size 1400,560 enhanced font "Sans,11" }
  else { set terminal pdfcairo size 10in,4in enhanced font "Sans,9" }
  set output outbase.'.'.fmt
  set multiplot layout 1,2
  set grid lc rgb "#dddddd"
  set logscale xy
  set format x "10^{%L}"
  set format y "10^{%L}"
  set ylabel "K/K_0"
  set key bottom left box opaque
  set xlabel "t [s]"
  set xrange [1e-3:*]
  set title "(a) r = 0.6: K against t (thin: seed 0, thick: seed mean)"
  plot for [k=1:n] run(k) using "t":"K_over_K0" with lines lw 0.8 lc rgb word(colors, (k-1)%7+1) notitle, \
       for [k=1:n] mt(k) using "t":(10**column("log10_K_over_K0")) with lines lw 2.5 lc rgb word(colors, (k-1)%7+1) title lab(k)
  set xlabel "C/N"
  set xrange [0.1:*]
  set title "(b) r = 0.6: K against C/N; dashed: (C/N)^{-2.5}, dotted: (C/N)^{-7}"
  a = 10**(2.5*log10(10)) * 0.4   # anchors chosen to sit near the curves
  plot for [k=1:n] run(k) using "C_over_N":"K_over_K0" with lines lw 0.8 lc rgb word(colors, (k-1)%7+1) notitle, \
       for [k=1:n] mc(k) using "C_over_N":(10**column("log10_K_over_K0")) with lines lw 2.5 lc rgb word(colors, (k-1)%7+1) title lab(k), \
       [10:100] 0.4*(x/10)**-2.5 with lines lw 1.5 dt 2 lc rgb "black" notitle, \
       [100:1000] 0.4*10**-2.5*(x/100)**-7 with lines lw 1.5 dt 3 lc rgb "black" notitle
  unset multiplot
  unset output
}
