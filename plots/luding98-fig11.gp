# Luding (1998) Fig. 11: the run of Fig. 10 at the paper's instants (fig11_selection.tsv: t, C/N,
# the common colour range); each disk coloured by its collision frequency N_c over the last
# Δt = t/2 on one logarithmic scale for all panels (viridis: dark = few, yellow = many collisions;
# the paper used red-to-blue). Disks with N_c = 0 get the bottom colour.
# Variables set by granrepro: datadir, outbase.
set datafile separator "\t"
sel = datadir.'/fig11_selection.tsv'
n = int(system("awk '/^#/{u++; next} END{print (NR-u)-1}' ".sel))
tt(k) = system(sprintf("awk -F'\t' '/^#/{u++; next} (NR-u)==%d{printf \"%%.4g\", $1}' ", k+1).sel)
cc(k) = system(sprintf("awk -F'\t' '/^#/{u++; next} (NR-u)==%d{printf \"%%.0f\", $2}' ", k+1).sel)
lo = real(system("awk -F'\t' '/^#/{u++; next} (NR-u)==2{print $3}' ".sel))
hi = real(system("awk -F'\t' '/^#/{u++; next} (NR-u)==2{print $4}' ".sel))
L = real(system("awk -F'\t' '/^#/{u++; next} (NR-u)>1{if($1>m)m=$1; if($2>m)m=$2}END{print m}' ".datadir.'/snapshot_0.tsv'))
L = ceil(L)
nc = (n+1)/2
set palette defined (0 '#440154', 1 '#482878', 2 '#3E4989', 3 '#31688E', 4 '#26828E', 5 '#1F9E89', 6 '#35B779', 7 '#6DCD59', 8 '#B4DE2C', 9 '#FDE725')
do for [fmt in "png pdf"] {
  if (fmt eq "png") { set terminal pngcairo size 700*nc,1300 enhanced font "Sans,11" }
  else { set terminal pdfcairo size 5*nc,9.3 enhanced font "Sans,9" }
  set output outbase.'.'.fmt
  set multiplot layout 2,nc
  set size ratio -1
  set xrange [0:L]
  set yrange [0:L]
  set xlabel "x/d"
  set ylabel "y/d"
  set logscale cb
  set format cb "10^{%L}"
  set cblabel "N_c [s^{-1}] (same scale in every panel)"
  set cbrange [lo:hi]
  unset key
  do for [k=1:n] {
    f = datadir.'/snapshot_'.(k-1).'.tsv'
    set title sprintf("t = %s s, C/N = %s", tt(k), cc(k))
    plot f using 1:2:(0.5):($3 > lo ? $3 : lo) skip 1 with circles fs solid noborder lc palette
  }
  unset multiplot
  unset output
}
