#!/bin/sh
# Usage: example_orbits.sh ORBITS_BINARY MODE OUTPUT_DIR
# Runs the orbits example in a virtual X server (Xvfb) and checks what it prints (and, headless, draws).
#   headless  300 and then 600 frames (2.5 and 5 orbits at T/120), the second with a screenshot. Checks that
#             explicit Euler gains energy (its energy error is positive and grows from frame 300 to 600) and
#             ends more than 10 times further off than every symplectic method (semi-implicit Euler,
#             velocity Verlet, Forest-Ruth, McLachlan); that RK4, Forest-Ruth and McLachlan end closer to the
#             exact position than semi-implicit Euler; and that the screenshot is 800x600 with each method's colour drawn in the
#             orbit view (above the legend).
#   key_space holds SPACE with real key events (xdotool), then Escape: the run must end paused, with paused
#             frames counted and fewer steps than frames.
#   key_up    holds UP, then Escape: the step must have doubled once, from T/120 to T/60.
set -eu
binary=$1 mode=$2 out=$3
for tool in xvfb-run python3; do
    command -v "$tool" >/dev/null 2>&1 || { echo "FAILED: $tool is not installed (scripts/deps.sh installs it)"; exit 1; }
done
mkdir -p "$out"

# field NAME LINE: the value of NAME=value in LINE.
field() { echo "$2" | tr ' ' '\n' | sed -n "s/^$1=//p"; }
method_line() { grep "^method=$1 " "$2" || { echo "FAILED: no line for $1 in $2" >&2; return 1; }; }

case "$mode" in
headless)
    png="$out/orbits.png"
    rm -f "$png"
    xvfb-run -a -s "-screen 0 1024x768x24" "$binary" --frames 300 > "$out/orbits_300.log"
    xvfb-run -a -s "-screen 0 1024x768x24" "$binary" --frames 600 --screenshot "$png" > "$out/orbits_600.log"
    cat "$out/orbits_600.log"
    euler_300=$(field energy_error "$(method_line explicit_euler "$out/orbits_300.log")")
    euler=$(field energy_error "$(method_line explicit_euler "$out/orbits_600.log")")
    semi=$(field energy_error "$(method_line semi_implicit_euler "$out/orbits_600.log")")
    verlet=$(field energy_error "$(method_line velocity_verlet "$out/orbits_600.log")")
    ruth=$(field energy_error "$(method_line forest_ruth "$out/orbits_600.log")")
    mclachlan=$(field energy_error "$(method_line mclachlan4 "$out/orbits_600.log")")
    semi_x=$(field position_error "$(method_line semi_implicit_euler "$out/orbits_600.log")")
    rk4_x=$(field position_error "$(method_line rk4 "$out/orbits_600.log")")
    ruth_x=$(field position_error "$(method_line forest_ruth "$out/orbits_600.log")")
    mclachlan_x=$(field position_error "$(method_line mclachlan4 "$out/orbits_600.log")")
    awk -v e300="$euler_300" -v e="$euler" -v s="$semi" -v v="$verlet" -v f="$ruth" -v m="$mclachlan" \
        -v sx="$semi_x" -v rx="$rk4_x" -v fx="$ruth_x" -v mx="$mclachlan_x" 'function abs(x) { return x < 0 ? -x : x }
    BEGIN {
        failed = 0
        printf "explicit_euler energy error: %g at frame 300, %g at frame 600\n", e300, e
        if (!(e300 > 0 && e > e300)) { print "FAILED: explicit Euler should gain energy, more and more"; failed = 1 }
        worst = abs(s); if (abs(v) > worst) worst = abs(v); if (abs(f) > worst) worst = abs(f); if (abs(m) > worst) worst = abs(m)
        printf "largest symplectic energy error %g: explicit Euler is %.0fx that\n", worst, abs(e) / worst
        if (!(abs(e) > 10 * worst)) { print "FAILED: explicit Euler should be > 10x off in energy"; failed = 1 }
        printf "position errors: semi_implicit_euler %g, rk4 %g, forest_ruth %g, mclachlan4 %g\n", sx, rx, fx, mx
        if (!(rx < sx && fx < sx && mx < sx)) { print "FAILED: RK4, Forest-Ruth and McLachlan should end closer than semi-implicit Euler"; failed = 1 }
        exit failed
    }'
    # The colours come from the program's own lines (rgb=R,G,B); the legend starts at y = 424.
    python3 - "$png" 424 $(sed -n 's/^method=\([a-z_0-9]*\) .* rgb=\([0-9,]*\).*/\1=\2/p' "$out/orbits_600.log") <<'EOF'
