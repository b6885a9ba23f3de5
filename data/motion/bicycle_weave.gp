# docs/motion.md's plot of the nonlinear Whipple bicycle's lean, enclosed over every step:
#   build/appell enclose data/scenes/system_whipple_bicycle_weave_5.json --t-end 10 --out OUT5
#   build/appell enclose data/scenes/system_whipple_bicycle_weave_3.json --t-end 10 --max-seconds 1500 --out OUT3
#   gnuplot -e "five='OUT5/steps.csv'; three='OUT3/steps.csv'" data/motion/bicycle_weave.gp
# (columns 31 and 32 of steps.csv: phi_over_lo, phi_over_hi, the lean over [t0, t1])
set terminal png size 900,700 noenhanced
set output 'data/motion/bicycle_weave.png'
set datafile separator ','
set multiplot layout 2,1
set xlabel 't (s)'
set ylabel 'lean phi (rad)'
set title 'Whipple bicycle, nonlinear, lean rate 0.5 rad/s at t = 0: the lean enclosed over every step'
set grid
set key bottom left
set xrange [0:10]
plot five every ::1 using (($1+$2)/2):(($31+$32)/2):1:2:31:32 with boxxy fs solid 0.5 lc rgb '#3060c0' title '5 m/s (weave -0.78 +- 4.46i linearized): decays', \
     three every ::1 using (($1+$2)/2):(($31+$32)/2):1:2:31:32 with boxxy fs solid 0.5 lc rgb '#c03020' title '3 m/s (weave 1.71 +- 2.32i): grows; the enclosure stops at 1.638 s'
set title '5 m/s: the largest |lean| over each step (upper bound), log scale'
set ylabel '|phi| (rad)'
set logscale y
set format y '%.0e'
set key top right
plot five every ::1 using (($1+$2)/2):((-$31 > $32) ? -$31 : $32) with lines lw 1.5 lc rgb '#3060c0' title 'max |phi| over [t0, t1]'
unset multiplot
