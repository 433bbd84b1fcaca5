#!/usr/bin/env bash
# Measures the viewer's feel (issue 5): the UI frame time while the preview renders, and the
# time from an edit to the first complete preview pass. It opens the real viewer under Xvfb on
# the default scene, makes EDITS film-distance edits (each waits for its first pass), and prints
# the viewer's own --stats-json figures.
#
#   bench/viewer-feel.sh [EDITS]      (default 20; needs Xvfb and build/lenslab, or the binary named by $LENSLAB)
#
# FEEL_SETUP: script lines run before the edits (e.g. "set spectral off"; bench/preview-modes.sh).
# FEEL_JSON: write the figures to this file instead of printing them.
set -euo pipefail
cd "$(dirname "$0")/.."
edits=${1:-20}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
{
  if [[ -n "${FEEL_SETUP:-}" ]]; then echo "$FEEL_SETUP"; fi
  echo "wait-spp 4"
  for ((i = 0; i < edits; ++i)); do
    # Alternate between two film distances near the default focus.
    if ((i % 2)); then echo "set film-distance 36.9"; else echo "set film-distance 37.3"; fi
    echo "wait-spp 1"
    echo "wait-frames 10"
  done
  echo "quit"
} > "$work/feel.script"
tests/app/with-xvfb ${LENSLAB:-build/lenslab} --size 1400x850 --script "$work/feel.script" \
  --stats-json "$work/stats.json"
if [[ -n "${FEEL_JSON:-}" ]]; then cp "$work/stats.json" "$FEEL_JSON"; else cat "$work/stats.json"; fi
