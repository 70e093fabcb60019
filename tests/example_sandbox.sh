#!/bin/sh
# Usage: example_sandbox.sh SANDBOX_BINARY MODE OUTPUT_DIR
# Runs the sandbox example in a virtual X server (Xvfb) and checks the line it prints on exit (and, headless,
# what it draws). The simulation steps a fixed 1/60 s per frame, so every number but us_per_step is the same
# on every run with the same options, however fast Xvfb draws.
#   headless  90 frames with random kicks, gravity off/on x wind off/on, plus the last again without a
#             screenshot. Checks that every run keeps all particles inside the window (they bounce), that
#             scene= names gravity exactly when gravity is on and state.force (wind and kicks are forces), that
#             gravity pulls the particles down (mean_y over 100 px larger) and the wind pushes them right
#             (mean_vx > 20 px/s and mean_x over 100 px larger; without wind |mean_vx| < 10 px/s), that the
#             same options give the same line, and that the screenshot (OUTPUT_DIR/sandbox.png) is an 800x600
#             picture of particles in every hue, more of them in the lower half (gravity).
#   methods   60 frames with gravity, wind and kicks under each of the ten methods (--method): each run
#             keeps every particle inside, prints its method, and gravity and wind move the mean the same
#             way under every method (mean_y and mean_x over 50 px past those after one calm frame).
#   collisions
#             600 frames (10 s) with gravity and collisions on, no kicks, and a screenshot
#             (OUTPUT_DIR/sandbox_collisions.png): the balls have piled up on the floor and rest there: scene=
#             names contacts, every ball is drawn whole inside the window, the largest overlap between two
#             balls (motus_find_contacts, printed as overlap_ratio, a share of the smaller radius) is below 20%
#             (measured 5.1% at the sandbox's 2 substeps, 5,000 balls 40 deep; tests/contacts.c holds a 2,000-ball
#             pile at 4 substeps under 1%), the pile's rms speed is below 10 px/s (measured 3.7; a ball's fall
#             through one radius under gravity is 40 px/s)
#             and its mean height is that of a pile on the floor (mean_y > 400 px: the balls' area fills the
#             lower 300 px of the window); the same run with collisions off, as a control, has the balls
#             overlapping (overlap_ratio > 0.5) and not resting.
#   key_g, key_w, key_k, key_d, key_m, key_r, key_c, key_t
#             start with gravity, wind, damping and collisions off and random kicks on, hold the key with real
#             key events (xdotool), then Escape: exactly one change, of that key's switch, and scene= follows it
#             (G: gravity; W: wind on, state.force; K: kicks off and, without wind, no state.force; D:
#             damping_per_second; M: the method after semi-implicit Euler, explicit_euler; R: one reset, so
#             fewer steps since it than frames). C starts with gravity on and kicks off, and instead of Escape
#             lets the run end after 600 frames: collisions=1, scene= names contacts, and the balls rest in a
#             pile as in `collisions` (every ball whole inside the window, largest overlap below 20%).
#             T first moves the pointer to (640, 150) in the window, and after the key waits 3 s: tether=1, the
#             tether's point is the pointer (to 1 px), scene= names tether and linear_drag, and the swarm has
#             gathered there against the kicks (its mean within 60 px of the point, from (400, 300)).
set -eu
binary=$1 mode=$2 out=$3
for tool in xvfb-run python3; do
    command -v "$tool" >/dev/null 2>&1 || { echo "FAILED: $tool is not installed (scripts/deps.sh installs it)"; exit 1; }
done
mkdir -p "$out"

