#!/usr/bin/env bash
# The viewer's preview after an edit in its default mode (Spectral: auto, which is spectral for the
# default lens: it has Abbe numbers) against `set spectral off` (RGB), in the same run (issue 39).
# Runs bench/viewer-feel.sh RUNS times per mode, alternating the modes, and prints each run's
# medians and, over the runs, the median of each figure and the default / RGB ratio. A change that
# makes the default mode slower again shows in the ratio even on a day when the shared machine is
# slow: both modes run on the same machine minutes apart.
#
#   bench/preview-modes.sh [RUNS] [EDITS]   (defaults 3 and 12; the binary: build/lenslab, or $LENSLAB)
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-3}
edits=${2:-12}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for ((run = 0; run < runs; ++run)); do
  # Alternate which mode goes first, so that neither always gets the quieter minute.
  if ((run % 2)); then modes=(rgb default); else modes=(default rgb); fi
  for mode in "${modes[@]}"; do
    setup=""
    [[ $mode == rgb ]] && setup="set spectral off"
    FEEL_SETUP="$setup" FEEL_JSON="$work/$mode-$run.json" bench/viewer-feel.sh "$edits" >/dev/null
  done
done
python3 - "$work" "$runs" <<'PY'
import json, statistics, sys
work, runs = sys.argv[1], int(sys.argv[2])
figures = [
    ("edit_to_first_pass_ms_median", "edit -> first full pass on screen"),
    ("edit_to_first_pass_ms_max", "  worst edit of the run"),
    ("first_pass_render_ms_median", "  renderer: job start -> pass published"),
    ("first_pass_table_ms_median", "  renderer: job start -> exit-pupil table built"),
    ("first_pass_coarse_look_ms_median", "  renderer: job start -> coarse look published"),
    ("edit_to_first_picture_ms_median", "edit -> coarse look on screen"),
]
data = {mode: [json.load(open(f"{work}/{mode}-{run}.json")) for run in range(runs)]
        for mode in ("default", "rgb")}
print(f"{'ms (median of the edits per run)':48} {'default (spectral)':>24} {'RGB':>24} {'ratio':>6}")
for key, label in figures:
    cells, medians = [], {}
    for mode in ("default", "rgb"):
        values = [d[key] for d in data[mode]]
        medians[mode] = statistics.median(values)
        cells.append(" ".join(f"{v:.0f}" for v in values) + f" | {medians[mode]:.1f}")
    ratio = medians["default"] / medians["rgb"] if medians["rgb"] else float("nan")
    print(f"{label:48} {cells[0]:>24} {cells[1]:>24} {ratio:6.2f}")
PY
