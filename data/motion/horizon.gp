# docs/motion.md's long-horizon plots, from the horizon.csv files of several runs of
# `appell horizon` (one run per scalar or pair of scalars, as the study ran them):
#   gnuplot -e "series='A/horizon.csv:double A/horizon.csv:long-double B/horizon.csv:dd'; \
#               name='euler_body'; out='data/motion/euler_body_horizon.png'" data/motion/horizon.gp
# Each entry FILE:SCALAR draws that scalar's error (solid) and its Brouwer line (dashed, the same
# colour) against the time in periods (column `periods`; for a scene whose period `horizon` does
# not know, give it: -e "period=2.31251" divides column `t` by it), on log-log axes.
set terminal pngcairo size 1000,560 noenhanced font ',11'
set output out
set datafile separator ','
set datafile columnheaders
set logscale xy
set autoscale xfix
set format y '%.0e'
set mxtics 10
set xlabel 'time (periods)'
set ylabel 'error against the 256-bit reference'
set title name.": error against time (solid); Brouwer's law, eps sqrt(steps), dashed"
set grid
set key outside right top vertical Left reverse
file(s) = s[1:strstrt(s, ':') - 1]
scalar(s) = s[strstrt(s, ':') + 1:]
n = words(series)
if (!exists("period")) period = 0
x(dummy) = period > 0 ? column('t') / period : column('periods')
plot for [i = 1:n] file(word(series, i)) using (x(0) > 0 ? x(0) : 1/0):(column('error_'.scalar(word(series, i))) > 0 ? column('error_'.scalar(word(series, i))) : 1/0) with lines lw 2 lc i title scalar(word(series, i)), \
     for [i = 1:n] file(word(series, i)) using (x(0) > 0 ? x(0) : 1/0):(column('brouwer_'.scalar(word(series, i)))) with lines dt 2 lw 1.5 lc i notitle, \
     NaN with lines dt 2 lw 1.5 lc rgb 'black' title "dashed: Brouwer's law"
