# Luding (1998) Fig. 2: K/K0 against t/t0 from ED (solid) and DSMC (dash-dotted) with identical
# initial conditions, and Eq. (18) dashed as in the caption. t0 from kinetic theory (sqrt(2 pi) in
# Eq. 19; see experiments/cooling/cooling.cpp). The x axis starts at the first sample after t = 0.
# Variables set by granrepro: datadir, outbase, tables, has().
# Parameters set by granrepro: n_side, rho, r
set datafile separator "\t"
set datafile missing "NaN"
set key autotitle columnhead
ed = datadir.'/energy_ed.tsv'
ds = datadir.'/energy_dsmc.tsv'
have_dsmc = has('energy_dsmc')
# The run's own N = n_side^2 (99856 in the paper, 10^4 at quick scale), so the title says which.
N = int(n_side)**2
# First sample after t = 0 (the log axis cannot show t = 0).
stats ed using (column("t_over_t0") > 0 ? column("t_over_t0") : NaN) nooutput
xlo = STATS_min
do for [fmt in "png pdf"] {
  if (fmt eq "png") { set terminal pngcairo size 800,600 enhanced font "Sans,11" }
  else { set terminal pdfcairo size 5.5in,4.1in enhanced font "Sans,10" }
  set output outbase.'.'.fmt
  set logscale xy
  set format x "10^{%L}"
  set format y "10^{%L}"
  set xlabel "t/t_0"
  set ylabel "K/K_0"
  set xrange [xlo:*]
  set grid lc rgb "#dddddd"
  set key bottom left box opaque
  set title sprintf("freely cooling gas, N = %d, ρ = %s, r = %s", N, rho, r)
  if (have_dsmc) {
    plot ed using "t_over_t0":"K_over_K0" with lines lw 2.5 lc rgb "#0072B2" title "ED", \
         ds using "t_over_t0":"K_over_K0" with lines lw 2.5 dt 4 lc rgb "#D55E00" title "DSMC", \
         ed using "t_over_t0":"eq18" with lines lw 1.5 dt 2 lc rgb "black" title "Eq. (18)"
  } else {
    plot ed using "t_over_t0":"K_over_K0" with lines lw 2.5 lc rgb "#0072B2" title "ED", \
         ed using "t_over_t0":"eq18" with lines lw 1.5 dt 2 lc rgb "black" title "Eq. (18)"
  }
  unset output
}