# field NAME LINE: the value of NAME=value in LINE.
field() { echo "$2" | tr ' ' '\n' | sed -n "s/^$1=//p"; }
# has_flag TERM LINE: whether scene= in LINE names TERM.
has_flag() { field scene "$2" | tr '|' '\n' | grep -qx "$1"; }
# summary LOG: the line printed on exit, or a failure.
summary() { grep '^frames=' "$1" || { echo "FAILED: no summary line in $1" >&2; cat "$1" >&2; return 1; }; }
all_inside() {
    [ "$(field inside "$1")" = "$(field particles "$1")" ] || { echo "FAILED: not every particle is inside: $1"; return 1; }
}
# check_pile LINE: the balls rest in a pile on the floor, drawn whole inside the window, overlapping by less
# than 20% of a radius.
check_pile() {
    [ "$(field whole "$1")" = "$(field particles "$1")" ] ||
        { echo "FAILED: not every ball is drawn whole inside the window: $1"; return 1; }
    awk -v ratio="$(field overlap_ratio "$1")" -v px="$(field max_overlap "$1")" -v rms="$(field rms_speed "$1")" \
        -v y="$(field mean_y "$1")" 'BEGIN {
        failed = 0
        printf "pile: largest overlap %.4f px = %.5f of the smaller radius, rms speed %.3f px/s, mean_y %.1f px\n", px, ratio, rms, y
        if (!(ratio < 0.2)) { print "FAILED: the balls overlap by 20% of a radius or more"; failed = 1 }
        if (!(rms < 10)) { print "FAILED: the pile should be at rest (rms speed < 10 px/s)"; failed = 1 }
        if (!(y > 400)) { print "FAILED: the balls should lie on the floor (mean_y > 400 px)"; failed = 1 }
        exit failed }'
}
run() { # run NAME OPTIONS...: a headless run, its line on stdout
    name=$1
    shift
    xvfb-run -a -s "-screen 0 1024x768x24" "$binary" "$@" > "$out/sandbox_$name.log" 2>&1
    summary "$out/sandbox_$name.log"
}

case "$mode" in
headless)
    png="$out/sandbox.png"
    rm -f "$png"
    calm=$(run calm --frames 90 --gravity off --wind off)
    fall=$(run gravity --frames 90 --gravity on --wind off)
    wind=$(run wind --frames 90 --gravity off --wind on)
    both=$(run both --frames 90 --gravity on --wind on --screenshot "$png")
    again=$(run again --frames 90 --gravity on --wind on)
    printf '%s\n' "$calm" "$fall" "$wind" "$both" "$again"
    failed=0
    for line in "$calm" "$fall" "$wind" "$both"; do
        all_inside "$line" || failed=1
        gravity=$(field gravity "$line")
        if has_flag gravity "$line"; then flag=1; else flag=0; fi
        [ "$flag" = "$gravity" ] || { echo "FAILED: scene= and gravity=$gravity disagree: $line"; failed=1; }
        has_flag state.force "$line" || { echo "FAILED: random kicks are on, scene= lacks state.force: $line"; failed=1; }
    done
    awk -v y0="$(field mean_y "$calm")" -v y1="$(field mean_y "$fall")" -v vx0="$(field mean_vx "$calm")" \
        -v vx1="$(field mean_vx "$wind")" -v x0="$(field mean_x "$calm")" -v x1="$(field mean_x "$wind")" '
    function abs(v) { return v < 0 ? -v : v }
    BEGIN {
        failed = 0
        printf "gravity: mean_y %.1f -> %.1f px\n", y0, y1
        if (!(y1 > y0 + 100)) { print "FAILED: gravity should pull the particles down"; failed = 1 }
        printf "wind: mean_vx %.1f -> %.1f px/s, mean_x %.1f -> %.1f px\n", vx0, vx1, x0, x1
        if (!(abs(vx0) < 10 && vx1 > 20 && x1 > x0 + 100)) { print "FAILED: the wind should push them right"; failed = 1 }
        exit failed
    }' || failed=1
    # Reproducible: the same options give the same line, but for the measured time.
    strip() { echo "$1" | sed 's/ us_per_step=[^ ]*//; s/ fps=[^ ]*//'; }
    [ "$(strip "$both")" = "$(strip "$again")" ] || { echo "FAILED: the same options gave different runs"; failed=1; }
    [ "$failed" = 0 ] || exit 1
    # The picture: between the bars (84 px at the top, 26 at the bottom), bright saturated pixels of every
    # 30-degree hue, and with gravity more particle pixels in the lower half than the upper.
    python3 - "$png" 84 574 <<'EOF'
