#!/bin/sh
# Usage: example_wsad.sh WSAD_BINARY KEY OUTPUT_DIR
# Runs the WSAD example in a virtual X server (Xvfb), holds KEY (w, a, s or d) for one second with real key
# events (xdotool), closes the window with Escape, and checks that the printed final position moved at
# least 10 px in the key's direction and less than 1 px across it.
set -eu
binary=$1 key=$2 out=$3
for tool in xvfb-run xdotool; do
    command -v "$tool" >/dev/null 2>&1 || { echo "FAILED: $tool is not installed (scripts/deps.sh installs it)"; exit 1; }
done
mkdir -p "$out"
log="$out/wsad_key_$key.log"

# Inside the X server: start the example (frame cap as a safety net), wait for its window, focus it, hold
# the key. `xdotool key` (press and release at once) is too short for IsKeyDown to see; hold it instead.
xvfb-run -a -s "-screen 0 1024x768x24" sh -c '
    "$1" --frames 1800 > "$3" 2>&1 & pid=$!
    window=$(timeout 30 xdotool search --sync --onlyvisible --name "^motus - WSAD\$" | head -n 1)
    if [ -z "$window" ]; then echo "the example opened no window"; kill $pid; exit 1; fi
    xdotool windowfocus --sync "$window"
    sleep 0.3
    xdotool keydown "$2"; sleep 1; xdotool keyup "$2"
    sleep 0.3
    xdotool key Escape
    wait $pid' sh "$binary" "$key" "$log"

cat "$log"
# frames=N force=(fx, fy) velocity=(vx, vy) position=(x, y) mass=m
line=$(grep '^frames=' "$log")
x=$(echo "$line" | sed -n 's/.*position=(\([^,]*\), \([^)]*\)).*/\1/p')
y=$(echo "$line" | sed -n 's/.*position=(\([^,]*\), \([^)]*\)).*/\2/p')
awk -v key="$key" -v x="$x" -v y="$y" 'BEGIN {
    dx = x - 400; dy = y - 300
    if (key == "w") { along = -dy; across = dx } else if (key == "s") { along = dy; across = dx }
    else if (key == "a") { along = -dx; across = dy } else { along = dx; across = dy }
    if (across < 0) across = -across
    printf "key %s: moved %.2f px its way, %.2f px across\n", key, along, across
    if (along < 10 || across >= 1) { print "FAILED"; exit 1 }
}'
