#!/bin/sh
# Times the renderer on the issue's benchmark scenes, whole process, and prints wall time, CPU
# time and peak memory of each run (GNU time) plus the renderer's own stats JSON.
#
#   bench/render-bench.sh [BUILD_DIR] [SHARED_DIR] [RUNS]
#
# BUILD_DIR defaults to ./build, SHARED_DIR to ../shared (beside the project), RUNS to 3.
# BENCH_PAIR_ONLY=1: only the benchmark pair (bench-dgauss and bench-perspective, alternating).
# Targets (issue 4): course dgauss 300x300 at 32 spp <= 1.0 s, at 512 spp <= 12 s;
# bench-dgauss <= 4 s and <= 1.5x bench-perspective; peak memory <= 300 MB.
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$here/build}
shared=${2:-$here/../shared}
runs=${3:-3}
lenslab=$build/lenslab
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
[ -x "$lenslab" ] || { echo "no $lenslab: build first" >&2; exit 1; }
[ -d "$shared" ] || { echo "no $shared" >&2; exit 1; }

run() {  # name, then lenslab render arguments
  name=$1; shift
  i=1
  while [ "$i" -le "$runs" ]; do
    /usr/bin/time -f "%e %U %S %M" -o "$out/time" "$lenslab" render "$@" --quiet \
      --out "$out/$name.exr" --stats-json "$out/$name.json" >/dev/null
    read -r wall user system kb < "$out/time"
    # CPU seconds (user + system) beside the wall time: on a shared machine the wall time also
    # carries the time other tenants held the cores.
    printf '%-22s run %d  wall %6.2f s  cpu %6.2f s  peak %5d MB  %s\n' "$name" "$i" "$wall" \
      "$(awk -v u="$user" -v s="$system" 'BEGIN { print u + s }')" $((kb / 1024)) \
      "$(tr -d '\n ' < "$out/$name.json" | sed 's/"output":"[^"]*",\{0,1\}//')"
    i=$((i + 1))
  done
}

scenes=$shared/reference/scenes
if [ -z "${BENCH_PAIR_ONLY:-}" ]; then
run course-dgauss-32 "$scenes/dof-dragons.dgauss.pbrt" --spp 32
run course-dgauss-512 "$scenes/dof-dragons.dgauss.pbrt" --spp 512
run course-fisheye-32 "$scenes/dof-dragons.fisheye.pbrt" --spp 32
fi

# The benchmark pair, alternating (lens, pinhole, lens, ...): the machine's speed swings by 10-30%
# between consecutive runs (bench/README.md, issue 39), so the lens/pinhole ratio is taken within
# each pair, and its median over the pairs; beside the wall-clock ratio, the CPU-time one (user +
# system), which does not count the time other tenants held the cores.
ratios=""
cpuRatios=""
i=1
while [ "$i" -le "$runs" ]; do
  for name in bench-dgauss bench-perspective; do
    /usr/bin/time -f "%e %U %S %M" -o "$out/time" "$lenslab" render "$shared/bench/$name.pbrt" \
      --quiet --out "$out/$name.exr" --stats-json "$out/$name.json" >/dev/null
    read -r wall user system kb < "$out/time"
    printf '%-22s run %d  wall %6.2f s  cpu %6.2f s  peak %5d MB\n' "$name" "$i" "$wall" \
      "$(awk -v u="$user" -v s="$system" 'BEGIN { print u + s }')" $((kb / 1024))
    eval "wall_$(echo "$name" | tr - _)=$wall"
    eval "cpu_$(echo "$name" | tr - _)=$(awk -v u="$user" -v s="$system" 'BEGIN { print u + s }')"
  done
  ratio=$(awk -v a="$wall_bench_dgauss" -v b="$wall_bench_perspective" 'BEGIN { printf "%.3f", a / b }')
  cpuRatio=$(awk -v a="$cpu_bench_dgauss" -v b="$cpu_bench_perspective" 'BEGIN { printf "%.3f", a / b }')
  echo "  pair $i: bench-dgauss / bench-perspective = $ratio (CPU time $cpuRatio)"
  ratios="$ratios $ratio"
  cpuRatios="$cpuRatios $cpuRatio"
  i=$((i + 1))
done
median() { echo "$1" | tr ' ' '\n' | sed '/^$/d' | sort -n | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
echo "bench-dgauss / bench-perspective, median of $runs pairs: $(median "$ratios") (CPU time $(median "$cpuRatios"))"
