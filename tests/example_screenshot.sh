#!/bin/sh
# Usage: example_screenshot.sh WSAD_BINARY PROBE_BINARY PNG
# The demo's headless run: 120 frames of fixed 1/60 s, scripted input (D for 1 s, then S for 0.5 s), a
# screenshot. Checks that the printed state is the one the step and damping give, and that the screenshot
# shows the particle there and no longer at the centre.
set -eu
binary=$1 probe=$2 png=$3
command -v xvfb-run >/dev/null 2>&1 || { echo "FAILED: xvfb-run is not installed (scripts/deps.sh installs it)"; exit 1; }
mkdir -p "$(dirname "$png")"
rm -f "$png"
line=$(xvfb-run -a -s "-screen 0 1024x768x24" "$binary" --frames 120 --fixed-dt --autopilot --screenshot "$png" | grep '^frames=')
echo "$line"
x=$(echo "$line" | sed -n 's/.*position=(\([^,]*\), \([^)]*\)).*/\1/p')
y=$(echo "$line" | sed -n 's/.*position=(\([^,]*\), \([^)]*\)).*/\2/p')
# Expected from the reference's update (v += F/m*h; x += v*h; v *= 0.99) replayed in double.
expected=$(awk 'BEGIN { h = 1/60; x = 400; y = 300; vx = 0; vy = 0
    for (n = 0; n < 120; n++) { ax = (n < 60) ? 50 : 0; ay = (n >= 60 && n < 90) ? 50 : 0
        vx += ax*h; vy += ay*h; x += vx*h; y += vy*h; vx *= 0.99; vy *= 0.99 }
    printf "%.2f %.2f", x, y }')
echo "expected position ($(echo "$expected" | tr ' ' ','))"
awk -v x="$x" -v y="$y" -v e="$expected" 'BEGIN { split(e, p, " ")
    if ((x - p[1])^2 > 0.01^2 + 1e-12 || (y - p[2])^2 > 0.01^2 + 1e-12) { print "FAILED: state differs"; exit 1 } }'
"$probe" "$png" 800 600 "$(printf %.0f "$x")" "$(printf %.0f "$y")" 400 300
