#!/usr/bin/env bash
# sweep_checks.sh MOMENTBENCH WORKDIR CHECK: end-to-end properties of `sweep` on the tiny dataset.
#   threads  same results with 1 and 2 threads
#   resume   killed with SIGKILL mid-way, resumed: same results as an uninterrupted run
#   shards   3 shards merged: same results as one run; overlapping or mismatched shards refused
#   killloop kill -9 at 20 random instants (from the first milliseconds on), then --resume: the
#            same results every time
#   screen   --screen (two stages): shards screened, merged and confirmed by --resume give the one
#            run's rows, also when the shards kept few unit errors (screen.keep_sigmas=0) and
#            --resume finds the directory's own config; a kill mid-screen resumes to the same; the
#            report marks estimates apart
#   series   sweeps of 2 and 4 functions in one report (the seed paper's Figure 3); sweeps measured
#            against another reference refused; CSV numbers at full precision
#   transparency  target transparency on tests/data/oit_tiny.yaml: the same rows for 1 and 2
#            threads and after kill -9 and --resume; screened; MBOIT's basis marked in the report;
#            its candidate's error equals `oit`'s lp:power4 transmittance error
#   scattering  target scattering on scattering_tiny: the same rows for 1 and 2 threads and after
#            kill -9 and --resume; screened; the power-moment candidate's error equals `scatter`'s
#            pss_lp:power4 at beta 0 against pss_exact, and the report places it
# Results are compared through `report`'s candidates.csv and references.csv (everything but time).
set -eu
mb=$1 work=$2 check=$3
rm -rf "$work" && mkdir -p "$work"
tiny_oit="$(dirname "$0")/../data/oit_tiny.yaml"
common=(--set dataset=tiny --set sample=24 --set sample_seed=3 --set "references=[vsm,hamburger4,lp:power4]" --set lp.grid=64)
results() {  # sweep dir -> report dir with the CSVs
  "$mb" report -q --no-plot "$1" -o "$1.report" >/dev/null
}
same() {
  diff "$1.report/candidates.csv" "$2.report/candidates.csv" && diff "$1.report/references.csv" "$2.report/references.csv"
}
count() {
  /usr/bin/python3 -c "import sqlite3,sys; print(sqlite3.connect(sys.argv[1]).execute('select count(*) from candidates').fetchone()[0])" "$1/results.sqlite" 2>/dev/null || echo 0
}
# kill -9 the sweep PID once its directory DIR holds N screened estimates.
kill_after_estimates() {
  local pid=$1 dir=$2 n
  for _ in $(seq 1 600); do
    n=$(/usr/bin/python3 -c "import sqlite3,sys; print(sqlite3.connect(sys.argv[1]).execute('select count(*) from estimates').fetchone()[0])" "$dir/results.sqlite" 2>/dev/null || echo 0)
    [ "$n" -ge "$3" ] && break
    sleep 0.05
  done
  kill -9 "$pid"
  wait "$pid" 2>/dev/null || true
}
# A sweep target's common checks: sweep NAME... (COUNT candidates) gives the same rows with 2 and 1
# threads and after kill -9 mid-way and --resume; screened, its estimates and exact rows apart.
target_checks() {
  local name=$1 planned=$2
  shift 2
  "$mb" sweep -q "$@" --set threads=2 -o "$work/${name}2"
  results "$work/${name}2"
  "$mb" sweep -q "$@" --set threads=1 -o "$work/${name}1"
  results "$work/${name}1"
  same "$work/${name}2" "$work/${name}1"
  "$mb" sweep -q "$@" --set threads=1 -o "$work/${name}k" 2>/dev/null &
  local pid=$!
  for _ in $(seq 1 600); do
    [ "$(count "$work/${name}k")" -ge 2 ] && break
    sleep 0.02
  done
  kill -9 $pid
  wait $pid 2>/dev/null || true
  local n
  n=$(count "$work/${name}k")
  [ "$n" -lt "$planned" ] || { echo "sweep_checks: the kill did not land mid-way ($n)"; exit 1; }
  "$mb" sweep -q "$@" --resume -o "$work/${name}k"
  results "$work/${name}k"
  same "$work/${name}2" "$work/${name}k"
  "$mb" sweep -q "$@" --screen 0.3 --set screen.top=2 -o "$work/${name}s"
  results "$work/${name}s"
  grep -q "(estimate) |" "$work/${name}s.report/report.md"
}
# The run the threads, resume, shards and series checks compare with (killloop, screen and
# transparency sweep their own configs).
if [ "$check" = threads ] || [ "$check" = resume ] || [ "$check" = shards ] || [ "$check" = series ]; then
  "$mb" sweep -q "${common[@]}" --set threads=2 -o "$work/reference"
  results "$work/reference"
