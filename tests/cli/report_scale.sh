#!/usr/bin/env bash
# report_scale.sh MOMENTBENCH WORKDIR: `report` on a sweep of all C(37, 4) = 66 045 candidates
# (docs/sweeps.md, "Full scale"). A real screened sweep of 200 candidates on the tiny dataset is
# grown to every combination of its catalog: the other 65 845 join as estimates screened out by
# their shard (as a full run stores them), their means and standard errors drawn from the real
# ones. The report must rank all 66 045, write one CSV row each, plot them, and stay under 2 GB of
# memory (the peak resident size of the process, from getrusage).
set -eu
mb=$1 work=$2
rm -rf "$work" && mkdir -p "$work"
"$mb" sweep -q --set dataset=tiny --set resolution=32 --set sample=200 --set sample_seed=1 \
  --set lp.grid=32 --set "references=[vsm,hamburger4]" --screen 0.1 --set screen.top=5 \
  --set threads=2 -o "$work/sweep"
/usr/bin/python3 - "$work/sweep/results.sqlite" <<'PY'
import itertools, random, sqlite3, sys
db = sqlite3.connect(sys.argv[1])
rows = db.execute("select name, mean, se, solved, failed from estimates where stage = 1").fetchall()
functions = sorted({f for (name, *_ ) in rows for f in name.split("; ")})
assert len(functions) == 37, len(functions)
have = {frozenset(name.split("; ")) for (name, *_) in rows}
have |= {frozenset(n.split("; ")) for (n,) in db.execute("select name from candidates")}
random.seed(7)
next_id = 1 + max(i for (i,) in db.execute("select id from estimates union select id from candidates"))
new = []
for combo in itertools.combinations(functions, 4):
    if frozenset(combo) in have:
        continue
    _, mean, se, solved, failed = random.choice(rows)
    new.append((next_id, 1, "; ".join(combo), mean * random.uniform(0.9, 1.6), se, solved, failed,
                None, 0.1, mean, 0))
    next_id += 1
db.executemany("insert into estimates values (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)", new)
db.execute("update meta set value = ? where key = 'planned'", (str(66045),))
db.commit()
total = db.execute("select count(distinct id) from (select id from estimates union select id from candidates)").fetchone()[0]
assert total == 66045, total
PY
/usr/bin/python3 - "$mb" "$work" <<'PY'
import resource, subprocess, sys, time
mb, work = sys.argv[1:]
start = time.monotonic()
subprocess.run([mb, "report", "-q", f"{work}/sweep", "-o", f"{work}/report"], check=True,
               stdout=subprocess.DEVNULL)
seconds = time.monotonic() - start
peak_mb = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024
print(f"report of 66045 candidates: {seconds:.1f} s, peak resident {peak_mb:.0f} MB")
assert peak_mb < 2048, peak_mb
assert seconds < 60, seconds  # issue 60: a report of every candidate within a minute
PY
rows=$(($(wc -l < "$work/report/candidates.csv") - 1))
[ "$rows" -eq 66045 ] || { echo "report_scale: candidates.csv has $rows rows, expected 66045"; exit 1; }
grep -q "66045" "$work/report/report.md"
ls "$work/report/"*.png >/dev/null
