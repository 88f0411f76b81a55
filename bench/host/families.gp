# Chart of core instructions per line by command family, daran-ascii against
# the baseline yardstick. Called by run_all.sh:
#   gnuplot -e "datafile='families.dat'; outfile='chart.png'" families.gp
set terminal pngcairo size 1000,520 font "sans,10" noenhanced
set output outfile
set title "Host (x86-64, gcc -O2): instructions per line, callgrind"
set style data histograms
set style histogram clustered gap 1
set style fill solid 0.85 border -1
set boxwidth 0.9
set logscale y
set yrange [50:*]
set ylabel "instructions per line (log scale)"
set grid ytics
set key top left
set xtics rotate by -30
plot datafile using 2:xtic(1) title "daran-ascii" lc rgb "#2a7ab0", \
     '' using 3 title "baseline (sscanf/strtof/printf)" lc rgb "#c8553d"