fi
case $check in
threads)
  "$mb" sweep -q "${common[@]}" --set threads=1 -o "$work/one"
  results "$work/one"
  same "$work/reference" "$work/one"
  ;;
resume)
  "$mb" sweep -q "${common[@]}" --set threads=1 -o "$work/killed" &
  pid=$!
  for _ in $(seq 1 600); do
    n=$(count "$work/killed")
    [ "$n" -ge 3 ] && break
    sleep 0.05
  done
  kill -9 $pid
  wait $pid 2>/dev/null || true
  n=$(count "$work/killed")
  echo "killed after $n of 24 candidates"
  [ "$n" -ge 1 ] && [ "$n" -lt 24 ] || { echo "sweep_checks: the kill did not land mid-way ($n)"; exit 1; }
  # A resume with a different config is refused, and changes nothing.
  # The reference and both bias options are part of the config's hash (docs/reference.md §3).
  for other in bias.constant=0.002 bias.slope=2 reference=receiver_plane; do
    if "$mb" sweep -q "${common[@]}" --set $other --resume -o "$work/killed" 2>"$work/err"; then exit 1; fi
    grep -q "run with another config" "$work/err"
  done
  "$mb" sweep -q "${common[@]}" --set threads=2 --resume -o "$work/killed"
  [ "$(count "$work/killed")" -eq 24 ]
  results "$work/killed"
  same "$work/reference" "$work/killed"
  ;;
shards)
  for k in 1 2 3; do "$mb" sweep -q "${common[@]}" --shard $k/3 -o "$work/shard$k"; done
  "$mb" merge "$work/shard1" "$work/shard2" "$work/shard3" -o "$work/merged"
  results "$work/merged"
  same "$work/reference" "$work/merged"
  # A missing shard is named; --partial merges the rest and the report says so.
  if "$mb" merge "$work/shard1" "$work/shard3" -o "$work/partial" 2>"$work/err"; then exit 1; fi
  grep -q "shards 2/3 of this sweep are missing" "$work/err" && [ ! -e "$work/partial" ]
  "$mb" merge --partial "$work/shard1" "$work/shard3" -o "$work/partial" >/dev/null
  "$mb" report -q --no-plot "$work/partial" -o "$work/partial.report" | grep -q "merged without shards 2/3"
  # Overlapping shards (a full run contains shard 1's candidates) are refused, with no output.
  if "$mb" merge "$work/shard1" "$work/reference" -o "$work/overlap" 2>"$work/err"; then exit 1; fi
  grep -q "overlapping shards" "$work/err"
  [ ! -e "$work/overlap" ]
  # Shards of different configs are refused too.
  "$mb" sweep -q "${common[@]}" --set bias.constant=0.002 --shard 2/3 -o "$work/other2"
  if "$mb" merge "$work/shard1" "$work/other2" -o "$work/mismatch" 2>"$work/err"; then exit 1; fi
  grep -q "not shards of one sweep" "$work/err"
  [ ! -e "$work/mismatch" ]
  ;;
