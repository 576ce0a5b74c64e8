# Luding (1998) Fig. 11: the run of Fig. 10 at the paper's instants (fig11_selection.tsv: t, C/N,
# the common colour range); each disk coloured by its collision frequency N_c over the last
# Δt = t/2 on one logarithmic scale for all panels (viridis: dark = few, yellow = many collisions;
# the paper used red-to-blue). Disks with N_c = 0 get the bottom colour.
# Each title gives, beside ours, the paper's C/N where the paper has a snapshot at that time: Fig.
# 11 is captioned "t = 0.640 s, C/N = 39" and "t = 10.24 s, C/N = 183" (Section 4.2); our later
# snapshots have no paper panel. A script reads no claim: the same numbers are in
# expected/cluster-growth.toml, claims cn_39_at_0.64s (paper = 39.0) and cn_183_at_10.24s
# (paper = 183.0).
# Variables set by granrepro: datadir, outbase.
paper_t = "0.64 10.24"
paper_cn = "39 183"
# The paper's C/N at our time t (a text), or "" where the paper has no snapshot (times agree to 0.1 %).
paper_at(t) = sum [j=1:words(paper_t)] (abs(real(t) / real(word(paper_t, j)) - 1) < 1e-3 ? j : 0)
set datafile separator "\t"
sel = datadir.'/fig11_selection.tsv'
# Row k of the selection: the panel's t and C/N; the colour range is in row 1.
stats sel using (0) skip 1 nooutput  # every row, whatever it holds
n = STATS_records
array tts[n]
array ccs[n]
do for [k=1:n] {
  stats sel using (tts[k] = sprintf("%.4g", column(1)), ccs[k] = sprintf("%.0f", column(2)), 0) skip 1 every ::(k-1)::(k-1) nooutput
}
tt(k) = tts[k]
cc(k) = ccs[k]
stats sel using (lo = column(3), hi = column(4), 0) skip 1 every ::0::0 nooutput
# The box: the largest coordinate of the first snapshot, rounded up.
stats datadir.'/snapshot_0.tsv' using ($1 > $2 ? $1 : $2) skip 1 nooutput
L = ceil(STATS_max)
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
    j = paper_at(tt(k))
    set title sprintf("t = %s s, C/N = %s", tt(k), cc(k)).(j > 0 ? sprintf("  (paper: C/N = %s)", word(paper_cn, j)) : "")
    plot f using 1:2:(0.5):($3 > lo ? $3 : lo) skip 1 with circles fs solid noborder lc palette
  }
  unset multiplot
  unset output
}
