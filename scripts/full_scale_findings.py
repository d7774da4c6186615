#!/usr/bin/python3
"""The full-scale figures of results/FINDINGS.md (issue 60) from published sweeps.

usage: full_scale_findings.py results/sweep-default-full [results/sweep-translucent-full ...]

Reads each directory's candidates.csv (one row per candidate: the exact mean where `exact` is true,
else the screen's last estimate with its standard error), references.csv and, when present,
exact-sample.csv (the seeded sample of 1 000 evaluated exactly). Prints markdown: per series the
best, median and worst; the ranks of power and trigonometric moments among the four-function
candidates; how many candidates lie within 0.01, 0.05 and 0.1 pp of the best, with the interval
that two standard errors either way give; where each reference technique falls; and, for two or
more directories, the overlap of their top 20 and top 1 % and Spearman's rank correlation on the
exact sample they share. Nothing here reads a database: the published CSVs are enough.
"""
import csv
import os
import sys

import numpy as np

from compare_sweeps import pearson, ranks  # ranks average ties

POWER4 = "z; z^2; z^3; z^4"
TRIG4 = "sin(2 pi z); cos(2 pi z); sin(4 pi z); cos(4 pi z)"
MARGINS_PP = (0.01, 0.05, 0.1)
Z = 2.0  # standard errors either way for the intervals


def read_candidates(path):
    rows = []
    with open(path) as f:
        for r in csv.DictReader(f):
            if not r["mean_error"]:
                continue
            se = float(r["standard_error"] or 0)
            exact = r["exact"].lower() in ("true", "1", "yes")
            rows.append((r["series"], r["functions"], float(r["mean_error"]), 0.0 if exact else se,
                         exact))
    return rows


def read_references(path):
    with open(path) as f:
        return [(r["technique"], float(r["mean_error"])) for r in csv.DictReader(f)]


def pct(x):
    return f"{100 * x:.4f}"


def series_table(rows):
    print("| series | candidates | exact | best % | median % | worst % | best candidate |")
    print("|---|---|---|---|---|---|---|")
    for name in sorted({r[0] for r in rows}):
        s = sorted((r for r in rows if r[0] == name), key=lambda r: r[2])
        means = np.array([r[2] for r in s])
        print(f"| {name} | {len(s)} | {sum(r[4] for r in s)} | {pct(means[0])} | "
              f"{pct(np.median(means))} | {pct(means[-1])} | {s[0][1]} |")


def rank_with_interval(four, value, se):
    """Rank of a mean among `four` (1 = best), with the ranks two standard errors allow."""
    m = np.array([r[2] for r in four])
    e = np.array([r[3] for r in four])
    point = 1 + int(np.sum(m < value))
    best = 1 + int(np.sum(m + Z * e < value - Z * se))
    worst = 1 + int(np.sum(m - Z * e < value + Z * se))
    return point, best, worst


def basis_ranks(four):
    by_name = {r[1]: r for r in four}
    print("| basis | mean % | mean is | rank among all | rank interval (±2 SE) |")
    print("|---|---|---|---|---|")
    for label, name in (("power moments", POWER4), ("trigonometric moments", TRIG4)):
        if name not in by_name:
            print(f"| {label} | — | — | — | — |")
            continue
        _, _, mean, se, exact = by_name[name]
        point, lo, hi = rank_with_interval(four, mean, se)
        print(f"| {label} | {pct(mean)} | {'exact' if exact else 'estimate'} | "
              f"{point} of {len(four)} | {lo}–{hi} |")


def plateau(four):
    m = np.array([r[2] for r in four])
    e = np.array([r[3] for r in four])
    best = m.min()
    print("| within | candidates | interval (±2 SE) |")
    print("|---|---|---|")
    for pp in MARGINS_PP:
        limit = best + pp / 100
        print(f"| {pp} pp | {int(np.sum(m <= limit))} | {int(np.sum(m + Z * e <= limit))}–"
              f"{int(np.sum(m - Z * e <= limit))} |")


def references_table(four, refs):
    m = np.array([r[2] for r in four])
    print("| technique | mean % | four-function candidates better | percentile |")
    print("|---|---|---|---|")
    for name, mean in sorted(refs, key=lambda r: r[1]):
        better = int(np.sum(m < mean))
        print(f"| {name} | {pct(mean)} | {better} of {len(m)} | {100 * better / len(m):.1f} |")


def spearman(a, b):
    return pearson(ranks(a), ranks(b))


def read_exact_sample(path):
    with open(path) as f:
        return {r["functions"]: float(r["mean_error"]) for r in csv.DictReader(f) if r["mean_error"]}


def cross_dataset(dirs, fours):
    names = [os.path.basename(d.rstrip("/")) for d in dirs]
    print("| A | B | top 20 of A in B's top 20 | top 1 % of A in B's top 1 % | "
          "Spearman on the exact sample (n) |")
    print("|---|---|---|---|---|")
    for i in range(len(dirs)):
        for j in range(i + 1, len(dirs)):
            a = [r[1] for r in sorted(fours[i], key=lambda r: r[2])]
            b = [r[1] for r in sorted(fours[j], key=lambda r: r[2])]
            onepct = max(1, min(len(a), len(b)) // 100)
            top20 = len(set(a[:20]) & set(b[:20]))
            top1 = len(set(a[:onepct]) & set(b[:onepct]))
            rho = "—"
            pa, pb = (os.path.join(d, "exact-sample.csv") for d in (dirs[i], dirs[j]))
            if os.path.exists(pa) and os.path.exists(pb):
                ea, eb = read_exact_sample(pa), read_exact_sample(pb)
                common = sorted(set(ea) & set(eb))
                if len(common) > 2:
                    rho = (f"{spearman([ea[c] for c in common], [eb[c] for c in common]):.3f} "
                           f"({len(common)})")
            print(f"| {names[i]} | {names[j]} | {top20} | {top1} of {onepct} | {rho} |")


def main():
    dirs = sys.argv[1:]
    if not dirs:
        sys.exit(__doc__)
    fours = []
    for d in dirs:
        rows = read_candidates(os.path.join(d, "candidates.csv"))
        four = [r for r in rows if r[0].startswith("4")]
        fours.append(four)
        print(f"## {os.path.basename(d.rstrip('/'))}\n")
        series_table(rows)
        print()
        basis_ranks(four)
        print()
        plateau(four)
        print()
        refs = os.path.join(d, "references.csv")
        if os.path.exists(refs):
            references_table(four, read_references(refs))
            print()
    if len(dirs) > 1:
        print("## Across datasets\n")
        cross_dataset(dirs, fours)


if __name__ == "__main__":
    main()
