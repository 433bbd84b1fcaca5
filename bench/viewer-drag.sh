#!/usr/bin/env bash
# Measures the viewer while a value is dragged with every panel of the vignetting teaching open
# (issue 21's target: 60 frames/s, no computation holding the UI thread over 4 ms in a frame).
# It opens the real viewer under Xvfb on the vignetting demo (the wide 22 mm), shows the
# Illumination panel with a film point's bundle and its footprint, the heat-map overlay and the
# measured fall-off, then drags with real X input (xdotool): the film-point slider across its
# range and back, then the film plane in the cross-section. It prints the viewer's --stats-json
# for the frames of the drags alone: frame_ms_* (the frame rate), frame_work_ms_* (the UI
# thread's whole work per frame in wall time, rasterizing included) and frame_compute_cpu_ms_*
# (the UI thread's CPU time computing before rasterizing), and where the worst frame spent it
# (worst_compute_frame_stages_cpu_ms; each stage's p99 and maximum over the frames in
# compute_stage_cpu_ms_p99 / _max; the panels are stages named by their ids).
#
#   bench/viewer-drag.sh [STEPS]      (default 120 mouse steps per drag, 16 ms apart; needs Xvfb,
#                                      xdotool and build/lenslab, or the binary named by $LENSLAB)
set -euo pipefail
cd "$(dirname "$0")/.."
# The viewer and xdotool on one private X server.
if [[ -z "${VIEWER_DRAG_ON_XVFB:-}" ]]; then
  VIEWER_DRAG_ON_XVFB=1 exec tests/app/with-xvfb "$PWD/bench/viewer-drag.sh" "$@"
fi
steps=${1:-120}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cat > "$work/drag.script" <<SCRIPT
load-scene $PWD/scenes/vignetting.pbrt
set layout 0.28 0.42 0.45
show-panel illumination
set film-point 4
set vignetting-overlay on
wait-spp 4
wait-frames 5
dump-ui $work/ui.json
wait-until-file $work/go
reset-stats
wait-until-file $work/done
quit
SCRIPT
drive() {
  until [ -f "$work/ui.json" ]; do sleep 0.1; done
  read -r sx sy sw fx fy < <(python3 - "$work/ui.json" <<'PY'
import json, sys
w = json.load(open(sys.argv[1]))["widgets"]
s, f = w["illumination/film-point"], w["cross-section/film"]
print(int(s["x"] + 6), int(s["y"] + s["height"] / 2), int(s["width"] - 12),
      int(f["x"] + f["width"] / 2), int(f["y"] + f["height"] * 0.3))
PY
)
  W=$(xdotool search --sync --onlyvisible --name '^lenslab - ' | head -n1)
  xdotool windowfocus --sync "$W"
  touch "$work/go"
  sleep 0.3
  # The slider: pressed at its left end, moved across and back, released.
  xdotool mousemove --window "$W" "$sx" "$sy" mousedown 1
  for ((i = 1; i <= steps; ++i)); do
    x=$((sx + sw * (i <= steps / 2 ? 2 * i : 2 * (steps - i)) / steps))
    xdotool mousemove --window "$W" "$x" "$sy"
    sleep 0.016
  done
  xdotool mouseup 1
  sleep 0.3
  # The film plane: 30 px toward the lens and back.
  xdotool mousemove --window "$W" "$fx" "$fy" mousedown 1
  for ((i = 1; i <= steps; ++i)); do
    x=$((fx - 30 * (i <= steps / 2 ? 2 * i : 2 * (steps - i)) / steps))
    xdotool mousemove --window "$W" "$x" "$fy"
    sleep 0.016
  done
  xdotool mouseup 1
  sleep 0.3
  touch "$work/done"
}
drive &
driver=$!
${LENSLAB:-build/lenslab} --size 1400x900 --script "$work/drag.script" \
  --stats-json "$work/stats.json"
wait "$driver"
cat "$work/stats.json"
