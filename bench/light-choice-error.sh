#!/bin/sh
# Noise of two builds' renders at equal samples per pixel, against one converged reference: for
# changes that should leave the picture's expectation alone and change its noise (the path
# tracer's choice of light, stop 35).
#
#   bench/light-choice-error.sh BASE_BUILD NEW_BUILD [SPP] [REFERENCE_SPP] [WIDTHxHEIGHT] [SCENE[@X0,Y0,X1,Y1]...]
#
# Renders each scene (default: scenes/default.pbrt, its part below the lamps, and the lower half
# of the subject's sphere in scenes/bokeh.pbrt, which bench/README.md measured at 600x400) with
# both builds at SPP (default 16) with seeds 1, 2 and 3, and with NEW_BUILD at REFERENCE_SPP
# (default 1024) with seed 7, and prints the RMS error of each test image against the reference
# (linear RGB, all channels, PFM) over the scene's region (@ and fractions of the width and
# height, top left to bottom right; the whole picture without), the median over the seeds, and
# the ratio new / base. The reference's own noise adds 1/64 of a test
# image's variance at the defaults. A small bright lamp's disc is seen by few of its pixels'
# samples whatever light the path tracer samples, and its noise swamps the rest of a picture:
# hence the regions.
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
[ $# -ge 2 ] || { sed -n 2,17p "$0" >&2; exit 2; }
base=$1
new=$2
spp=${3:-16}
refspp=${4:-1024}
size=${5:-300x200}
shift $(($# < 5 ? $# : 5))
scenes=${*:-"$here/scenes/default.pbrt $here/scenes/default.pbrt@0,0.3,1,1 $here/scenes/bokeh.pbrt@0.29,0.555,0.34,0.595"}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for build in "$base" "$new"; do
  [ -x "$build/lenslab" ] || { echo "no $build/lenslab: build first" >&2; exit 1; }
done

render() {  # build scene spp seed out
  "$1/lenslab" render "$2" --spp "$3" --seed "$4" --resolution "$size" --quiet --out "$5" >/dev/null
}

for entry in $scenes; do
  scene=${entry%%@*}
  region=0,0,1,1
  [ "$scene" = "$entry" ] || region=${entry#*@}
  name=$(basename "$scene" .pbrt)
  if [ ! -f "$out/$name-ref.pfm" ]; then  # a scene listed again with another region
    render "$new" "$scene" "$refspp" 7 "$out/$name-ref.pfm"
    for seed in 1 2 3; do  # alternating builds
      render "$base" "$scene" "$spp" "$seed" "$out/$name-base-$seed.pfm"
      render "$new" "$scene" "$spp" "$seed" "$out/$name-new-$seed.pfm"
    done
  fi
  python3 - "$here/bench" "$out" "$name" "$spp" "$refspp" "$region" <<'PY'
import sys
sys.path.insert(0, sys.argv[1])
from pfm_region import read_region, rmse
out, name, spp, refspp, region = sys.argv[2:7]
def pfm(path):
    return read_region(path, *map(float, region.split(',')))
ref = pfm(f'{out}/{name}-ref.pfm')
label = name if region == '0,0,1,1' else f'{name}@{region}'
e = {b: sorted(rmse(pfm(f'{out}/{name}-{b}-{s}.pfm'), ref) for s in (1, 2, 3))
     for b in ('base', 'new')}
print(f'{label:26s} {spp} spp vs {refspp} spp: RMSE base {e["base"][1]:.5f} '
      f'({e["base"][0]:.5f}-{e["base"][2]:.5f})  new {e["new"][1]:.5f} '
      f'({e["new"][0]:.5f}-{e["new"][2]:.5f})  ratio {e["new"][1] / e["base"][1]:.3f}')
PY
done
