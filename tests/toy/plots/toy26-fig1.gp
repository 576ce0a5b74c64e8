# The toy's figure (tests/toy/): measured e_N against the e_N asked for.
# Variables set by granrepro: datadir, outbase.
set datafile separator "\t"
set key autotitle columnhead
do for [fmt in "png pdf"] {
  if (fmt eq "png") { set terminal pngcairo size 600,450 } else { set terminal pdfcairo size 5in,3.75in }
  set output outbase.'.'.fmt
  set xlabel "e_N of Eq. (4)"
  set ylabel "e_N measured"
  plot datadir.'/toy.tsv' using 1:2 with points pt 7 title "measured", x with lines title "Eq. (4)"
}
