# Schäfer & Wolf (1995) Fig. 3: Δv_y and Δv_x against v_y^i for one free grain grazing one wall
# grain. Panel (a) is the paper's figure with its robustness checks (dt/100, √β collapse, HKK),
# computed with the default reading of Eq. (2) (F_N = |F_N| of Eq. (1), as printed).
# Panel (b) sets the readings of which F_N enters Coulomb's law side by side, beyond the figure's
# range: Δv_y (solid) and its shear part alone, the integral of Eq. (6) (dashed); the paper's 1/v
# argument is about the shear part; the undamped law (γ_N = 0) for reference. Panel (c): Δv_x.
# Variables set by granrepro: datadir, outbase.
# Parameters set by granrepro: betas
set datafile separator "\t"
set datafile missing "NaN"
set key autotitle columnhead
f3 = datadir.'/fig3.tsv'
hv = datadir.'/high_velocity.tsv'
rx = datadir.'/readings_extended.tsv'
# One table per beta of the run (collapse_beta<beta>.tsv); the paper's are 0.1 and 100.
beta(k) = datadir.'/collapse_beta'.word(betas, k).'.tsv'
bcolors = "#009E73 #CC79A7 #E69F00 #56B4E9"
bsizes = "0.8 0.7"
readings = "magnitude clipped elastic signed"
rcolors = "#0072B2 #E69F00 #009E73 #CC79A7"

do for [fmt in "png pdf"] {
  if (fmt eq "png") { set terminal pngcairo size 1650,540 enhanced font "Sans,11" }
  else { set terminal pdfcairo size 12in,3.9in enhanced font "Sans,9" }
  set output outbase.'.'.fmt
  set multiplot layout 1,3
  set logscale x
  set xlabel "v_y^i  [m/s]"
  set ylabel "velocity change  [m/s]"
  set format x "10^{%L}"
  set grid lc rgb "#dddddd"

  set title "(a) one wall grain, k_N = 2000 N/m, e_N = 0.70"
  set key top left box opaque
  set offsets 0, 0, graph 0.45, 0
  plot f3 using "vy_i":"dvy" with lines lw 2 lc rgb "#0072B2" title "Δv_y", \
       f3 using "vy_i":"dvx" with lines lw 2 dt 2 lc rgb "#D55E00" title "Δv_x", \
       f3 using "vy_i":"dvy_fine" every 2 with points pt 6 ps 0.8 lc rgb "#0072B2" title "Δv_y, Δt/100", \
       for [k=1:words(betas)] beta(k) using "vy_i_scaled":"dvy_scaled" every 3::((k-1)%3) with points pt 2*k ps real(word(bsizes, (k-1)%2+1)) \
         lc rgb word(bcolors, (k-1)%4+1) title "β = ".word(betas, k).", axes / √β", \
       f3 using "vy_i":"dvy_hkk" with lines lw 1.5 dt 4 lc rgb "#555555" title "Δv_y, Hertz-Kuwabara-Kono"

  set title "(b) readings of F_N in Eq. (2): Δv_y (solid), its shear part, Eq. (6) (dashed)"
  set offsets 0, 0, 0, 0
  set logscale y
  set format y "10^{%L}"
  set yrange [1e-3:1]
  set key bottom left box opaque font ",9"
  plot for [i=1:4] rx using "vy_i":(column("dvy_".word(readings, i))) with lines lw 2 lc rgb word(rcolors, i) \
         title word(readings, i).((i == 1) ? " (as printed)" : ""), \
       for [i=1:4] rx using "vy_i":(column("dvy_shear_".word(readings, i))) with lines lw 1.5 dt 2 lc rgb word(rcolors, i) notitle, \
       hv using "vy_i":"dvy_elastic" with lines lw 2 dt 4 lc rgb "#555555" title "undamped law (γ_N = 0)", \
       rx using "vy_i":(($1 > 20) ? 2.0/$1 : NaN) with lines lw 1 dt 3 lc rgb "black" title "∝ 1/v_y^i"

  set title "(c) Δv_x per reading of F_N in Eq. (2)"
  set yrange [1e-4:1]
  plot for [i=1:4] rx using "vy_i":(column("dvx_".word(readings, i))) with lines lw 2 lc rgb word(rcolors, i) \
         title word(readings, i), \
       rx using "vy_i":(($1 > 20) ? 2.0/$1 : NaN) with lines lw 1 dt 3 lc rgb "black" title "∝ 1/v_y^i", \
       rx using "vy_i":(($1 > 20) ? 20.0/$1**2 : NaN) with lines lw 1 dt 5 lc rgb "black" title "∝ 1/v_y^{i 2}"
  unset logscale y
  set format y "%g"
  unset multiplot
  unset output
}
