#!/usr/bin/python3
"""How well a screened sweep's estimates agree with exact means at full scale (docs/sweeps.md,
"Calibration"; results/sweep-<dataset>-full/).

usage: screen_calibration.py SCREENED/results.sqlite EXACT/results.sqlite

SCREENED is a screened sweep (its estimates table), EXACT a sweep of (some of) the same candidates
evaluated exactly (its candidates table). For every candidate in both, and for each screening stage
it has an estimate of, the miss z = (estimate - exact mean) / standard error. Prints, per stage, how
many, the root mean square of z (1 when the standard errors are honest), the largest |z|, how many
lie beyond 3 (a normal law expects 0.27 %), and the mean of z (a bias of the estimator).
"""
import math
import sqlite3
import sys


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    screened = sqlite3.connect(f"file:{sys.argv[1]}?mode=ro", uri=True)
    exact_db = sqlite3.connect(f"file:{sys.argv[2]}?mode=ro", uri=True)
    exact = dict(exact_db.execute("select name, mean from candidates"))
    stages = {}
    for stage, name, mean, se in screened.execute("select stage, name, mean, se from estimates"):
        if name in exact and se > 0:
            stages.setdefault(stage, []).append((name, (mean - exact[name]) / se))
    if not stages:
        sys.exit("screen_calibration: no candidate is both screened and exact")
    print("| stage | candidates | rms of z | largest abs(z) | beyond 3 | expected beyond 3 | mean z |")
    print("|---|---|---|---|---|---|---|")
    for stage in sorted(stages):
        z = [v for _, v in stages[stage]]
        n = len(z)
        rms = math.sqrt(sum(v * v for v in z) / n)
        worst = max(stages[stage], key=lambda p: abs(p[1]))
        beyond = sum(abs(v) > 3 for v in z)
        print(f"| {stage} | {n} | {rms:.3f} | {abs(worst[1]):.2f} ({worst[0]}) | {beyond} | "
              f"{0.0027 * n:.1f} | {sum(z) / n:+.3f} |")


if __name__ == "__main__":
    main()