killloop)
  small=(--set dataset=tiny --set sample=6 --set sample_seed=5 --set "references=[vsm]" --set lp.grid=32 --set threads=2)
  "$mb" sweep -q "${small[@]}" -o "$work/small"
  results "$work/small"
  for i in $(seq 1 20); do
    rm -rf "$work/k$i"
    # Delays from 0 to ~1.5 s: before the directory exists, while the database is being created,
    # among the references and among the candidates.
    delay=$(/usr/bin/python3 -c "import random; random.seed($i); print(round(random.random() ** 2 * 1.5, 3))")
    "$mb" sweep -q "${small[@]}" -o "$work/k$i" 2>/dev/null &
    pid=$!
    sleep "$delay"
    kill -9 $pid 2>/dev/null || true
    wait $pid 2>/dev/null || true
    "$mb" sweep -q "${small[@]}" --resume -o "$work/k$i"
    results "$work/k$i"
    same "$work/small" "$work/k$i" || { echo "kill after ${delay}s: results differ"; exit 1; }
  done
  # The two windows that once could not resume, made by hand: the directory alone, and the
  # directory with its config.yaml and a half-created database under its temporary name.
  mkdir -p "$work/window1" "$work/window2"
  cp "$work/small/config.yaml" "$work/window2/" && echo partial > "$work/window2/.results.sqlite.new-999999"
  for w in window1 window2; do
    "$mb" sweep -q "${small[@]}" --resume -o "$work/$w"
    results "$work/$w"
    same "$work/small" "$work/$w"
  done
  [ ! -e "$work/window2/.results.sqlite.new-999999" ]
  # A directory that is not a sweep's is not taken over.
  mkdir -p "$work/foreign" && echo keep > "$work/foreign/notes.txt"
  if "$mb" sweep -q "${small[@]}" --resume -o "$work/foreign" 2>"$work/err"; then exit 1; fi
  grep -q "not a sweep's" "$work/err" && [ "$(ls "$work/foreign")" = notes.txt ]
  ;;
screen)
  screen=(--set dataset=tiny --set resolution=128 --set sample=40 --set sample_seed=3 --set "references=[vsm]" --set lp.grid=64 --screen 0.3 --set screen.refine=0.6 --set screen.top=3)
  "$mb" sweep -q "${screen[@]}" -o "$work/screened"
  results "$work/screened"
  # Estimates and exact rows apart, in the report and its CSV.
  grep -q "(estimate) |" "$work/screened.report/report.md"
  grep -q "was screened (\`sweep --screen\`)" "$work/screened.report/report.md"
  exact=$(/usr/bin/python3 -c "import csv,sys; print(sum(r['exact'] == '1' for r in csv.DictReader(open(sys.argv[1]))))" "$work/screened.report/candidates.csv")
  [ "$exact" -ge 3 ] && [ "$exact" -lt 40 ] || { echo "sweep_checks: $exact exact rows of 40"; exit 1; }
  # The best row is exact (docs/sweeps.md): with one confirmation and every difference within 1 a
  # tie, the confirmed best estimate's exact mean comes out above 5 other estimates on this sample;
  # the rounds after the confirmation make those exact, and the report's best row is then exact.
  "$mb" sweep --set dataset=tiny --set resolution=128 --set sample=40 --set sample_seed=2 \
      --set "references=[vsm]" --set lp.grid=64 --screen 0.2 --set screen.top=1 \
      --set screen.margin=-1 -o "$work/ties" 2>"$work/tieslog"
  grep -q "sweep: 5 unconfirmed estimates below the best exact mean" "$work/tieslog"
  results "$work/ties"
  /usr/bin/python3 - "$work/ties.report/candidates.csv" <<'PY'
