# docs/motion.md's plot of the sleigh's knife reaction:
#   build/appell enclose data/scenes/system_chaplygin_sleigh.json --t-end 10 --out OUT
#   gnuplot -e "steps='OUT/steps.csv'" data/motion/chaplygin_sleigh_knife_reaction.gp
# (columns 31 and 32 of steps.csv: knife_reaction_lo, knife_reaction_hi)
set terminal png size 900,500 noenhanced
set output 'data/motion/chaplygin_sleigh_knife_reaction.png'
set datafile separator ','
set xlabel 't (s)'
set ylabel 'lateral force of the knife edge (N)'
set title 'Chaplygin sleigh: the knife reaction, enclosed over every step'
set grid
set key top right
U = sqrt(2.24); J = 0.62; c = 2*0.4*U/J; s0 = atanh(1/U)
lam(t) = 2 * U*tanh(c*t + s0) * U*sqrt(2/J)/cosh(c*t + s0) * 0.3/J
set xrange [0:10]
plot steps every ::1 using (($1+$2)/2):(($31+$32)/2):1:2:31:32 with boxxy fs solid 0.35 lc rgb '#3060c0' title 'enclosure over each step [t0, t1] (appell enclose, interval)',      lam(x) with lines lw 2 lc rgb '#c03020' title 'closed form m u w I_G / (I_G + m a^2)'
