# Chart of instructions per line by command family: the core (pre-framed and
# byte path) against the hand-written and the sscanf/printf yardsticks.
# Called by run_all.sh:
#   gnuplot -e "datafile='families.dat'; outfile='chart.png'" families.gp
# families.dat columns: family, core pre-framed, core byte path, hand-written
# pre-framed, hand-written byte path, sscanf/printf
set terminal pngcairo size 1200,560 font "sans,10" noenhanced
set output outfile
set title "Host (x86-64, gcc 12 -O2): instructions per line by command family, callgrind"
set style data histograms
set style histogram clustered gap 1
set style fill solid 0.85 border -1
set boxwidth 0.9
set logscale y
set yrange [300:*]
set ylabel "instructions per line (log scale)"
set grid ytics
set key top left
set xtics rotate by -30
plot datafile using 2:xtic(1) title "daran-ascii, pre-framed (daran_process_line)" lc rgb "#2a7ab0", \
     '' using 3 title "daran-ascii, byte path (daran_rx_write + daran_poll)" lc rgb "#8cc0e0", \
     '' using 4 title "hand-written yardstick, pre-framed" lc rgb "#4e9a3a", \
     '' using 5 title "hand-written yardstick, byte path (line buffer)" lc rgb "#a6d490", \
     '' using 6 title "sscanf/strtof/printf yardstick" lc rgb "#c8553d"
