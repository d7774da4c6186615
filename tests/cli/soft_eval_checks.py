"""Checks one `eval` run under area lights (tests/cli/CMakeLists.txt, cli.eval_soft):
each per-angle row of errors.csv is its views merged (receiver-weighted means, the maximum), the
report has the per-angle table and the blocker audit, and blocker_audit.csv's rows keep the
audit's own invariants (the bounds ordered, their penumbrae ordered, `outside` as stated)."""
import csv
import sys
from collections import defaultdict

out = sys.argv[1]
rows = list(csv.DictReader(open(out + "/errors.csv")))
angle_rows = {(r["technique"], r["view"]): r for r in rows
              if r["scene"] == "all" and r["view"] != "all"}
views = defaultdict(list)
for r in rows:
    if r["scene"] != "all":
        views[(r["technique"], r["view"].rsplit("_", 1)[1])].append(r)
assert angle_rows, "no per-angle rows in errors.csv"
lp_rows = [r for r in rows if r["technique"] == "msm_soft:lp:power4" and r["scene"] == "all"]
assert lp_rows and all(int(r["failures"]) == 0 for r in lp_rows), lp_rows
assert set(angle_rows) == set(views), (sorted(angle_rows), sorted(views))
for key, merged in angle_rows.items():
    parts = views[key]
    n = sum(int(p["receivers"]) for p in parts)
    assert int(merged["receivers"]) == n, key
    for column in ("mean_error", "leak", "over_darkening"):
        mean = sum(int(p["receivers"]) * float(p[column]) for p in parts) / n
        assert abs(mean - float(merged[column])) <= 1e-12, (key, column, mean, merged[column])
    assert float(merged["max_error"]) == max(float(p["max_error"]) for p in parts), key

report = open(out + "/report.md").read()
assert "## Per light angle" in report
assert "## msm_soft's blocker search against its sharp bounds" in report

audit = list(csv.DictReader(open(out + "/blocker_audit.csv")))
assert len(audit) > 20, len(audit)
for a in audit:
    lo, hi = sorted((float(a["blocker_lo"]), float(a["blocker_hi"])))
    assert lo <= float(a["blocker_exact"]) + 1e-7 and float(a["blocker_exact"]) <= hi + 1e-7, a
    assert float(a["penumbra_lo"]) <= float(a["penumbra_hi"]), a
    seed = float(a["blocker_seed"])
    outside = seed < float(a["blocker_lo"]) - 1e-9 or seed > float(a["blocker_hi"]) + 1e-9
    assert int(a["outside"]) == outside, a
pcss = {(r["technique"], r["scene"], r["view"]): r
        for r in csv.DictReader(open(out + "/pcss_errors.csv"))}
assert set(pcss) == {(r["technique"], r["scene"], r["view"]) for r in rows}, "pcss_errors rows"
for key, r in pcss.items():
    assert r["receivers"] == next(e["receivers"] for e in rows
                                  if (e["technique"], e["scene"], e["view"]) == key), key
    if key[0] == "pcss_exact":
        assert float(r["mean_error"]) == 0 and float(r["max_error"]) == 0, r
assert any(float(r["mean_error"]) > 0 for r in pcss.values())
assert "## Against exact PCSS" in report
print("soft eval: %d per-angle rows, %d audited receivers" % (len(angle_rows), len(audit)))
