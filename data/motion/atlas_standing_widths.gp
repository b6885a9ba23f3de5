# docs/contacts.md's plot of the standing humanoid's enclosure: the widest of its 54 state
# components at each step's end, on the torques that hold it at rest, held by joint stiffness, and
# held by the controller that puts every mode of the rest at 10 rad/s (docs/contacts.md):
#   build/appell enclose data/scenes/urdf_atlas_standing.json --t-end 0.3 --out OUT0
#   build/appell enclose data/scenes/urdf_atlas_standing_held.json --t-end 0.3 --out OUT1
#   scripts/standing_modes.py build/appell data/scenes/urdf_atlas_standing.json MODES.json 10
#   build/appell enclose MODES.json --t-end 0.3 --out OUT2
#   gnuplot -e "torques='OUT0/steps.csv'; held='OUT1/steps.csv'; modes='OUT2/steps.csv'" data/motion/atlas_standing_widths.gp
# (columns 3 to 110 of steps.csv: the state's lo and hi at t1, 54 components)
set terminal png size 900,520 noenhanced
set output 'data/motion/atlas_standing_widths.png'
set datafile separator ','
set xlabel 't (s)'
set ylabel 'widest state component (rad, m, rad/s)'
set title 'Atlas standing on both soles, enclosed in interval: the widest state component at each step'
set grid
set xrange [0:0.3]
set logscale y
set format y '%.0e'
set key top left Left reverse opaque
set yrange [1e-11:4e-6]
widest(f) = sprintf("< awk -F, 'NR > 1 { w = 0; for (i = 3; i < 110; i += 2) if ($(i + 1) - $i > w) w = $(i + 1) - $i; print $2, w }' %s", f)
set datafile separator whitespace
plot widest(torques) using 1:2 with linespoints pt 7 ps 0.5 lc rgb '#c03020' title 'on the torques that hold it at rest (urdf_atlas_standing): grows as exp(30.9 t)', \
     widest(held) using 1:2 with linespoints pt 7 ps 0.5 lc rgb '#3060c0' title 'held by joint stiffness (urdf_atlas_standing_held): one mode grows as exp(3.3 t)', \
     widest(modes) using 1:2 with linespoints pt 7 ps 0.5 lc rgb '#20a040' title 'every mode at 10 rad/s (scripts/standing_modes.py): stable, shorter steps'