import colorsys, struct, sys, zlib

path, top, bottom = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
data = open(path, "rb").read()
assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
pos, idat, width, height, channels = 8, b"", 0, 0, 0
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

hues, upper, lower, middle = [0] * 12, 0, 0, (top + bottom) // 2
for y in range(top, bottom):
    row = rows[y]
    for x in range(0, stride, channels):
        r, g, b = row[x] / 255, row[x + 1] / 255, row[x + 2] / 255
        h, s, v = colorsys.rgb_to_hsv(r, g, b)
        if v < 0.8 or s < 0.4:
            continue  # background, soft edges
        hues[int(h * 12) % 12] += 1
        if y < middle: upper += 1
        else: lower += 1
print("particle pixels per 30-degree hue:", hues)
print("upper half %d, lower half %d" % (upper, lower))
failed = False
if min(hues) < 100:
    print("FAILED: not every hue is drawn"); failed = True
if not lower > 1.5 * upper:
    print("FAILED: with gravity the lower half should hold more particles"); failed = True
sys.exit(1 if failed else 0)
EOF
    ;;
collisions)
    png="$out/sandbox_collisions.png"
    rm -f "$png"
    pile=$(run collisions --frames 600 --gravity on --random off --collisions on --screenshot "$png")
    control=$(run collisions_off --frames 600 --gravity on --random off --collisions off)
    printf '%s\n' "$pile" "$control"
    failed=0
    all_inside "$pile" || failed=1
    [ "$(field collisions "$pile")" = 1 ] && has_flag contacts "$pile" ||
        { echo "FAILED: --collisions on should give collisions=1 and scene= contacts"; failed=1; }
    has_flag contacts "$control" && { echo "FAILED: with collisions off scene= names contacts"; failed=1; }
    [ -s "$png" ] || { echo "FAILED: no screenshot $png"; failed=1; }
    check_pile "$pile" || failed=1
    awk -v ratio="$(field overlap_ratio "$control")" 'BEGIN {
        printf "control, collisions off: largest overlap %.3f of the smaller radius\n", ratio
        if (!(ratio > 0.5)) { print "FAILED: without collisions the balls should overlap"; exit 1 } }' || failed=1
    exit $failed
    ;;
methods)
    start=$(run start --frames 1 --gravity off --wind off --random off) # (--frames 0 runs until Escape)
    failed=0
    for method in semi_implicit_euler explicit_euler position_verlet velocity_verlet leapfrog midpoint rk4 \
                  forest_ruth mclachlan4 exact_linear_drag; do
        line=$(run "method_$method" --frames 60 --gravity on --wind on --method "$method")
        echo "$line"
        all_inside "$line" || failed=1
        [ "$(field method "$line")" = "$method" ] || { echo "FAILED: asked for $method: $line"; failed=1; }
        awk -v x0="$(field mean_x "$start")" -v y0="$(field mean_y "$start")" -v x1="$(field mean_x "$line")" \
            -v y1="$(field mean_y "$line")" -v m="$method" 'BEGIN {
            if (!(y1 > y0 + 50 && x1 > x0 + 50)) { printf "FAILED: %s: gravity and wind should move the mean\n", m; exit 1 } }' ||
            failed=1
    done
    exit $failed
    ;;
