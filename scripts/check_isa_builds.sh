#!/usr/bin/env bash
# The LP engine's answers must not depend on the instruction set (src/lp/lanes/lanes.h). The
# native build's lp_runs_dump writes the fragments of lp_bench's warm runs once; lp_replay, which
# links the LP engine alone (lp/, basis/), is built for other -march targets and solves them as
# the native lp_replay does:
#  - x86-64-v3 (AVX2 + FMA): the same answers hash, bit for bit, and the same pivots;
#  - x86-64 (SSE2, no FMA): the compiler cannot contract a * b + c into one rounding as the other
#    builds do, so single LPs differ in the last bits; every answer is still certified to 1e-9
#    (docs/reference.md §2), so the sums of G must agree to 2e-9 per LP, with no LP left unsolved.
# The native build makes lp_replay_<target> itself (tests/bench/CMakeLists.txt); where it has no
# such target, this script configures and builds lp_replay for the target in WORK_DIR.
#   bash scripts/check_isa_builds.sh [NATIVE_BUILD] [WORK_DIR]   (defaults build/release, build/isa)
set -euo pipefail
cd "$(dirname "$0")/.."
native=${1:-build/release}
work=${2:-build/isa}
python=/usr/bin/python3
jobs=$(nproc)

for tool in lp_runs_dump lp_replay; do
  [[ -x $native/tests/bench/$tool ]] || { echo "no $native/tests/bench/$tool: build first" >&2; exit 2; }
done
launcher=$(sed -n 's/^CMAKE_CXX_COMPILER_LAUNCHER:[A-Z]*=//p' "$native/CMakeCache.txt" 2>/dev/null || true)
mkdir -p "$work"
"$native/tests/bench/lp_runs_dump" "$work/runs.bin"
# Lines "row answers pivots g_sum lps not_optimal" (tests/bench/lp_replay.cpp).
"$native/tests/bench/lp_replay" "$work/runs.bin" >"$work/native.txt"
status=0
for target in x86-64-v3 x86-64; do
  dir=$work/$target
  replay=$native/tests/bench/lp_replay_$target
  # The native build's own target, brought up to date (nothing to do after a full build).
  if ! cmake --build "$native" -j"$jobs" --target "lp_replay_${target//-/_}" >"$dir.log" 2>&1; then
    # The native build's compiler launcher (ccache) is reused when it has one: a second run of the
    # suite then compiles nothing it compiled before.
    cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Release -DMOMENTBENCH_NATIVE=OFF \
        -DMOMENTBENCH_MARCH="$target" ${launcher:+-DCMAKE_CXX_COMPILER_LAUNCHER="$launcher"} >/dev/null
    cmake --build "$dir" -j"$jobs" --target lp_replay >"$dir.log" 2>&1 || { tail -20 "$dir.log"; exit 1; }
    replay=$dir/tests/bench/lp_replay
  fi
  "$replay" "$work/runs.bin" >"$dir.txt"
  "$python" - "$work/native.txt" "$dir.txt" "$target" <<'PY' || status=1
import sys
native = {l.split()[0]: l.split() for l in open(sys.argv[1])}
other = {l.split()[0]: l.split() for l in open(sys.argv[2])}
target, ok = sys.argv[3], True
for row, n in sorted(native.items()):
    o = other[row]
    if target == "x86-64-v3":
        same = o[1] == n[1] and o[2] == n[2]
        print("%-10s %-24s answers %s vs native %s, pivots %s vs %s: %s" % (
            target, row, o[1], n[1], o[2], n[2], "same" if same else "DIFFERENT"))
    else:
        lps = int(n[4])
        gap = abs(float(o[3]) - float(n[3]))
        same = gap <= 2e-9 * lps and float(o[5]) == 0 and float(n[5]) == 0
        print("%-10s %-24s sum of G differs by %.3g over %d LPs (allowed %.3g), unsolved %s: %s" % (
            target, row, gap, lps, 2e-9 * lps, o[5], "agrees" if same else "DISAGREES"))
    ok &= same
sys.exit(0 if ok else 1)
PY
done
exit $status
