#!/usr/bin/env bash
# Where the CPU goes per edit in the viewer (issue 5): the UI thread, the software rasterizer's
# threads (llvmpipe), the render workers and the X server, in CPU milliseconds per edit. Unlike
# the wall-clock figures of bench/viewer-feel.sh, CPU time hardly depends on what else the shared
# machine runs, so it shows a change to the UI's cost in one pair of runs.
#
# The viewer opens on the default scene under Xvfb, renders 4 spp, then makes EDITS film-distance
# edits back to back, each waiting for its first complete pass and 3 frames. The counts start at
# the first edit; the workers' figure includes what they render after each first pass.
#
#   bench/viewer-cpu.sh [EDITS]     (default 20; the binary: build/lenslab, or $LENSLAB)
set -euo pipefail
cd "$(dirname "$0")/.."
edits=${1:-20}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
{
  printf 'wait-spp 4\nscreenshot %s/ready.png\nwait-until-file %s/go\n' "$work" "$work"
  for ((i = 0; i < edits; ++i)); do
    if ((i % 2)); then echo "set film-distance 36.9"; else echo "set film-distance 37.3"; fi
    printf 'wait-spp 1\nwait-frames 3\n'
  done
  echo "quit"
} > "$work/cpu.script"
cat > "$work/poll.py" <<'PY'
import glob, json, os, statistics, sys, time
pid, work = int(sys.argv[1]), sys.argv[2]
tick_ms = 1000.0 / os.sysconf("SC_CLK_TCK")

def threads():
    """CPU ms so far of each thread of the viewer and of the X server, by thread id."""
    found = {}
    for stat in glob.glob(f"/proc/{pid}/task/*/stat") + glob.glob("/proc/[0-9]*/stat"):
        try:
            text = open(stat).read()
        except OSError:
            continue
        name = text[text.index("(") + 1:text.rindex(")")]
        fields = text[text.rindex(")") + 2:].split()
        tid = stat.split("/")[-2]
        if "/task/" not in stat and name != "Xvfb":
            continue
        if "/task/" not in stat:
            group = "xvfb"
        elif tid == str(pid):
            group = "ui"
        elif name.startswith("llvmpipe"):
            group = "llvmpipe"
        else:
            group = "workers"
        found[(group, tid)] = (int(fields[11]) + int(fields[12])) * tick_ms
    return found

while not os.path.exists(f"{work}/ready.png"):
    if not os.path.exists(f"/proc/{pid}"):
        sys.exit("the viewer quit before its first pass")
    time.sleep(0.01)
time.sleep(0.05)
start = threads()
open(f"{work}/go", "w").close()
last = {}
while os.path.exists(f"/proc/{pid}"):
    last.update(threads())  # threads that end keep their last reading
    time.sleep(0.02)
stats = json.load(open(f"{work}/stats.json"))
edits = len(stats["edit_to_first_pass_ms"])
per_edit = {}
for (group, tid), ms in last.items():
    per_edit[group] = per_edit.get(group, 0.0) + (ms - start.get((group, tid), 0.0)) / edits
print(json.dumps({
    "edits": edits,
    "edit_to_first_pass_ms_median": round(statistics.median(stats["edit_to_first_pass_ms"]), 1),
    "cpu_ms_per_edit": {group: round(ms, 1) for group, ms in sorted(per_edit.items())},
}))
PY
tests/app/with-xvfb bash -c "'${LENSLAB:-build/lenslab}' --size 1400x850 --script '$work/cpu.script' \
  --stats-json '$work/stats.json' >/dev/null & viewer=\$!
  python3 '$work/poll.py' \$viewer '$work'; wait \$viewer"
