#!/usr/bin/python3
"""The true CDF of one kernel's depth distribution and the sharp lower bounds of Problem 1 for
m = 2, 3, 4, one panel per basis, as in the seed paper's Figure 3. Reads momentbench bounds'
bounds.csv and distribution.csv; writes <out>.png and <out>.pdf. Run with Debian's /usr/bin/python3
(python3-matplotlib)."""
import argparse
import csv
import re

from plot_common import save_png_and_pdf  # first: it selects the headless backend

import matplotlib.pyplot as plt  # noqa: E402

# The seed paper's colours: m = 2 red, m = 3 cyan, m = 4 green; the CDF blue.
COLOURS = {2: "#d62728", 3: "#17becf", 4: "#2ca02c"}


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--bounds", required=True)
    parser.add_argument("--distribution", required=True)
    parser.add_argument("--out", required=True, help="output path without extension")
    args = parser.parse_args()

    with open(args.bounds) as f:
        reader = csv.reader(f)
        header = next(reader)
        rows = [r for r in reader]
    zf = [float(r[0]) for r in rows]
    series = {}  # basis -> [(m, values)]
    for column, name in enumerate(header[2:], start=2):
        match = re.fullmatch(r"(.*) m=(\d+)", name)
        basis, m = match.group(1), int(match.group(2))
        values = [float(r[column]) if r[column] else float("nan") for r in rows]
        series.setdefault(basis, []).append((m, values))
    with open(args.distribution) as f:
        atoms = sorted((float(r["depth"]), float(r["weight"])) for r in csv.DictReader(f))
    total = sum(w for _, w in atoms)

    # The CDF as an exact step function (mass strictly below z_f), not from the samples.
    lo, hi = zf[0], zf[-1]
    step_x, step_y, mass = [lo], [0.0], 0.0
    for depth, weight in atoms:
        if depth <= lo:
            mass += weight / total
            step_y[0] = mass
            continue
        if depth >= hi:
            break
        step_x += [depth, depth]
        step_y += [mass, mass + weight / total]
        mass += weight / total
    step_x.append(hi)
    step_y.append(mass)

    panels = list(series.items())
    fig, axes = plt.subplots(1, len(panels), figsize=(3.6 * len(panels), 3.2), squeeze=False, sharey=True)
    for ax, (basis, curves) in zip(axes[0], panels):
        ax.plot(step_x, step_y, color="#1f77b4", linewidth=1.6, label="CDF $F_Z$")
        for m, values in curves:
            ax.plot(zf, values, color=COLOURS.get(m, None), linewidth=1.1, label=f"$m = {m}$")
        ax.set_title(basis, fontsize=9)
        ax.set_xlabel("$z_f$")
        ax.set_xlim(lo, hi)
        ax.set_ylim(-0.02, 1.02)
        ax.grid(alpha=0.25, linewidth=0.5)
    axes[0][0].set_ylabel("shadow intensity")
    axes[0][-1].legend(loc="upper left", fontsize=7)
    save_png_and_pdf(fig, args.out, "plot_bounds.py")


if __name__ == "__main__":
    main()