import csv, sys
rows = [r for r in csv.DictReader(open(sys.argv[1])) if r["exact"] in ("0", "1")]
best = min(float(r["mean_error"]) for r in rows if r["exact"] == "1")
assert all(float(r["mean_error"]) >= best for r in rows if r["exact"] == "0"), "an estimate heads the table"
assert 6 <= sum(r["exact"] == "1" and r["id"] != "0" for r in rows) < 40, "expected the confirmed one and the 5 ahead (the pilot aside)"
PY
  # Shards screen their share; the confirmation waits for the merge, then --resume runs it.
  "$mb" sweep -q "${screen[@]}" --shard 1/2 -o "$work/s1"
  "$mb" sweep -q "${screen[@]}" --shard 2/2 -o "$work/s2"
  [ "$(count "$work/s1")" -eq 0 ] && [ "$(count "$work/s2")" -eq 0 ]
  "$mb" merge "$work/s1" "$work/s2" -o "$work/smerged" | grep -q "40 screened"
  "$mb" sweep -q "${screen[@]}" --resume -o "$work/smerged"
  results "$work/smerged"
  same "$work/screened" "$work/smerged"
  # Full scale (docs/sweeps.md): a shard keeps unit errors only near its own best. With
  # screen.keep_sigmas=0 the shards drop most; the merge keeps out those the sweep's best proves out
  # of reach, screens the others again, and confirms the same rows. `sweep --resume -o DIR`
  # without --config nor --shard resumes with DIR's config.yaml and shard (shard 1 killed first).
  "$mb" sweep -q "${screen[@]}" --set screen.keep_sigmas=0 --set threads=1 --shard 1/2 -o "$work/k1" 2>/dev/null &
  kill_after_estimates $! "$work/k1" 3
  "$mb" sweep -q --resume -o "$work/k1"
  "$mb" sweep -q "${screen[@]}" --set screen.keep_sigmas=0 --shard 2/2 -o "$work/k2"
  dropped() {
    /usr/bin/python3 -c "import sqlite3,sys; print(sqlite3.connect(sys.argv[1]).execute('select count(*) from estimates where run_errors is null').fetchone()[0])" "$1/results.sqlite"
  }
  [ "$(dropped "$work/k1")" -gt 5 ] || { echo "sweep_checks: shard 1 kept every unit error"; exit 1; }
  "$mb" merge "$work/k1" "$work/k2" -o "$work/kmerged" >/dev/null
  "$mb" sweep --resume -o "$work/kmerged" 2>"$work/kerr"
  grep -q "resuming with $work/kmerged/config.yaml" "$work/kerr"
  [ "$(dropped "$work/kmerged")" -gt 0 ] || { echo "sweep_checks: the merge proved nothing out of reach"; exit 1; }
  results "$work/kmerged"
  # Against a sweep that keeps every unit error.
  "$mb" sweep -q "${screen[@]}" --set screen.keep_sigmas=100 -o "$work/keepall"
  [ "$(dropped "$work/keepall")" -eq 0 ] || { echo "sweep_checks: keep_sigmas=100 dropped unit errors"; exit 1; }
  results "$work/keepall"
  same "$work/keepall" "$work/kmerged"
  same "$work/keepall" "$work/screened"
  # Nothing to resume and no --config: refused, naming the file, and nothing created.
  if "$mb" sweep -q --resume -o "$work/nothere" 2>"$work/err"; then exit 1; fi
  grep -q "nothere/config.yaml: not found" "$work/err" && [ ! -e "$work/nothere" ]
  # Killed while screening, resumed: the same rows.
  "$mb" sweep -q "${screen[@]}" --set threads=1 -o "$work/skilled" 2>/dev/null &
  kill_after_estimates $! "$work/skilled" 5
  "$mb" sweep -q "${screen[@]}" --resume -o "$work/skilled"
  results "$work/skilled"
  same "$work/screened" "$work/skilled"
  ;;
