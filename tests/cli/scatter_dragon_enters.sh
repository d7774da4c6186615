#!/usr/bin/env bash
# Seed 004 Figure 7 (docs/scattering.md §4): the scattering_dragon pair through `scatter` and
# scripts/scatter_dragon_enters.py. The exact row is the reference (no change off the dragon's
# shadow, all of its darkening); pss_exact, which keeps the rectified row's own depths, reproduces
# the dragon's shadow to within a tenth; four moments darken rays the dragon does not shadow.
set -euo pipefail
mb=$1 out=$2 script=$3
rm -rf "$out"
"$mb" scatter -q --set dataset=scattering_dragon --set scatter.reference_resolution=512 \
  --set scatter.light_resolution=512 --set 'techniques=[exact, pss_exact, pss_msm4]' \
  --out "$out" >/dev/null
/usr/bin/python3 "$script" "$out" > "$out/dragon.md"
cat "$out/dragon.md"
grep -q '^| exact | 0.000 | 0 (0.0 %) | 0.000 | 0.00 | 1.00 |$' "$out/dragon.md"
awk -F'|' '$2 == " pss_exact " { r = $7 + 0; exit !(r > 0.9 && r < 1.1) }' "$out/dragon.md"
awk -F'|' '$2 == " pss_msm4 " { split($4, a, " "); exit !(a[1] + 0 > 0) }' "$out/dragon.md"
grep -q '^| pss_msm4 ' "$out/dragon.md"