key_g | key_w | key_k | key_d | key_m | key_r | key_c | key_t)
    command -v xdotool >/dev/null 2>&1 || { echo "FAILED: xdotool is not installed (scripts/deps.sh installs it)"; exit 1; }
    key=${mode#key_}
    log="$out/sandbox_$mode.log"
    # C: gravity on and no kicks, so that the balls pile up; the run ends by itself after 600 frames.
    if [ "$key" = c ]; then start="--frames 600 --gravity on --random off" last=true
    else start="--frames 1800 --gravity off --random on" last="xdotool key Escape"; fi
    # As tests/example_wsad.sh: wait for the window, focus it, hold the key (a press-and-release from
    # `xdotool key` can fall between two frames), Escape. --frames is only a safety net.
    xvfb-run -a -s "-screen 0 1024x768x24" sh -c '
        "$1" $4 --wind off --damping off --collisions off > "$3" 2>&1 & pid=$!
        window=$(timeout 30 xdotool search --sync --onlyvisible --name "^motus - sandbox\$" | head -n 1)
        if [ -z "$window" ]; then echo "the example opened no window"; kill $pid; exit 1; fi
        xdotool windowfocus --sync "$window"
        if [ "$2" = t ]; then xdotool mousemove --window "$window" 640 150; fi
        sleep 0.3
        xdotool keydown "$2"; sleep 0.5; xdotool keyup "$2"
        sleep 0.5
        if [ "$2" = t ]; then sleep 3; fi
        $5
        wait $pid' sh "$binary" "$key" "$log" "$start" "$last"
    cat "$log"
    line=$(summary "$log")
    all_inside "$line"
    [ "$(field toggles "$line")" = 1 ] || { echo "FAILED: holding $key should change exactly one thing once"; exit 1; }
    [ "$key" = r ] || [ "$(field resets "$line")" = 0 ] || { echo "FAILED: only R resets"; exit 1; }
    case "$key" in
    g) [ "$(field gravity "$line")" = 1 ] && has_flag gravity "$line" ||
        { echo "FAILED: G should switch gravity on, and scene= name gravity"; exit 1; } ;;
    w) [ "$(field wind "$line")" = 1 ] && has_flag state.force "$line" ||
        { echo "FAILED: W should switch the wind on, and scene= name state.force"; exit 1; } ;;
    k) [ "$(field random "$line")" = 0 ] && ! has_flag state.force "$line" ||
        { echo "FAILED: K should switch the kicks off and, with no wind, state.force with them"; exit 1; } ;;
    d) [ "$(field damping "$line")" = 1 ] && has_flag damping_per_second "$line" ||
        { echo "FAILED: D should switch damping on, and scene= name damping_per_second"; exit 1; } ;;
    m) [ "$(field method "$line")" = explicit_euler ] ||
        { echo "FAILED: M should move from semi_implicit_euler to the next method, explicit_euler"; exit 1; } ;;
    r) [ "$(field resets "$line")" = 1 ] && [ "$(field steps "$line")" -lt "$(field frames "$line")" ] ||
        { echo "FAILED: R should reset once, and the steps since be fewer than the frames"; exit 1; } ;;
    t) [ "$(field tether "$line")" = 1 ] && has_flag tether "$line" && has_flag linear_drag "$line" ||
        { echo "FAILED: T should switch the tether on, and scene= name tether and linear_drag"; exit 1; }
       awk -v px="$(field tether_x "$line")" -v py="$(field tether_y "$line")" -v mx="$(field mean_x "$line")" \
           -v my="$(field mean_y "$line")" 'BEGIN {
           dx = mx - px; dy = my - py
           printf "tether at (%.1f, %.1f), the swarm'"'"'s mean at (%.1f, %.1f)\n", px, py, mx, my
           if (px < 639 || px > 641 || py < 149 || py > 151) { print "FAILED: the tether should be at the pointer, (640, 150)"; exit 1 }
           if (dx * dx + dy * dy > 60 * 60) { print "FAILED: the swarm should have gathered within 60 px of the tether"; exit 1 } }' ;;
    c) [ "$(field collisions "$line")" = 1 ] && has_flag contacts "$line" ||
        { echo "FAILED: C should switch collisions on, and scene= name contacts"; exit 1; }
       check_pile "$line" ;;
    esac
    echo "key $key: changed once, scene=$(field scene "$line") method=$(field method "$line")"
    ;;
*)
    echo "usage: $0 SANDBOX_BINARY headless|collisions|methods|key_g|key_w|key_k|key_d|key_m|key_r|key_c|key_t OUTPUT_DIR" >&2
    exit 2
    ;;
esac
