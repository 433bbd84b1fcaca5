#!/usr/bin/env bash
# `./run` in a fresh copy of the checkout builds the viewer and no test or benchmark program, so
# that a new user's first window does not wait for the test suite to compile.
#
# The copy's build runs dry: a `cmake` earlier on PATH hands every call to the real one and adds
# ninja's -n to `cmake --build`, which then names every step the real build would take (one line
# per object and per program linked) without taking it. The test costs a configure, not a build. ./run's last step (exec build/lenslab)
# then finds no binary; only what it asked to build is checked.
set -euo pipefail
source_dir=$(cd "$1" && pwd)
real_cmake=$(command -v cmake)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# A fresh clone of the working tree as it stands: the tracked files, uncommitted edits included.
mkdir -p "$work/checkout" "$work/bin"
(cd "$source_dir" && git ls-files -z | xargs -0 cp --parents -t "$work/checkout")

cat >"$work/bin/cmake" <<STUB
#!/usr/bin/env bash
if [[ "\${1:-}" == "--build" ]]; then
  echo "cmake \$*" >>"$work/build-calls.txt"
  exec "$real_cmake" "\$@" -- -n >>"$work/dry-run.txt"
fi
exec "$real_cmake" "\$@"
STUB
chmod +x "$work/bin/cmake"

export CMAKE_GENERATOR=Ninja  # ninja -n: the dry run this test reads
(cd "$work/checkout" && PATH="$work/bin:$PATH" ./run --version >"$work/run.log" 2>&1) || true

fail() {
  echo "run_builds_only_the_viewer: $*" >&2
  echo "--- ./run's output:" >&2
  cat "$work/run.log" >&2
  exit 1
}
[[ -s "$work/build-calls.txt" ]] || fail "./run did not call cmake --build"
echo "./run asked: $(cat "$work/build-calls.txt")"
# Every program the dry run would link: the viewer alone (the guard against passing on an empty
# dry run), not a test, benchmark or fuzz-replay program.
programs=$(sed -n 's/.*Linking CXX executable //p' "$work/dry-run.txt")
[[ "$programs" == lenslab ]] ||
  fail "./run would link $(echo "$programs" | wc -l) programs, not the viewer alone:
$(echo "$programs" | head -8)"
echo "run_builds_only_the_viewer: ./run links the viewer and no other program"
