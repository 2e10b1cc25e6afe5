# gmcc reproduce gehler-shi: laid out like Finlayson & Hordley (1999) Fig. 5 on measured Gehler-Shi charts
if (!exists('png_file')) png_file = 'gehler-shi-paper.png'
if (!exists('svg_file')) svg_file = 'gehler-shi-paper.svg'
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
  if (term == 1) { set terminal pngcairo size 1500,1040 font ',9'; set output png_file }
  if (term == 2) { set terminal svg size 1500,1040 font 'sans,9'; set output svg_file }
  set multiplot layout 4,3
  set ylabel 'Canon1D yellowish: mean error (deg)'
  plot 'gehler-shi-paper.dat' index 0 using 1:2 with linespoints ls 1 title 'max-area', '' index 0 using 1:3 with linespoints ls 2 title '2-D mean', '' index 0 using 1:4 with linespoints ls 3 title '3-D mean'
  set ylabel 'Canon1D yellowish: mean worst case (deg)'
  plot 'gehler-shi-paper.dat' index 0 using 1:5 with linespoints ls 1 title 'max-area', '' index 0 using 1:6 with linespoints ls 2 title '2-D mean', '' index 0 using 1:7 with linespoints ls 3 title '3-D mean'
  set ylabel 'Canon1D yellowish: mean recovery (deg)'
  plot 'gehler-shi-paper.dat' index 0 using 1:8 with linespoints ls 1 title 'max-area', '' index 0 using 1:9 with linespoints ls 2 title '2-D mean', '' index 0 using 1:10 with linespoints ls 3 title '3-D mean', '' index 0 using 1:11 with linespoints ls 4 title 'grey world', '' index 0 using 1:12 with linespoints ls 5 title 'max-RGB'
  set ylabel 'Canon1D bluish: mean error (deg)'
  plot 'gehler-shi-paper.dat' index 1 using 1:2 with linespoints ls 1 title 'max-area', '' index 1 using 1:3 with linespoints ls 2 title '2-D mean', '' index 1 using 1:4 with linespoints ls 3 title '3-D mean'
  set ylabel 'Canon1D bluish: mean worst case (deg)'
  plot 'gehler-shi-paper.dat' index 1 using 1:5 with linespoints ls 1 title 'max-area', '' index 1 using 1:6 with linespoints ls 2 title '2-D mean', '' index 1 using 1:7 with linespoints ls 3 title '3-D mean'
  set ylabel 'Canon1D bluish: mean recovery (deg)'
  plot 'gehler-shi-paper.dat' index 1 using 1:8 with linespoints ls 1 title 'max-area', '' index 1 using 1:9 with linespoints ls 2 title '2-D mean', '' index 1 using 1:10 with linespoints ls 3 title '3-D mean', '' index 1 using 1:11 with linespoints ls 4 title 'grey world', '' index 1 using 1:12 with linespoints ls 5 title 'max-RGB'
  set ylabel 'Canon5D yellowish: mean error (deg)'
  plot 'gehler-shi-paper.dat' index 2 using 1:2 with linespoints ls 1 title 'max-area', '' index 2 using 1:3 with linespoints ls 2 title '2-D mean', '' index 2 using 1:4 with linespoints ls 3 title '3-D mean'
  set ylabel 'Canon5D yellowish: mean worst case (deg)'
  plot 'gehler-shi-paper.dat' index 2 using 1:5 with linespoints ls 1 title 'max-area', '' index 2 using 1:6 with linespoints ls 2 title '2-D mean', '' index 2 using 1:7 with linespoints ls 3 title '3-D mean'
  set ylabel 'Canon5D yellowish: mean recovery (deg)'
  plot 'gehler-shi-paper.dat' index 2 using 1:8 with linespoints ls 1 title 'max-area', '' index 2 using 1:9 with linespoints ls 2 title '2-D mean', '' index 2 using 1:10 with linespoints ls 3 title '3-D mean', '' index 2 using 1:11 with linespoints ls 4 title 'grey world', '' index 2 using 1:12 with linespoints ls 5 title 'max-RGB'
  set ylabel 'Canon5D bluish: mean error (deg)'
  plot 'gehler-shi-paper.dat' index 3 using 1:2 with linespoints ls 1 title 'max-area', '' index 3 using 1:3 with linespoints ls 2 title '2-D mean', '' index 3 using 1:4 with linespoints ls 3 title '3-D mean'
  set ylabel 'Canon5D bluish: mean worst case (deg)'
  plot 'gehler-shi-paper.dat' index 3 using 1:5 with linespoints ls 1 title 'max-area', '' index 3 using 1:6 with linespoints ls 2 title '2-D mean', '' index 3 using 1:7 with linespoints ls 3 title '3-D mean'
  set ylabel 'Canon5D bluish: mean recovery (deg)'
  plot 'gehler-shi-paper.dat' index 3 using 1:8 with linespoints ls 1 title 'max-area', '' index 3 using 1:9 with linespoints ls 2 title '2-D mean', '' index 3 using 1:10 with linespoints ls 3 title '3-D mean', '' index 3 using 1:11 with linespoints ls 4 title 'grey world', '' index 3 using 1:12 with linespoints ls 5 title 'max-RGB'
  unset multiplot
  set output
}
