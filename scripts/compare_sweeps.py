#!/usr/bin/python3
"""Compare two sweeps' rankings of the same candidates (results/FINDINGS.md §9c).

usage: compare_sweeps.py A/results.sqlite B/results.sqlite [--top N] [--with-estimates]

Prints the candidates both sweeps finished, Spearman's and Kendall's rank correlation of their mean
errors, how many of A's best N and best 1 % are among B's, the mean error by family (power, trig,
mixed) in each, and failures (infeasible or unstable LPs) per sweep. --with-estimates ranks a
screened sweep's candidates without an exact mean by their last estimate (results/
sweep-<dataset>-full/); Kendall's tau is left out above 3 000 candidates (quadratic).
"""
import argparse
import sqlite3
import sys


def load(path, with_estimates=False):
    con = sqlite3.connect(f"file:{path}?mode=ro", uri=True)
    rows = con.execute(
        "select name, mean, infeasible, unstable from candidates where mean is not null"
    ).fetchall()
    out = {name: (mean, infeasible + unstable) for name, mean, infeasible, unstable in rows}
    if with_estimates:
        for name, mean, failed in con.execute(
                "select name, mean, failed from estimates order by id, stage"):
            if name not in out or out[name][2:]:  # the last stage's estimate of a screened one
                out[name] = (mean, failed, "estimate")
    return out


def ranks(values):
    order = sorted(range(len(values)), key=lambda i: values[i])
    r = [0.0] * len(values)
    i = 0
    while i < len(order):  # average ranks over ties
        j = i
        while j + 1 < len(order) and values[order[j + 1]] == values[order[i]]:
            j += 1
        for k in range(i, j + 1):
            r[order[k]] = (i + j) / 2
        i = j + 1
    return r


def pearson(x, y):
    n = len(x)
    mx, my = sum(x) / n, sum(y) / n
    sxy = sum((a - mx) * (b - my) for a, b in zip(x, y))
    sxx = sum((a - mx) ** 2 for a in x)
    syy = sum((b - my) ** 2 for b in y)
    return sxy / (sxx * syy) ** 0.5


def kendall(x, y):
    concordant = discordant = 0
    for i in range(len(x)):
        for j in range(i + 1, len(x)):
            s = (x[i] - x[j]) * (y[i] - y[j])
            concordant += s > 0
            discordant += s < 0
    return (concordant - discordant) / (concordant + discordant)


def family(name):
    funcs = [f.strip() for f in name.split(";")]
    trig = sum(("sin" in f or "cos" in f) for f in funcs)
    power = sum(f == "z" or f.startswith("z^") for f in funcs)
    if power == len(funcs):
        return "power"
    if trig == len(funcs):
        return "trigonometric"
    return "mixed"


def main():
    p = argparse.ArgumentParser()
    p.add_argument("a")
    p.add_argument("b")
    p.add_argument("--top", type=int, default=20)
    p.add_argument("--with-estimates", action="store_true")
    args = p.parse_args()
    a, b = load(args.a, args.with_estimates), load(args.b, args.with_estimates)
    names = sorted(set(a) & set(b))
    if len(names) < 3:
        sys.exit(f"compare_sweeps: only {len(names)} candidates in both sweeps")
    xa = [a[n][0] for n in names]
    xb = [b[n][0] for n in names]
    print(f"candidates in both: {len(names)}")
    print(f"mean error, A: {100 * sum(xa) / len(xa):.4f} %, B: {100 * sum(xb) / len(xb):.4f} %")
    print(f"Spearman rank correlation: {pearson(ranks(xa), ranks(xb)):.4f}")
    if len(names) <= 3000:
        print(f"Kendall tau: {kendall(xa, xb):.4f}")
    for top in (args.top, max(1, len(names) // 100)):
        top_a = set(sorted(names, key=lambda n: a[n][0])[:top])
        top_b = set(sorted(names, key=lambda n: b[n][0])[:top])
        print(f"A's best {top} among B's best {top}: {len(top_a & top_b)}")
    for label, d in (("A", a), ("B", b)):
        best = sorted(names, key=lambda n: d[n][0])[:5]
        print(f"best 5 in {label}: " + " | ".join(f"{n} ({100 * d[n][0]:.4f} %)" for n in best))
        print(f"LP failures in {label}: {sum(d[n][1] for n in names)}")
    families = {}
    for n in names:
        families.setdefault(family(n), []).append(n)
    for f, members in sorted(families.items()):
        ma = sum(a[n][0] for n in members) / len(members)
        mb = sum(b[n][0] for n in members) / len(members)
        print(f"{f}: {len(members)} candidates, A {100 * ma:.4f} %, B {100 * mb:.4f} %")


if __name__ == "__main__":
    main()
