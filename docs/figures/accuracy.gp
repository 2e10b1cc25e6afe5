# gmcc accuracy: relative error of the 3-D mean against a 4096-bit certified reference,
# by route, on the 7-gon of docs/accuracy.md. Written by `gmcc accuracy --plot DIR`;
# to redraw by hand: cd DIR && gnuplot accuracy.gp
if (!exists('png_file')) png_file = 'accuracy.png'
if (!exists('svg_file')) svg_file = 'accuracy.svg'
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set xrange [5e-13:20]
set yrange [5e-18:*]
set xlabel 'polygon width w'
set ylabel 'relative error of the map (0 drawn at 1e-17)'
set key at graph 0.02, graph 0.13 left bottom Left reverse box opaque samplen 3
set grid
set arrow from graph 0, first 2**-53 to graph 1, first 2**-53 nohead dt 4 lc rgb '#888888'
set label '2^{-53}' at graph 0.01, first 2**-53 offset 0, 0.6 textcolor rgb '#888888'
set terminal pngcairo size 800,500 font ',9'
set output png_file
plot \
  'accuracy.dat' index 0 using 1:2 with linespoints lc rgb '#d62728' lw 2 pt 7 title 'closed form, double', \
  'accuracy.dat' index 1 using 1:2 with linespoints lc rgb '#9ecae1' dt 2 pt 9 title 'quadrature n=2', \
  'accuracy.dat' index 2 using 1:2 with linespoints lc rgb '#6baed6' dt 2 pt 9 title 'quadrature n=4', \
  'accuracy.dat' index 3 using 1:2 with linespoints lc rgb '#3182bd' dt 2 pt 9 title 'quadrature n=8', \
  'accuracy.dat' index 4 using 1:2 with linespoints lc rgb '#08519c' dt 2 pt 9 title 'quadrature n=16', \
  'accuracy.dat' index 5 using 1:2 with linespoints lc rgb '#a1d99b' dt 3 pt 13 title 'Monte Carlo N=1e4', \
  'accuracy.dat' index 6 using 1:2 with linespoints lc rgb '#74c476' dt 3 pt 13 title 'Monte Carlo N=1e5', \
  'accuracy.dat' index 7 using 1:2 with linespoints lc rgb '#31a354' dt 3 pt 13 title 'Monte Carlo N=1e6', \
  'accuracy.dat' index 8 using 1:2 with linespoints lc rgb '#006d2c' dt 3 pt 13 title 'Monte Carlo N=1e7', \
  'accuracy.dat' index 9 using 1:2 with linespoints lc rgb '#000000' lw 2 pt 5 title 'closed form, certified', \
  'accuracy.dat' index 10 using 1:2 with linespoints lc rgb '#000000' lw 1 dt 4 pt 0 title 'certified: its bound'
set terminal svg size 800,500 font ',9' dynamic
set output svg_file
replot
set output
