# plot_tradeoff.gp - draws the figures of bench/tradeoff from the files it wrote into OUT:
#   gnuplot -e "out='OUT'" bench/plot_tradeoff.gp
# writes OUT/work_precision.png, OUT/convergence.png and OUT/kepler_energy.png. scripts/tradeoff.sh runs it.
# The curves of each panel come from OUT/plot/lines.gp (generated: which methods run on which problem);
# the layout, axes and colours are here. One colour per algorithm: motus solid, its peer dashed.

if (!exists("out")) out = "tradeoff-out"
load out."/plot/lines.gp"

set terminal pngcairo size 2400,1950 enhanced font "sans,14" linewidth 1.5
set encoding utf8

# ---- one style per algorithm (index = the style number tradeoff.cpp writes) --------------------------
set style line 1 lc rgb "#d62728" lw 2 pt 4 ps 1.1   # explicit Euler (motus explicit_euler, odeint euler)
set style line 2 lc rgb "#ff7f0e" lw 2 pt 6 ps 1.1   # semi-implicit / symplectic Euler
set style line 3 lc rgb "#8c564b" lw 2 pt 8 ps 1.1   # position Verlet
set style line 4 lc rgb "#1f77b4" lw 2 pt 10 ps 1.1  # velocity Verlet (motus, odeint)
set style line 5 lc rgb "#17becf" lw 2 pt 12 ps 1.1  # velocity Verlet, forces reused
set style line 6 lc rgb "#393b79" lw 2 pt 14 ps 1.1  # leapfrog
set style line 7 lc rgb "#6b6ecf" lw 2 pt 14 ps 1.1  # leapfrog, forces reused
set style line 8 lc rgb "#7f7f7f" lw 2 pt 2 ps 1.1   # midpoint
set style line 9 lc rgb "#2ca02c" lw 2 pt 5 ps 1.0   # RK4 (motus, odeint runge_kutta4)
set style line 10 lc rgb "#9467bd" lw 2 pt 7 ps 1.0  # Forest-Ruth
set style line 11 lc rgb "#bcbd22" lw 2 pt 3 ps 1.1  # exact linear-drag step
set style line 12 lc rgb "#004d00" lw 2 pt 9 ps 1.1  # GSL rk4 (step doubling)
set style line 13 lc rgb "#000000" lw 2 pt 11 ps 1.1 # GSL rk8pd
set style line 14 lc rgb "#e377c2" lw 2 pt 13 ps 1.1 # McLachlan's 4th order (motus mclachlan4, odeint sb3a_mclachlan)
set style line 20 lc rgb "#808080" lw 1.5 dt 3       # reference slopes

set logscale xy
set format x "10^{%L}"
set format y "10^{%L}"
set grid xtics ytics mxtics mytics lc rgb "#e8e8e8"
set key off
set yrange [1e-16<*:*<10]

problems = "free_fall gravity_linear_drag harmonic_oscillator damped_oscillator kepler_circular kepler_eccentric projectile_quadratic_drag"
titles = "'free fall (gravity)' 'gravity + linear drag' 'harmonic oscillator' 'damped oscillator (linear drag)' 'Kepler, circular orbit' 'Kepler, e = 0.5' 'projectile, quadratic drag (vs rk8pd reference)'"

# The last cell of a 3x3 layout: the legend alone.
legend_cell(l) = sprintf("unset logscale; unset border; unset tics; unset grid; unset xlabel; unset ylabel; set xrange [0:1]; set yrange [0:1]; set key center center vertical maxrows 22 width -2 samplen 4 spacing 1.1 font 'sans,14'; unset title; plot %s", l)

# ---- work-precision --------------------------------------------------------------------------------
set output out."/work_precision.png"
set multiplot layout 3,3 title sprintf("Work-precision: largest position error against cost (batch of %d particles; motus solid, peers dashed)", particles) font "sans,18"
set xlabel "cost of the whole run (ns per particle)"
set ylabel "largest position error (m)"
do for [i=1:words(problems)] {
    p = word(problems, i)
    set title word(titles, i)." — double"
    eval "plot @wp_".p."_double"
}
set title "Kepler, e = 0.5 — float (motus and odeint)"
plot @wp_kepler_eccentric_float
set title
eval legend_cell(legend_double)
unset multiplot

# ---- convergence -----------------------------------------------------------------------------------
reset_axes = "set logscale xy; set border; set tics; set grid xtics ytics mxtics mytics lc rgb '#e8e8e8'; set key off; set autoscale; set yrange [1e-16<*:*<10]"
@reset_axes
set output out."/convergence.png"
set multiplot layout 3,3 title "Convergence: largest position error against time step (slopes 1, 2 and 4 dotted; motus solid, peers dashed)" font "sans,18"
set xlabel "time step dt (s)"
set ylabel "largest position error (m)"
slope1(x) = 6 * x
slope2(x) = 1 * x**2
slope4(x) = 0.1 * x**4
slopes = "slope1(x) ls 20 notitle, slope2(x) ls 20 notitle, slope4(x) ls 20 notitle"
set label 1 "1" at 0.075, slope1(0.075) offset 0.6,0 textcolor rgb "#606060"
set label 2 "2" at 0.075, slope2(0.075) offset 0.6,0 textcolor rgb "#606060"
set label 3 "4" at 0.075, slope4(0.075) offset 0.6,0 textcolor rgb "#606060"
do for [i=1:words(problems)] {
    p = word(problems, i)
    set title word(titles, i)." — double"
    eval "plot @cv_".p."_double, @slopes"
}
set title "Kepler, e = 0.5 — float (motus and odeint)"
plot @cv_kepler_eccentric_float, @slopes
set title
unset label
eval legend_cell(legend_double.", NaN ls 20 title 'slopes 1, 2, 4'")
unset multiplot

# ---- energy over many Kepler orbits ----------------------------------------------------------------
@reset_axes
set terminal pngcairo size 1600,1000 enhanced font "sans,15" linewidth 1.5
set output out."/kepler_energy.png"
set title sprintf("Energy over %d orbits of the e = 0.5 Kepler problem at dt = 1/60 s (double solid, float dashed)", orbits) font "sans,17"
set xlabel "orbit number (period 2π s)"
set ylabel "largest |E − E_0| / |E_0| during the orbit"
set yrange [1e-17<*:*<100]
set key outside right center vertical samplen 4 spacing 1.2
set label 1 "explicit Euler spirals outwards: E → 0, the orbit unbound" at graph 0.02, graph 0.97 textcolor rgb "#d62728"
set label 2 "symplectic methods: bounded; RK4: drifts in proportion to time" at graph 0.02, graph 0.93
# columns: orbit, then explicit_euler, semi_implicit_euler, velocity_verlet, rk4, forest_ruth in double, then in float
energy_style = "1 2 4 9 10"
energy_title = "'explicit Euler' 'semi-implicit Euler' 'velocity Verlet' 'RK4' 'Forest-Ruth'"
plot for [i=1:5] out."/kepler_energy.dat" using 1:i+1 with lines ls word(energy_style, i)+0 dt 1 title word(energy_title, i)." (double)", \
     for [i=1:5] out."/kepler_energy.dat" using 1:i+6 with lines ls word(energy_style, i)+0 dt 2 title word(energy_title, i)." (float)"