series)
  "$mb" sweep -q "${common[@]}" --set combination_size=2 -o "$work/two"
  "$mb" report -q --no-plot "$work/two" "$work/reference" -o "$work/series" >/dev/null
  grep -q "^| 2 functions | 24 | " "$work/series/report.md"
  grep -q "^| 4 functions | 24 | " "$work/series/report.md"
  grep -q "with every added function — agrees" "$work/series/report.md"
  [ "$(grep -c '^"2 functions",' "$work/series/candidates.csv")" -eq 24 ]
  # Full precision: the means read back bit for bit from the database.
  /usr/bin/python3 - "$work/reference/results.sqlite" "$work/series/candidates.csv" <<'PY'
import csv, sqlite3, sys
db = dict(sqlite3.connect(sys.argv[1]).execute("select id, mean from candidates"))
rows = [r for r in csv.DictReader(open(sys.argv[2])) if r["series"] == "4 functions"]
assert len(rows) == 24 and all(float(r["mean_error"]) == db[int(r["id"])] for r in rows), "means lost precision"
PY
  # The grid's bias, measured in the run against the continuous closed forms: a grid admits fewer
  # distributions than [0, 1], so the LP's error can only be the smaller (docs/reference.md §2).
  "$mb" sweep -q --set dataset=tiny --set sample=2 --set sample_seed=3 --set lp.grid=64 \
      --set "references=[lp:power4, hausdorff4, lp:trig4, tmsm]" -o "$work/bias"
  "$mb" report -q --no-plot "$work/bias" -o "$work/bias.report" >/dev/null
  for basis in "power moments" "trigonometric moments"; do
    line=$(grep "^- $basis: lp:" "$work/bias.report/report.md")
    gap=$(sed -E 's/.*understates the error by (-?[0-9.e+-]+) percentage points/\1/' <<<"$line")
    /usr/bin/python3 -c "import sys; g = float(sys.argv[1]); assert g > -1e-6, g" "$gap"
  done
  # A sweep against the receiver-plane reference measures other errors: refused, no output.
  "$mb" sweep -q "${common[@]}" --set reference=receiver_plane -o "$work/plane"
  grep -q "oracle" <("$mb" report -q --no-plot "$work/plane" -o "$work/plane.report")
  if "$mb" report -q --no-plot "$work/two" "$work/plane" -o "$work/mixed" 2>"$work/err"; then exit 1; fi
  grep -q "cannot share a report" "$work/err"
  [ ! -e "$work/mixed" ]
  ;;
transparency)
  oit=(--set target=transparency --set dataset="$tiny_oit" --set lp.grid=64 --set sample=10 --set sample_seed=3 --set "oit_references=[exact, wboit, mboit_power4]")
  target_checks oit 10 "${oit[@]}"
  # MBOIT's basis marked; its sharp bound as `oit` measures lp:power4 (one LP per fragment there
  # too; single-fragment pixels, exact in both, are solved by oit and skipped by the sweep).
  "$mb" sweep -q --set target=transparency --set dataset="$tiny_oit" --set lp.grid=64 --set "oit_references=[mboit_power4]" \
      --set "candidates=[z; z^2; z^3; z^4, z; exp(z); exp(-z); log(1+z)]" -o "$work/oitm"
  results "$work/oitm"
  grep -q "| z; z^2; z^3; z^4 (MBOIT power4's basis) |" "$work/oitm.report/report.md"
  grep -q "MBOIT power4's basis: z; z^2; z^3; z^4, " "$work/oitm.report/report.md"
  "$mb" oit -q --set dataset="$tiny_oit" --set lp.grid=64 --set images=false --set deep_frames=false --set "techniques=[lp:power4]" -o "$work/oit_cmd" >/dev/null
  /usr/bin/python3 - "$work/oitm.report/candidates.csv" "$work/oit_cmd/errors.csv" <<'PY'
import csv, sys
sweep = {r["functions"]: float(r["mean_error"]) for r in csv.DictReader(open(sys.argv[1]))}
oit = {r["camera"]: float(r["transmittance_error"]) for r in csv.DictReader(open(sys.argv[2]))}
a, b = sweep["z; z^2; z^3; z^4"], oit["all"]
assert abs(a - b) <= 1e-9, (a, b)
PY
  ;;
