#!/usr/bin/env bash
# What a restructuring must leave unchanged (issue 58): eval's errors.csv and histograms on the
# tiny, default, translucent and soft_tiny datasets, oit's on its tiny dataset, and the rows of a
# tiny sweep's candidates and references_ tables without their seconds. Writes them into OUT; diff
# two builds' OUT directories (diff -r).
#   bash scripts/output_fingerprint.sh OUT [BUILD_DIR]       (default build/release)
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:?usage: output_fingerprint.sh OUT [BUILD_DIR]}
build=${2:-build/release}
mb="$build/momentbench"
python=/usr/bin/python3
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
mkdir -p "$out"
keep() {  # keep errors.csv and histograms of eval/oit output $1 as $out/$2
  mkdir -p "$out/$2"
  cp "$1/errors.csv" "$out/$2/"
  [ -d "$1/histograms" ] && cp -r "$1/histograms" "$out/$2/"
  return 0
}
hard='[pcf, oracle, vsm, esm, esm_zmax, esm_threshold, evsm2, evsm4, evsm2_float, evsm4_float, lvsm, csm, hamburger4, hamburger4_float, hamburger4_16bit, hausdorff4, hamburger6, tmsm, tmsm_float, lp:power4, lp:trig4]'
$mb eval -q --set dataset=tiny --set "techniques=$hard" --set images=false -o "$work/tiny" >/dev/null
keep "$work/tiny" eval-tiny
$mb eval -q --set dataset=default --set images=false -o "$work/default" >/dev/null
keep "$work/default" eval-default
$mb eval -q --set dataset=translucent --set 'techniques=[pcf, vsm, hamburger4, fom, lp:power4]' \
  --set images=false -o "$work/translucent" >/dev/null
keep "$work/translucent" eval-translucent
$mb eval -q --set dataset=tests/data/soft_tiny.yaml --set images=false \
  --set 'techniques=[pcf, hamburger4, pcss_exact, pcss, pcss_vsm, pcss_esm, pcss_csm, msm_soft, msm_soft:lp:power4]' \
  -o "$work/soft" >/dev/null
keep "$work/soft" eval-soft_tiny
cp "$work/soft/pcss_errors.csv" "$work/soft/blocker_audit.csv" "$out/eval-soft_tiny/" 2>/dev/null || true
oit='[exact, unsorted, wboit, mboit_power4, mboit_power6, mboit_power8, mboit_trig2, mboit_trig3, mboit_trig4, mboit_power4_float, mboit_power4_16bit, mboit_trig4_float, mboit_trig4_16bit, lp:power4]'
$mb oit -q --set dataset=tests/data/oit_tiny.yaml --set "techniques=$oit" --set images=false \
  --set deep_frames=false -o "$work/oit" >/dev/null
keep "$work/oit" oit-tiny
# oit's errors.csv ends with each technique's time: keep the first 16 columns.
cut -d, -f1-16 "$work/oit/errors.csv" > "$out/oit-tiny/errors.csv"
$mb sweep -q --config configs/sweeps/tiny.yaml -o "$work/sweep" >/dev/null
"$python" - "$work/sweep" > "$out/sweep-tiny.txt" <<'PY'
import glob, sqlite3, sys
db = sqlite3.connect(glob.glob(sys.argv[1] + "/*.sqlite")[0])
for table in ("candidates", "references_"):
    cols = [r[1] for r in db.execute("PRAGMA table_info(%s)" % table) if r[1] != "seconds"]
    for row in db.execute("SELECT %s FROM %s ORDER BY 1" % (", ".join(cols), table)):
        print(table, row)
PY
echo "output_fingerprint: $out"
