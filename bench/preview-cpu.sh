#!/bin/sh
# The renderer's part of the viewer's first preview pass after an edit, headless, in the default
# mode (spectral for the default lens) against RGB (issue 39): BM_PreviewFirstPass/coarse:4 with
# rgb:0 and rgb:1, REPS repetitions of each in random interleaving in one process, and the median
# of each counter and the default / RGB ratio. The CPU time per pass (all threads) hardly depends
# on what else the shared machine runs, where the wall-clock figures of bench/preview-modes.sh
# (the real viewer) swing with it: a change that makes the default mode dearer again shows here
# in one run.
#
#   bench/preview-cpu.sh [BUILD_DIR] [REPS]   (defaults build and 9)
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$here/build}
reps=${2:-9}
bench=$build/bench/lenslab_bench
[ -x "$bench" ] || { echo "no $bench: build with -DLENSLAB_BUILD_BENCH=ON first" >&2; exit 1; }
out=$(mktemp)
trap 'rm -f "$out"' EXIT
"$bench" --benchmark_filter='BM_PreviewFirstPass/coarse:4/' --benchmark_repetitions="$reps" \
  --benchmark_enable_random_interleaving=true --benchmark_min_time=0.05 \
  --benchmark_format=json >"$out" 2>/dev/null
python3 - "$out" <<'PY'
import json, statistics, sys
runs = [b for b in json.load(open(sys.argv[1]))["benchmarks"] if b.get("run_type") == "iteration"]
modes = {"default": "rgb:0", "RGB": "rgb:1"}
keys = [("cpu_ms", "CPU per pass, all threads"), ("table_ms", "job start -> exit-pupil table"),
        ("coarse_ms", "job start -> coarse look"), ("pass_ms", "job start -> first full pass")]
print("%-34s %9s %9s %6s" % ("ms, median of the repetitions", "default", "RGB", "ratio"))
for key, label in keys:
    m = {mode: statistics.median(b[key] for b in runs if arg in b["name"])
         for mode, arg in modes.items()}
    print("%-34s %9.1f %9.1f %6.2f" % (label, m["default"], m["RGB"], m["default"] / m["RGB"]))
PY