import struct, sys, zlib

path, view_bottom, wanted = sys.argv[1], int(sys.argv[2]), sys.argv[3:]
data = open(path, "rb").read()
assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
pos, idat, width = 8, b"", 0
while pos < len(data):
    length, kind = struct.unpack(">I4s", data[pos:pos + 8])
    body = data[pos + 8:pos + 8 + length]
    if kind == b"IHDR":
        width, height, depth, colour_type, _, _, interlace = struct.unpack(">IIBBBBB", body)
        assert depth == 8 and colour_type in (2, 6) and interlace == 0, "unexpected PNG format"
        channels = 4 if colour_type == 6 else 3
    elif kind == b"IDAT":
        idat += body
    pos += 12 + length
if (width, height) != (800, 600):
    sys.exit("FAILED: %s is %dx%d, expected 800x600" % (path, width, height))

raw, stride = zlib.decompress(idat), width * channels
rows, previous = [], bytearray(stride)
for y in range(height):  # undo the per-row PNG filters
    kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
    for i in range(stride):
        left = line[i - channels] if i >= channels else 0
        up_left = previous[i - channels] if i >= channels else 0
        up = previous[i]
        if kind == 1: line[i] = (line[i] + left) & 255
        elif kind == 2: line[i] = (line[i] + up) & 255
        elif kind == 3: line[i] = (line[i] + (left + up) // 2) & 255
        elif kind == 4:
            p = left + up - up_left
            pa, pb, pc = abs(p - left), abs(p - up), abs(p - up_left)
            line[i] = (line[i] + (left if pa <= pb and pa <= pc else up if pb <= pc else up_left)) & 255
    rows.append(line)
    previous = line

colours = [(item.split("=")[0], tuple(int(c) for c in item.split("=")[1].split(","))) for item in wanted]
counts = {name: 0 for name, _ in colours}
for y in range(37, view_bottom):  # below the top bar, above the legend
    row = rows[y]
    for x in range(0, stride, channels):
        pixel = row[x:x + 3]
        if max(pixel) < 100:
            continue  # background, faint trails
        for name, rgb in colours:
            if all(abs(pixel[c] - rgb[c]) <= 12 for c in range(3)):
                counts[name] += 1
failed = False
for name, rgb in colours:
    print("%s: %d pixels of rgb%s in the orbit view" % (name, counts[name], rgb))
    if counts[name] < 20:
        print("FAILED: %s is not drawn" % name)
        failed = True
sys.exit(1 if failed else 0)
EOF
    ;;
key_space | key_up)
    command -v xdotool >/dev/null 2>&1 || { echo "FAILED: xdotool is not installed (scripts/deps.sh installs it)"; exit 1; }
    key=$(if [ "$mode" = key_space ]; then echo space; else echo Up; fi)
    log="$out/orbits_$mode.log"
    # As tests/example_wsad.sh: wait for the window, focus it, hold the key (a press-and-release from
    # `xdotool key` can fall between two frames), Escape. --frames is only a safety net.
    xvfb-run -a -s "-screen 0 1024x768x24" sh -c '
        "$1" --frames 1800 > "$3" 2>&1 & pid=$!
        window=$(timeout 30 xdotool search --sync --onlyvisible --name "^motus - orbits\$" | head -n 1)
        if [ -z "$window" ]; then echo "the example opened no window"; kill $pid; exit 1; fi
        xdotool windowfocus --sync "$window"
        sleep 0.3
        xdotool keydown "$2"; sleep 0.5; xdotool keyup "$2"
        sleep 0.5
        xdotool key Escape
        wait $pid' sh "$binary" "$key" "$log"
    cat "$log"
    line=$(grep '^frames=' "$log")
    if [ "$mode" = key_space ]; then
        awk -v frames="$(field frames "$line")" -v steps="$(field steps "$line")" \
            -v paused="$(field paused "$line")" -v paused_frames="$(field paused_frames "$line")" 'BEGIN {
            printf "paused=%d after %d frames: %d steps, %d frames paused\n", paused, frames, steps, paused_frames
            if (paused != 1 || paused_frames < 10 || steps + paused_frames != frames) { print "FAILED"; exit 1 } }'
    else
        steps_per_orbit=$(field steps_per_orbit "$line")
        echo "steps per orbit after UP: $steps_per_orbit (120 before)"
        [ "$steps_per_orbit" = 60 ] || { echo "FAILED: UP should double the step once"; exit 1; }
    fi
    ;;
*)
    echo "usage: $0 ORBITS_BINARY headless|key_space|key_up OUTPUT_DIR" >&2
    exit 2
    ;;
esac
