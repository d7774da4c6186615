#!/usr/bin/env bash
# The scattering rows' cost (docs/scattering.md §3, issue 59 item 10): wall microseconds per view
# ray of each technique from errors.csv's time_s, per scene (the house: a few hundred triangles;
# the garden: thousands, with foliage cards), at three lengths of the rays that see no surface
# (scatter.max_distance), and of the exact reference at three light-map resolutions. A
# prefiltered row pays for its rectified map once per light view and camera (in its time) and
# then answers a ray from prefix sums: its cost per ray should not grow with the scene or the ray;
# the exact walk's grows with the texels a ray crosses. One run per setting, every technique in
# it, so the ratios between techniques share the machine's state.
#   bash scripts/bench_scatter_cost.sh [MOMENTBENCH] [DATASET] [THREADS]
set -euo pipefail
cd "$(dirname "$0")/.."
mb=$(realpath "${1:-build/release/momentbench}")
dataset=${2:-scattering}
threads=${3:-1}
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
techniques="exact, raymarch:32, raymarch:128, pss_exact, pss_msm4, pss_msm6, pss_csm, pss_lp:power4"
for d in 25 100 400; do
  "$mb" scatter -q --set dataset="$dataset" --set threads="$threads" --set images=false \
    --set scatter.max_distance="$d" --set "techniques=[$techniques]" --out "$work/d$d" > /dev/null
done
for r in 256 1024 4096; do
  "$mb" scatter -q --set dataset="$dataset" --set threads="$threads" --set images=false \
    --set scatter.reference_resolution="$r" --set "techniques=[exact]" --out "$work/r$r" > /dev/null
done
/usr/bin/python3 - "$work" <<'PY'
import csv, re, sys, glob, os
work = sys.argv[1]
def table(path):
    rows = [r for r in csv.DictReader(open(path)) if r["scene"] != "all"]
    time, frames = {}, {}
    for r in rows:
        key = (r["technique"], r["scene"])
        time[key] = time.get(key, 0) + float(r["time_s"])
    return time
def rays(path):  # pixels per scene from report.md's epipole lines "scene/view/camera: N of M"
    out = {}
    for m in re.finditer(r"^- ([^/]+)/[^/]+/[^:]+: \d+ of (\d+)", open(path).read(), re.M):
        out[m.group(1)] = out.get(m.group(1), 0) + int(m.group(2))
    return out
print("Wall µs per view ray (time_s of each light view and camera summed per scene, over its rays):\n")
for d in (25, 100, 400):
    t, n = table(f"{work}/d{d}/errors.csv"), rays(f"{work}/d{d}/report.md")
    scenes = sorted(n)
    if d == 25:
        print("| max_distance | technique | " + " | ".join(scenes) + " |")
        print("|---|---|" + "---|" * len(scenes))
    techs = list(dict.fromkeys(k[0] for k in t))
    for tech in techs:
        print(f"| {d} | {tech} | " + " | ".join("%.2f" % (t[(tech, s)] * 1e6 / n[s]) for s in scenes) + " |")
print("\nThe exact reference against the light map's resolution (max_distance 100):\n")
print("| scatter.reference_resolution | " + " | ".join(sorted(rays(f"{work}/r256/report.md"))) + " |")
print("|---|" + "---|" * len(rays(f"{work}/r256/report.md")))
for r in (256, 1024, 4096):
    t, n = table(f"{work}/r{r}/errors.csv"), rays(f"{work}/r{r}/report.md")
    print(f"| {r} | " + " | ".join("%.2f" % (t[("exact", s)] * 1e6 / n[s]) for s in sorted(n)) + " |")
PY
