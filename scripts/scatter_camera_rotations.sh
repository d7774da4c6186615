#!/usr/bin/env bash
# Filtered against point resampling of the rectified map as the camera turns (docs/scattering.md
# §3.3; seed 004 §2.3 and Figure 6: point-sampled rectification leaves stripes that move with the
# camera). Writes a copy of the scattering dataset's house in which each camera (`outside`,
# `corner`) is turned about the vertical axis through its position by 0, 0.1, ..., 0.7 degrees
# (8 cameras each, named <camera>_<k>), runs `scatter` on it once with scatter.resample=point and
# once with filtered, and tabulates per camera and technique the mean_error over its 8 turns:
# their mean, (population) standard deviation and max - min.
#   bash scripts/scatter_camera_rotations.sh OUT [MOMENTBENCH] [--set KEY=VALUE ...]
# Further --set arguments go to both runs (e.g. smaller maps). OUT/table.md holds the table.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:?usage: scatter_camera_rotations.sh OUT [MOMENTBENCH] [--set KEY=VALUE ...]}
shift
mb=build/release/momentbench
if [[ $# -gt 0 && $1 != --set ]]; then mb=$1; shift; fi
techniques=${TECHNIQUES:-"[pss_exact, pss_msm4, pss_msm6]"}
mkdir -p "$out/dataset"

/usr/bin/python3 - "$out/dataset" <<'PY'
import math, re, sys
out = sys.argv[1]
house = open("configs/scenes/scattering/house.yaml").read()
cameras = []
for m in re.finditer(r"- \{name: (\w+), position: \[([^\]]*)\], target: \[([^\]]*)\], (.*)\}", house):
    name, rest = m.group(1), m.group(4)
    position = [float(x) for x in m.group(2).split(",")]
    target = [float(x) for x in m.group(3).split(",")]
    for k in range(8):
        a = math.radians(0.1 * k)  # about +y through the camera: x' = x cos a + z sin a
        dx, dz = target[0] - position[0], target[2] - position[2]
        t = [position[0] + dx * math.cos(a) + dz * math.sin(a), target[1],
             position[2] - dx * math.sin(a) + dz * math.cos(a)]
        cameras.append("  - {name: %s_%d, position: [%s], target: [%s], %s}"
                       % (name, k, ", ".join(repr(x) for x in position),
                          ", ".join("%.12g" % x for x in t), rest))
scene = house[:house.index("\ncameras:")] + "\ncameras:\n" + "\n".join(cameras) + "\n"
scene = re.sub(r"^name: house$", "name: house_rotations", scene, flags=re.M)
open(out + "/house_rotations.yaml", "w").write(scene)
dataset = open("configs/datasets/scattering.yaml").read()
medium = re.search(r"^medium: .*$", dataset, re.M).group(0)
open(out + "/scattering_rotations.yaml", "w").write(
    "# The scattering dataset's house, cameras turned by 0.1 degree steps\n"
    "# (scripts/scatter_camera_rotations.sh).\nname: scattering_rotations\n" + medium +
    "\nscenes: [house_rotations.yaml]\n")
PY

for resample in point filtered; do
  "$mb" scatter -q --set dataset="$out/dataset/scattering_rotations.yaml" \
    --set "techniques=$techniques" --set images=false --set scatter.resample=$resample \
    "$@" --out "$out/$resample" >/dev/null
done

/usr/bin/python3 - "$out" <<'PY' | tee "$out/table.md"
import csv, statistics, sys
out = sys.argv[1]
rows = {}
for resample in ("point", "filtered"):
    for r in csv.DictReader(open(f"{out}/{resample}/errors.csv")):
        if r["camera"] == "all":
            continue
        camera = r["camera"].rsplit("_", 1)[0]
        rows.setdefault((camera, r["technique"], resample), []).append(float(r["mean_error"]))
print("| camera | technique | resample | turns | mean of mean_error | std | max - min |")
print("|---|---|---|---|---|---|---|")
for (camera, technique, resample), e in sorted(
        rows.items(), key=lambda kv: (kv[0][0], kv[0][1], kv[0][2] != "point")):
    print(f"| {camera} | {technique} | {resample} | {len(e)} | {statistics.mean(e):.5f} | "
          f"{statistics.pstdev(e):.2e} | {max(e) - min(e):.2e} |")
PY
