# plot_collisions.gp - draws the figure of bench/collisions from the files it wrote into OUT:
#   gnuplot -e "out='OUT'" bench/plot_collisions.gp
# writes OUT/collisions.png: ns per particle-step against N, log-log, one line per engine; four panels (2D and
# 3D, drop and pile). Every curve is one file of OUT/plot/ (DIMSd_SCENE_ENGINE.dat: N, ns per particle-step);
# OUT/plot/info.gp lists them. scripts/collisions.sh runs it and copies the figure to docs/collisions.png.

if (!exists("out")) out = "collisions-out"
curves_2d_drop = ""
curves_2d_pile = ""
curves_3d_drop = ""
curves_3d_pile = ""
machine = ""
n_min = 500
n_max = 2e6
load out."/plot/info.gp"

curve(key, engine) = sprintf("%s/plot/%s_%s.dat", out, key, engine)
colour(e) = e eq "motus" ? "#1f77b4" : e eq "motus-1substep" ? "#7fb8e0" : e eq "motus-1x1" ? "#17becf" : e eq "box2d" ? "#d62728" : e eq "chipmunk" ? "#2ca02c" : \
            e eq "bullet" ? "#ff7f0e" : e eq "brute" ? "#7f7f7f" : "#9467bd"
point(e) = e eq "motus" ? 7 : e eq "motus-1substep" ? 6 : e eq "motus-1x1" ? 4 : e eq "box2d" ? 5 : e eq "chipmunk" ? 9 : e eq "bullet" ? 11 : 13
width(e) = e eq "motus" ? 3 : 2

set terminal pngcairo size 1400,1000 font "sans,11"
set output out."/collisions.png"
set encoding utf8
set logscale xy
set format x "10^{%L}"
set format y "%g"
set xrange [n_min:n_max]
set grid xtics ytics mxtics mytics lc rgb "#e8e8e8"
set xlabel "balls N"
set ylabel "ns per particle-step (one frame of 1/60 s)"
set key top left Left reverse samplen 3 font "sans,10" opaque
set multiplot layout 2,2 title "Balls in a box: time per particle-step (median over the measured frames)\n{/*0.8 ".machine."}" font "sans,13"
do for [key in "2d_drop 2d_pile 3d_drop 3d_pile"] {
    list = value("curves_".key)
    set title (key[1:2] eq "2d" ? "2D" : "3D").", ".(key[4:] eq "drop" ? "drop (balls falling in, from the release)" : "pile (packed, at rest on the floor)")
    if (words(list) > 0) {
        plot for [i=1:words(list)] curve(key, word(list, i)) using 1:2 with linespoints \
             lc rgb colour(word(list, i)) lw width(word(list, i)) pt point(word(list, i)) ps 1.2 title word(list, i)
    } else {
        set label 1 "no data" at graph 0.5, 0.5 center
        plot NaN notitle
        unset label 1
    }
}
unset multiplot
