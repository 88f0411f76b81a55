# Chart of the property lookup cost for every row of the property table,
# daran-ascii (perfect hash) against the baseline's linear strcmp, with the
# core's lookup before the hash (1a9450a: 53 rows, packed segment index) for
# comparison. Called by run_all.sh:
#   gnuplot -e "datafile='lookup.dat'; olddata='lookup-1a9450a.dat'; outfile='chart.png'" lookup.gp
# (olddata optional).
set terminal pngcairo size 1000,420 font "sans,10" noenhanced
set output outfile
set title "Host (x86-64, gcc -O2): instructions per property lookup, by table row"
set xlabel "row of the property table (include/daran_properties.h order)"
set ylabel "instructions per lookup"
set grid
set key top left
set yrange [0:*]
if (exists("olddata")) {
  plot datafile using 1:2 with linespoints pt 7 ps 0.5 lc rgb "#2a7ab0" title "daran-ascii, perfect hash", \
       '' using 1:3 with linespoints pt 5 ps 0.5 lc rgb "#c8553d" title "baseline (linear strcmp)", \
       olddata using 1:2 with linespoints pt 9 ps 0.6 lc rgb "#7a9a3a" title "daran-ascii at 1a9450a: packed segment index, 53 rows"
} else {
  plot datafile using 1:2 with linespoints pt 7 ps 0.5 lc rgb "#2a7ab0" title "daran-ascii, perfect hash", \
       '' using 1:3 with linespoints pt 5 ps 0.5 lc rgb "#c8553d" title "baseline (linear strcmp)"
}
