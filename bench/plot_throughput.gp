# plot_throughput.gp - draws the figures of bench/throughput from the files its report wrote into OUT:
#   gnuplot -e "out='OUT'" bench/plot_throughput.gp
# writes OUT/throughput.png (gravity + damping in the four configurations, with the memory bound),
# OUT/throughput_scenes.png (every scene: motus semi-implicit Euler and rk4, the hand-written loop, motus with
# walls nobody reaches) and, when the -O2
# build was measured, OUT/throughput_o2.png. scripts/throughput.sh runs it. Every curve is one file of
# OUT/plot/ (BUILD_DIMSd_PRECISION_SCENE_METHOD.dat: N, median, min, max ns per particle-step).

if (!exists("out")) out = "throughput-out"
has_native = 0
has_o2 = 0
machine_native = ""
machine_o2 = ""
load out."/plot/info.gp"

curve(build, dims, precision, scene, method) = sprintf("%s/plot/%s_%dd_%s_%s_%s.dat", out, build, dims, precision, scene, method)

set encoding utf8
set logscale xy
set format x "10^{%L}"
set format y "%g"
set xrange [700:1.4e7]
set grid xtics ytics mxtics mytics lc rgb "#e8e8e8"
set xlabel "particles N"
set ylabel "ns per particle-step"
set key top left Left reverse samplen 3 spacing 1.05 font "sans,11" opaque

# ---- one style per method --------------------------------------------------------------------------------
set style line 1 lc rgb "#d62728" lw 2.5 pt 5 ps 0.9    # textbook loop
set style line 2 lc rgb "#7f7f7f" lw 2 dt 2 pt 6 ps 1.0 # hand-written loop
set style line 14 lc rgb "#d62728" lw 1.5 pt 4 ps 1.1   # the textbook loop written by hand
set style line 3 lc rgb "#1f77b4" lw 3 pt 7 ps 0.9      # motus
set style line 4 lc rgb "#9ecae1" lw 2.5 pt 9 ps 0.9    # motus + walls nobody reaches (the kernel for any scene)
set style line 5 lc rgb "#9467bd" lw 2.5 pt 11 ps 0.9   # motus, 2 threads
set style line 6 lc rgb "#2ca02c" lw 2.5 pt 13 ps 0.9   # odeint symplectic_euler
set style line 7 lc rgb "#98df8a" lw 2 pt 12 ps 0.9     # odeint velocity_verlet
set style line 10 lc rgb "#000000" lw 2.5               # the bound: in-place read-modify-write
set style line 11 lc rgb "#000000" lw 1.5 dt 2          # the bound on 2 threads
set style line 12 lc rgb "#8c564b" lw 1.2 dt 3          # copy
set style line 13 lc rgb "#bcbd22" lw 1.2 dt 4          # triad

