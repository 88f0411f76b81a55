# Chart of the property lookup cost for every row of the current property
# table: left, by row (table order); right, by the length of the path looked
# up (without "axisN."), which is what the core's and the hand-written
# yardstick's hashed lookups follow. The target (issue 13: <= 150 per row)
# is the dashed line; the core's lookup before the perfect hash (1a9450a: 53
# rows, packed segment index) is the grey line, for comparison. Called by
# run_all.sh:
#   gnuplot -e "datafile='lookup.dat'; olddata='lookup-1a9450a.dat'; outfile='chart.png'" lookup.gp
# (olddata optional). lookup.dat columns: row, core, hand-written, sscanf/printf, length, path.
set terminal pngcairo size 1300,480 font "sans,10" noenhanced
set output outfile
set multiplot layout 1,2 title "Host (x86-64, gcc 12 -O2): instructions per property lookup, callgrind"
set grid
set key below
set logscale y
set yrange [30:8000]
set ylabel "instructions per lookup (log scale)"
set xlabel "row of the property table (include/daran_properties.h order)"
set title "by table row"
if (exists("olddata")) {
  plot datafile using 1:2 with linespoints pt 7 ps 0.5 lc rgb "#2a7ab0" title "daran-ascii (perfect hash)", \
       '' using 1:3 with linespoints pt 5 ps 0.5 lc rgb "#4e9a3a" title "hand-written yardstick (hash table)", \
       '' using 1:4 with linespoints pt 13 ps 0.5 lc rgb "#c8553d" title "sscanf/printf yardstick (linear strcmp)", \
       olddata using 1:2 with lines lw 1 lc rgb "#999999" title "daran-ascii at 1a9450a (53 rows)", \
       150 with lines dt 2 lw 2 lc rgb "#000000" title "target: 150"
} else {
  plot datafile using 1:2 with linespoints pt 7 ps 0.5 lc rgb "#2a7ab0" title "daran-ascii (perfect hash)", \
       '' using 1:3 with linespoints pt 5 ps 0.5 lc rgb "#4e9a3a" title "hand-written yardstick (hash table)", \
       '' using 1:4 with linespoints pt 13 ps 0.5 lc rgb "#c8553d" title "sscanf/printf yardstick (linear strcmp)", \
       150 with lines dt 2 lw 2 lc rgb "#000000" title "target: 150"
}
set xlabel "length of the path looked up (bytes, without axisN.)"
set title "by path length"
plot datafile using 5:2 with points pt 7 ps 0.6 lc rgb "#2a7ab0" title "daran-ascii", \
     '' using 5:3 with points pt 5 ps 0.6 lc rgb "#4e9a3a" title "hand-written yardstick", \
     '' using 5:4 with points pt 13 ps 0.6 lc rgb "#c8553d" title "sscanf/printf yardstick", \
     150 with lines dt 2 lw 2 lc rgb "#000000" title "target: 150"
unset multiplot