scattering)
  sc=(--set target=scattering --set dataset=scattering_tiny --set combination_size=2 --set sample=8 --set sample_seed=3 --set "scatter_references=[pss_msm4]")
  target_checks sc 8 "${sc[@]}"
  # The power moments' candidate as `scatter` measures pss_lp:power4 at beta 0 against pss_exact.
  "$mb" sweep -q --set target=scattering --set dataset=scattering_tiny --set "scatter_references=[]" \
      --set "candidates=[z; z^2; z^3; z^4, z; exp(z); exp(-z); log(1+z)]" -o "$work/scm"
  results "$work/scm"
  # The report's rank of power moments is the one their mean error takes among the two candidates
  # in candidates.csv (1 + the candidates with less error).
  /usr/bin/python3 - "$work/scm.report/candidates.csv" "$work/scm.report/report.md" <<'PY'
import csv, re, sys
errors = {r["functions"]: float(r["mean_error"]) for r in csv.DictReader(open(sys.argv[1]))}
assert len(set(errors.values())) == 2, errors  # two candidates, no tie
power = errors["z; z^2; z^3; z^4"]
better = sum(e < power for e in errors.values())
line = re.search(r"power moments: .*rank (\d+) of (\d+) \((\d+) better", open(sys.argv[2]).read())
assert line and line.groups() == (str(1 + better), "2", str(better)), (line and line.groups(), errors)
PY
  grep -q "Target scattering" "$work/scm.report/report.md"
  "$mb" scatter -q --set dataset=scattering_tiny --set images=false --set scatter.beta=0 --set scatter.reference=pss_exact \
      --set "techniques=[pss_lp:power4, pss_lp:z; exp(z); exp(-z); log(1+z)]" -o "$work/sc_cmd" >/dev/null
  /usr/bin/python3 - "$work/scm.report/candidates.csv" "$work/sc_cmd/errors.csv" <<'PY'
import csv, sys
sweep = {r["functions"]: float(r["mean_error"]) for r in csv.DictReader(open(sys.argv[1]))}
rows = [r for r in csv.DictReader(open(sys.argv[2])) if r["scene"] == "all" and r["technique"] == "pss_lp:power4"]
a, b = sweep["z; z^2; z^3; z^4"], float(rows[0]["mean_error"])
assert abs(a - b) <= 1e-12 * max(1.0, b), (a, b)
PY
  # The rays whose LP failed (answered lit, after pss_lp's retry in exact arithmetic): `scatter`'s
  # report counts as many as the sweep does for the same candidate, over the same rays.
  /usr/bin/python3 - "$work/scm.report/candidates.csv" "$work/sc_cmd/report.md" <<'PY'
import csv, sys
name = "z; exp(z); exp(-z); log(1+z)"
row = [r for r in csv.DictReader(open(sys.argv[1])) if r["functions"] == name][0]
sweep = int(row["infeasible"]) + int(row["unstable"])
md = open(sys.argv[2]).read().split("## Rays a technique could not answer")[1]
cells = [[c.strip() for c in line.strip("|").split("|")] for line in md.splitlines()
         if line.startswith("| pss_lp:" + name + " | all |")]
assert len(cells) == 1, cells
failed, rays = int(cells[0][4]), int(cells[0][5])
assert failed == sweep and rays == int(row["fragments"]), (failed, sweep, rays)
PY
  # Options another target reads are refused, naming the key.
  if "$mb" sweep -q --set target=scattering --set dataset=scattering_tiny --set kernel.size=5 -o "$work/scbad" 2>"$work/err"; then exit 1; fi
  grep -q "kernel.size" "$work/err"
  [ ! -e "$work/scbad" ]
  ;;
esac
echo "sweep_checks $check: ok"
