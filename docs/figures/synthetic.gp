# gmcc reproduce synthetic: laid out like Finlayson & Hordley (1999) Fig. 3
if (!exists('png_file')) png_file = 'synthetic.png'
if (!exists('svg_file')) svg_file = 'synthetic.svg'
set datafile commentschars '#'
set xlabel 'number of surfaces'
set xrange [0.5:11.5]
set yrange [0:*]
set grid lc rgb '#dddddd'
set key top right
set style line 1 lc rgb '#d62728' lw 2 pt 7
set style line 2 lc rgb '#1f77b4' lw 2 pt 5
set style line 3 lc rgb '#2ca02c' lw 2 pt 9
set style line 4 lc rgb '#9467bd' lw 2 pt 11 dt 2
set style line 5 lc rgb '#8c564b' lw 2 pt 13 dt 2
do for [term = 1:2] {
  if (term == 1) { set terminal pngcairo size 1000,1040 font ',9'; set output png_file }
  if (term == 2) { set terminal svg size 1000,1040 font 'sans,9'; set output svg_file }
  set multiplot layout 4,2
  set ylabel 'D75: mean error (deg)'
  plot 'synthetic.dat' index 0 using 1:2 with linespoints ls 1 title 'max-area', '' index 0 using 1:3 with linespoints ls 2 title '2-D mean', '' index 0 using 1:4 with linespoints ls 3 title '3-D mean'
  set ylabel 'D75: mean worst case (deg)'
  plot 'synthetic.dat' index 0 using 1:5 with linespoints ls 1 title 'max-area', '' index 0 using 1:6 with linespoints ls 2 title '2-D mean', '' index 0 using 1:7 with linespoints ls 3 title '3-D mean'
  set ylabel 'D100: mean error (deg)'
  plot 'synthetic.dat' index 1 using 1:2 with linespoints ls 1 title 'max-area', '' index 1 using 1:3 with linespoints ls 2 title '2-D mean', '' index 1 using 1:4 with linespoints ls 3 title '3-D mean'
  set ylabel 'D100: mean worst case (deg)'
  plot 'synthetic.dat' index 1 using 1:5 with linespoints ls 1 title 'max-area', '' index 1 using 1:6 with linespoints ls 2 title '2-D mean', '' index 1 using 1:7 with linespoints ls 3 title '3-D mean'
  set ylabel 'P2856: mean error (deg)'
  plot 'synthetic.dat' index 2 using 1:2 with linespoints ls 1 title 'max-area', '' index 2 using 1:3 with linespoints ls 2 title '2-D mean', '' index 2 using 1:4 with linespoints ls 3 title '3-D mean'
  set ylabel 'P2856: mean worst case (deg)'
  plot 'synthetic.dat' index 2 using 1:5 with linespoints ls 1 title 'max-area', '' index 2 using 1:6 with linespoints ls 2 title '2-D mean', '' index 2 using 1:7 with linespoints ls 3 title '3-D mean'
  set ylabel 'P15000: mean error (deg)'
  plot 'synthetic.dat' index 3 using 1:2 with linespoints ls 1 title 'max-area', '' index 3 using 1:3 with linespoints ls 2 title '2-D mean', '' index 3 using 1:4 with linespoints ls 3 title '3-D mean'
  set ylabel 'P15000: mean worst case (deg)'
  plot 'synthetic.dat' index 3 using 1:5 with linespoints ls 1 title 'max-area', '' index 3 using 1:6 with linespoints ls 2 title '2-D mean', '' index 3 using 1:7 with linespoints ls 3 title '3-D mean'
  unset multiplot
  set output
}
