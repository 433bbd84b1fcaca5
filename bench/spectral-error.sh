#!/bin/sh
# Colour noise of the spectral render (issue 23): at equal samples per pixel, its error against a
# converged reference, beside the RGB render's error against its own converged reference.
#
#   bench/spectral-error.sh [BUILD_DIR] [SPP] [REFERENCE_SPP] [WIDTHxHEIGHT]
#
# Renders scenes/default.pbrt through the flint landscape lens (V_d 23.78: an uncorrected singlet),
# the double-Gauss 50 mm and the Cooke triplet 100 mm (both with the V_d of their sources), each in
# RGB (--spectral off) and spectrally (--spectral on), at
# SPP (default 16) with seed 1 and at REFERENCE_SPP (default 1024) with seed 7, and prints the
# RMS error of each test image against the reference of its own mode (linear RGB, all channels,
# PFM), and the ratio spectral / RGB. The references' own noise adds 1/64 of a test image's
# variance at the defaults. Takes several minutes on two cores. Since stop 35 the error is taken
# below the default scene's lamps (rows 30-100% from the top): their discs are noisy in either
# mode (few of a pixel's lens samples see so small a light), and over the whole picture that
# noise would bring the ratio toward 1 without any change in colour noise.
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$here/build}
spp=${2:-16}
refspp=${3:-1024}
size=${4:-300x200}
lenslab=$build/lenslab
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
[ -x "$lenslab" ] || { echo "no $lenslab: build first" >&2; exit 1; }

render() {  # name lens mode spp seed
  "$lenslab" render "$here/scenes/default.pbrt" --lens "$here/lenses/$2" --spectral "$3" \
    --spp "$4" --seed "$5" --resolution "$size" --quiet --out "$out/$1.pfm" >/dev/null
}

for lens in flint-landscape-50mm.dat dgauss-50mm.dat cooke-triplet-100mm.dat; do
  for mode in off on; do
    render "ref-$mode" "$lens" "$mode" "$refspp" 7
    render "test-$mode" "$lens" "$mode" "$spp" 1
  done
  python3 - "$here/bench" "$out" "$lens" "$spp" "$refspp" <<'PY'
import sys
sys.path.insert(0, sys.argv[1])
from pfm_region import read_region, rmse
out, lens, spp, refspp = sys.argv[2:6]
def pfm(path):  # below the lamps: rows 30-100% from the top
    return read_region(path, 0.0, 0.3, 1.0, 1.0)
e = {m: rmse(pfm(f'{out}/test-{m}.pfm'), pfm(f'{out}/ref-{m}.pfm')) for m in ('off', 'on')}
print(f'{lens:28s} {spp} spp vs {refspp} spp: RMSE rgb {e["off"]:.5f}  spectral {e["on"]:.5f}'
      f'  ratio {e["on"] / e["off"]:.3f}')
PY
done
