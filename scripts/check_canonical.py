#!/usr/bin/python3
"""The Hamburger closed forms against their own mathematics in 60-digit arithmetic.

For each worst case of a `momentbench verify` run (worst.csv, kind largest_dG) of hamburger4 or
hamburger6, the sharp lower bound of the Hamburger problem is recomputed with mpmath from the
instance's own depths and weights: the canonical representation through z_f (Chebyshev-Markov-
Stieltjes; seed 000's Algorithm for n = 2, the same construction for n = 3), i.e. solve B c =
(1, z_f, ..., z_f^n) with the Hankel matrix B of the exact moments, take the roots of
sum c_i z^i and z_f as the support, its weights from the Vandermonde system, and G = the mass
strictly below z_f. Prints, per technique, how often the closed form and the LP (finest grid)
agree with it, their largest errors, and how far the same bound moves when computed from the
moments rounded to double (what the closed form reads).

    /usr/bin/python3 scripts/check_canonical.py OUT/worst.csv [TOLERANCE]
"""
import csv
import sys

import mpmath as mp

mp.mp.dps = 60


def canonical_lower(moments, zf, n):
    """G of the canonical representation through zf; None for a singular Hankel matrix (a
    determinate moment vector) or when the representation is not a distribution."""
    hankel = mp.matrix(n + 1, n + 1)
    for i in range(n + 1):
        for j in range(n + 1):
            hankel[i, j] = moments[i + j]
    if abs(mp.det(hankel)) < mp.mpf(10) ** -45:
        return None  # on the boundary of the moment cone: determinate, no canonical family
    c = mp.lu_solve(hankel, mp.matrix([zf ** i for i in range(n + 1)]))
    roots = mp.polyroots([c[i] for i in range(n, -1, -1)], maxsteps=400, extraprec=400)
    points = [zf] + list(roots)
    if any(abs(mp.im(p)) > mp.mpf(10) ** -25 for p in points):
        return None
    points = [mp.re(p) for p in points]
    vandermonde = mp.matrix(n + 1, n + 1)
    for i in range(n + 1):
        for j in range(n + 1):
            vandermonde[i, j] = points[j] ** i
    weights = mp.lu_solve(vandermonde, mp.matrix([moments[i] for i in range(n + 1)]))
    if min(weights) < -mp.mpf(10) ** -20:
        return None
    return sum(weights[j] for j in range(n + 1) if points[j] < zf)


def main():
    tolerance = float(sys.argv[2]) if len(sys.argv) > 2 else 1e-6
    stats = {}
    for row in csv.DictReader(open(sys.argv[1])):
        technique = row["technique"]
        if row["kind"] != "largest_dG" or technique not in ("hamburger4", "hamburger6"):
            continue
        n = 3 if technique == "hamburger6" else 2
        zf = mp.mpf(row["zf"])
        depths = [mp.mpf(x) for x in row["depths"].split()]
        weights = [mp.mpf(x) for x in row["weights"].split()]
        total = sum(weights)
        moments = [sum(w * z ** k for z, w in zip(depths, weights)) / total
                   for k in range(2 * n + 1)]
        exact = canonical_lower(moments, zf, n)
        # The same bound from the moments as the closed form read them (rounded to double).
        read = [mp.mpf(1)] + [mp.mpf(x) for x in row["moments"].split()]
        from_double = canonical_lower(read, zf, n)
        finest = [k for k in row if k.startswith("G_lp_")][-1]
        s = stats.setdefault(technique, {"cases": 0, "not a distribution": 0,
                                         "closed form agrees": 0, "LP agrees": 0,
                                         "closed form max error": 0.0, "LP max error": 0.0,
                                         "rounding max effect": 0.0})
        s["cases"] += 1
        if exact is None:
            s["not a distribution"] += 1
            continue
        closed_form = abs(float(row["G_closed_form"]) - float(exact))
        lp = float(row[finest])
        lp_error = abs(lp - float(exact)) if lp == lp else float("inf")
        s["closed form agrees"] += closed_form <= tolerance
        s["LP agrees"] += lp_error <= tolerance
        s["closed form max error"] = max(s["closed form max error"], closed_form)
        s["LP max error"] = max(s["LP max error"], lp_error)
        if from_double is not None:
            s["rounding max effect"] = max(s["rounding max effect"], abs(float(from_double - exact)))
    print("technique | cases | closed form within %g | LP (%s) within %g | closed form max error "
          "| LP max error | bound's change from rounding the moments to double"
          % (tolerance, "finest grid", tolerance))
    for technique, s in stats.items():
        print("%s | %d | %d | %d | %.3g | %.3g | %.3g" % (
            technique, s["cases"], s["closed form agrees"], s["LP agrees"],
            s["closed form max error"], s["LP max error"], s["rounding max effect"]))


if __name__ == "__main__":
    main()
