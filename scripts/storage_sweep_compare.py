#!/usr/bin/python3
"""The storage sweep against the double-precision sweep (results/FINDINGS.md §14, issue 61 item 4).

usage: storage_sweep_compare.py MOMENTBENCH STORAGE_CSV DOUBLE_CSV OUT_DIR

STORAGE_CSV: `report`'s candidates.csv of the storage sweep (results/storage-sweep/report/);
DOUBLE_CSV: the full double-precision sweep's (results/sweep-default-full/candidates.csv; its
"4 functions" series). Writes OUT_DIR/transforms.jsonl, `momentbench storage --transform optimized`
of every storage candidate (resumable: candidates already in it are skipped), and
OUT_DIR/comparison.md: each sweep's top 5 with its rank and mean in the other, the double top 20 in
the storage sweep, Spearman's rank correlation, what storage costs each candidate (storage minus
double mean error) and how that cost relates to the double error and to the transform's numbers.
Means are exact where the `exact` column says so, else a screened estimate (marked ≈).
"""
import csv
import json
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from compare_sweeps import pearson, ranks  # noqa: E402


def load(path, series_prefix=None):
    rows = {}
    for r in csv.DictReader(open(path)):
        if series_prefix and not r["series"].startswith(series_prefix):
            continue
        rows[int(r["id"])] = r
    return rows


def spearman(a, b):
    return pearson(ranks(a), ranks(b))  # ties take their average rank


def rank_by_mean(rows, ids):
    """Rank (1 = least mean error) of each of `ids` among `ids`, by rows[id]'s mean error."""
    order = sorted(ids, key=lambda i: float(rows[i]["mean_error"]))
    return {i: k + 1 for k, i in enumerate(order)}


def transforms(mb, storage, path):
    done = {}
    if os.path.exists(path):
        for line in open(path):
            t = json.loads(line)
            done[t["id"]] = t
    env = dict(os.environ, OMP_NUM_THREADS="1")
    with open(path, "a") as out:
        for i, r in sorted(storage.items()):
            if i in done:
                continue
            p = subprocess.run([mb, "storage", "--basis", r["functions"], "--transform",
                                "optimized"], capture_output=True, text=True, env=env)
            if p.returncode:
                sys.exit(f"storage --basis '{r['functions']}': {p.stderr.strip()}")
            t = json.loads(p.stdout)
            t["id"] = i
            out.write(json.dumps(t) + "\n")
            out.flush()
            done[i] = t
    return done


def mean_text(r):
    m = 100 * float(r["mean_error"])
    if r["exact"] == "1":
        return f"{m:.4f}"
    return f"≈ {m:.4f} ± {100 * float(r['standard_error']):.4f}"


def main():
    if len(sys.argv) != 5:
        sys.exit(__doc__)
    mb, storage_csv, double_csv, out_dir = sys.argv[1:]
    storage = load(storage_csv)
    double = load(double_csv, "4 functions")
    missing = [i for i in storage if i not in double]
    if missing:
        sys.exit(f"{double_csv}: no row for candidates {missing[:5]}")
    os.makedirs(out_dir, exist_ok=True)
    t = transforms(mb, storage, os.path.join(out_dir, "transforms.jsonl"))
    ids = sorted(storage)
    s = [float(storage[i]["mean_error"]) for i in ids]
    d = [float(double[i]["mean_error"]) for i in ids]
    cost = [a - b for a, b in zip(s, d)]
    s_rank = rank_by_mean(storage, ids)
    d_rank = rank_by_mean(double, ids)
    all_rank = rank_by_mean(double, double)
    md = [f"# The storage sweep against double precision ({len(ids)} candidates)", "",
          f"`scripts/storage_sweep_compare.py` on `{storage_csv}` and `{double_csv}`. Mean error %;",
          "≈ marks a screened estimate ± its standard error. Ranks: among these candidates, and for",
          f"double also among all {len(double)}.", "",
          "| best 5 by | candidate | 16-bit, own optimized transform | rank | double | rank"
          " (of all) |", "|---|---|---|---|---|---|"]
    for name, order in (("16-bit", s_rank), ("double", d_rank)):
        for i in sorted(ids, key=lambda i: order[i])[:5]:
            md.append(f"| {name} | {storage[i]['functions']} | "
                      f"{mean_text(storage[i])} | {s_rank[i]} | {mean_text(double[i])} | "
                      f"{d_rank[i]} ({all_rank[i]}) |")
    top20 = sorted(double, key=lambda i: float(double[i]["mean_error"]))[:20]
    in_sweep = [i for i in top20 if i in storage]
    best = min(in_sweep, key=lambda i: s_rank[i]) if in_sweep else None
    n = len(ids)
    md += ["", f"- Spearman's rank correlation of the two errors: {spearman(s, d):.3f} over all "
           f"{n}; of the storage cost with the double error: {spearman(cost, d):.3f} (the cost is "
           "the 16-bit minus the double error: mostly the subtraction, results/FINDINGS.md §14).",
           f"- Storage cost (16-bit minus double): {100 * min(cost):.4f} to "
           f"{100 * max(cost):.4f} pp, median {100 * sorted(cost)[n // 2]:.4f} pp.",
           f"- The double top 20 in this sweep: {len(in_sweep)} of them; the best of them ranks "
           + (f"{s_rank[best]} ({storage[best]['functions']}, {mean_text(storage[best])})."
              if best is not None else "—."),
           f"- Top-5 overlap {len(set(sorted(ids, key=s_rank.get)[:5]) & set(sorted(ids, key=d_rank.get)[:5]))}, "
           f"top-20 overlap {len(set(sorted(ids, key=s_rank.get)[:20]) & set(sorted(ids, key=d_rank.get)[:20]))}.",
           "", "Spearman's correlation of the transform's numbers (`storage`) with each error:", "",
           "| quantity | 16-bit error | storage cost | double error |", "|---|---|---|---|"]
    for key in ("entropy_gain_bits", "transformed_hull_volume", "hull_volume"):
        v = [t[i][key] for i in ids]
        md.append(f"| {key} | {spearman(v, s):.3f} | {spearman(v, cost):.3f} | "
                  f"{spearman(v, d):.3f} |")
    open(os.path.join(out_dir, "comparison.md"), "w").write("\n".join(md) + "\n")
    print("\n".join(md))


if __name__ == "__main__":
    main()
