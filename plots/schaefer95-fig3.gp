# Schäfer & Wolf (1995) Fig. 3: Δv_y and Δv_x against v_y^i for one free grain grazing one wall
# grain. Panel (a) is the paper's figure with its robustness checks (dt/100, √β collapse);
# panel (b) extends the abscissa to show the 1/v tail of the elastic law and the plateau of the
# damped one. Variables set by granrepro: datadir, outbase.
set datafile separator "\t"
set datafile missing "NaN"
set key autotitle columnhead
f3 = datadir.'/fig3.tsv'
hv = datadir.'/high_velocity.tsv'
b01 = datadir.'/collapse_beta0.1.tsv'
b100 = datadir.'/collapse_beta100.tsv'

do for [fmt in "png pdf"] {
  if (fmt eq "png") { set terminal pngcairo size 1200,520 enhanced font "Sans,11" }
  else { set terminal pdfcairo size 9in,3.9in enhanced font "Sans,9" }
  set output outbase.'.'.fmt
  set multiplot layout 1,2
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
       b01 using "vy_i_scaled":"dvy_scaled" every 3 with points pt 2 ps 0.8 lc rgb "#009E73" title "β = 0.1, axes / √β", \
       b100 using "vy_i_scaled":"dvy_scaled" every 3::1 with points pt 4 ps 0.7 lc rgb "#CC79A7" title "β = 100, axes / √β", \
       f3 using "vy_i":"dvy_hkk" with lines lw 1.5 dt 4 lc rgb "#555555" title "Δv_y, Hertz-Kuwabara-Kono"

  set title "(b) beyond the figure: 1/v tail and the damped plateau"
  set offsets 0, 0, 0, 0
  set logscale y
  set format y "10^{%L}"
  set key bottom left box opaque
  plot hv using "vy_i":"dvy" with lines lw 2 lc rgb "#0072B2" title "Δv_y, e_N = 0.70", \
       hv using "vy_i":"dvx" with lines lw 2 dt 2 lc rgb "#D55E00" title "Δv_x, e_N = 0.70", \
       hv using "vy_i":"dvy_elastic" with lines lw 2 lc rgb "#009E73" title "Δv_y, γ_N = 0", \
       hv using "vy_i":(($1 > 20) ? 2.0/$1 : 1/0) with lines lw 1 dt 3 lc rgb "black" title "∝ 1/v_y^i"
  unset logscale y
  set format y "%g"
  unset multiplot
  unset output
}
