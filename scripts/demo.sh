#!/usr/bin/env bash
# Usage: scripts/demo.sh
# Installs what is missing, builds the WSAD example and runs it: in a window when there is a display,
# otherwise headless in a virtual X server (Xvfb) with scripted input, writing build/wsad.png and printing
# the particle's final state.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh demo
scripts/bootstrap-raylib.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=RelWithDebInfo -DMOTUS_BUILD_EXAMPLES=ON
cmake --build build --target wsad --parallel "$(nproc 2>/dev/null || echo 2)"
if [ -n "${DISPLAY:-}" ] && [ -z "${CI:-}" ]; then
    echo "W/A/S/D push the particle; Escape or closing the window quits."
    exec build/examples/wsad
fi
echo "No display: running 120 frames headless (D held for 1 s, then S for 0.5 s)."
xvfb-run -a -s "-screen 0 1024x768x24" build/examples/wsad --frames 120 --fixed-dt --autopilot --screenshot build/wsad.png
echo "Screenshot: build/wsad.png"