# ---- 1: gravity + damping, four configurations, native build -----------------------------------------
if (has_native) {
    set terminal pngcairo size 2000,1500 enhanced font "sans,13" linewidth 1.2
    set output out."/throughput.png"
    set multiplot layout 2,2 title "ns per particle-step against N: gravity + damping (odeint: gravity alone), -O3 -march=native, median of the rounds\n".machine_native font "sans,16"
    set yrange [0.1:1000] # room above the data for the (opaque) legend: it hid the textbook point at N = 5000
    do for [dims=2:3] {
        do for [p=1:2] {
            precision = word("float double", p)
            set title sprintf("%dD %s", dims, precision) font "sans,15"
            plot curve("native", dims, precision, "gravity_damping", "textbook") using 1:2 with linespoints ls 1 title "textbook path (motus\\_particle\\_*, N = 5000)", \
                 curve("native", dims, precision, "gravity_damping", "textbook_hand") using 1:2 with points ls 14 title "the same calls written by hand, no checks (N = 5000)", \
                 curve("native", dims, precision, "gravity_damping", "general") using 1:2 with linespoints ls 4 title "motus + walls nobody reaches (kernel for any scene)", \
                 curve("native", dims, precision, "gravity", "odeint_symplectic_euler") using 1:2 with linespoints ls 6 title "odeint symplectic\\_euler (gravity)", \
                 curve("native", dims, precision, "gravity", "odeint_velocity_verlet") using 1:2 with linespoints ls 7 title "odeint velocity\\_verlet (gravity)", \
                 curve("native", dims, precision, "gravity_damping", "hand") using 1:2 with linespoints ls 2 title "hand-written loop", \
                 curve("native", dims, precision, "gravity_damping", "motus") using 1:2 with linespoints ls 3 title "motus", \
                 curve("native", dims, precision, "gravity_damping", "motus_threads") using 1:2 with linespoints ls 5 title "motus, 2 threads", \
                 curve("native", dims, precision, "memory", "copy") using 1:2 with lines ls 12 title "copy (STREAM), same bytes", \
                 curve("native", dims, precision, "memory", "triad") using 1:2 with lines ls 13 title "triad (STREAM), same bytes", \
                 curve("native", dims, precision, "memory", "rmw_threads") using 1:2 with lines ls 11 title "bound, 2 threads", \
                 curve("native", dims, precision, "memory", "rmw") using 1:2 with lines ls 10 title "bound: x, v read and written in place"
        }
    }
    unset multiplot
    set autoscale y

    # ---- 2: every scene, float, native build: solid 2D, dashed 3D ------------------------------------
    set terminal pngcairo size 3000,1400 enhanced font "sans,13" linewidth 1.2
    set output out."/throughput_scenes.png"
    scenes = "drift gravity gravity_damping gravity_linear_drag mass_forces springs attractor"
    titles = "'drift only' 'gravity' 'gravity + damping' 'gravity + linear drag' 'per-particle mass + user forces' 'springs: a chain of N (2D only, coupled)' 'attractor (Kepler)'"
    set multiplot layout 2,4 title "Each scene, float, -O3 -march=native: motus_step (semi-implicit Euler, and rk4) against the hand-written loop for exactly that scene (2D solid, 3D dashed)\n".machine_native font "sans,16"
    do for [i=1:7] {
        scene = word(scenes, i)
        set title word(titles, i) font "sans,15"
        two = sprintf("curve('native', 2, 'float', '%s', 'general') using 1:2 with linespoints ls 4 title 'motus + walls nobody reaches, 2D', ", scene) . \
              sprintf("curve('native', 2, 'float', '%s', 'motus_rk4') using 1:2 with linespoints ls 5 title 'motus rk4, 2D', ", scene) . \
              sprintf("curve('native', 2, 'float', '%s', 'hand') using 1:2 with linespoints ls 2 title 'hand-written loop, 2D', ", scene) . \
              sprintf("curve('native', 2, 'float', '%s', 'motus') using 1:2 with linespoints ls 3 title 'motus, 2D', ", scene) . \
              "curve('native', 2, 'float', 'memory', 'rmw') using 1:2 with lines ls 10 title 'bound (2D)'"
        three = sprintf(", curve('native', 3, 'float', '%s', 'general') using 1:2 with lines ls 4 dt 2 lw 1.5 title '3D: dashed', ", scene) . \
                sprintf("curve('native', 3, 'float', '%s', 'hand') using 1:2 with lines ls 2 dt 3 lw 1.5 notitle, ", scene) . \
                sprintf("curve('native', 3, 'float', '%s', 'motus') using 1:2 with lines ls 3 dt 2 lw 1.5 notitle, ", scene) . \
                "curve('native', 3, 'float', 'memory', 'rmw') using 1:2 with lines ls 10 dt 2 lw 1.5 notitle"
        eval "plot ".two.(scene eq "springs" ? "" : three)
    }
    unset multiplot
}

# ---- 3: the -O2 build (no -march: the flags many games ship with) ---------------------------------------
if (has_o2) {
    set terminal pngcairo size 2000,800 enhanced font "sans,13" linewidth 1.2
    set output out."/throughput_o2.png"
    set multiplot layout 1,2 title "gravity + damping at -O2 (no -march): motus\\_step against what gcc makes of plain loops\n".machine_o2 font "sans,16"
    set yrange [0.1:100] # room for the legend above the textbook point
    do for [dims=2:3] {
        set title sprintf("%dD float", dims) font "sans,15"
        plot curve("o2", dims, "float", "gravity_damping", "textbook") using 1:2 with linespoints ls 1 title "textbook path (motus\\_particle\\_*, N = 5000), -O2", \
             curve("o2", dims, "float", "gravity_damping", "textbook_hand") using 1:2 with points ls 14 title "the same calls written by hand, no checks, -O2", \
             curve("o2", dims, "float", "gravity_damping", "general") using 1:2 with linespoints ls 4 title "motus + walls nobody reaches, -O2", \
             curve("o2", dims, "float", "gravity_damping", "hand") using 1:2 with linespoints ls 2 title "hand-written loop, -O2", \
             curve("o2", dims, "float", "gravity_damping", "motus") using 1:2 with linespoints ls 3 title "motus, -O2", \
             (has_native ? curve("native", dims, "float", "gravity_damping", "motus") : "/dev/null") using 1:2 with lines ls 3 lw 1.5 dt 3 title "motus, -O3 -march=native", \
             curve("o2", dims, "float", "memory", "rmw") using 1:2 with lines ls 10 title "bound, -O2"
    }
    unset multiplot
    set autoscale y
}
