#!/usr/bin/python3
"""Histogram of sweep candidates by mean error with the reference techniques marked, as in the
seed paper's Figure 4. Reads momentbench report's histogram.csv and references.csv; writes
<out>.png and <out>.pdf. Run with Debian's /usr/bin/python3 (python3-matplotlib)."""
import argparse
import csv

from plot_common import save_png_and_pdf  # first: it selects the headless backend

import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--histogram", required=True)
    parser.add_argument("--references", required=True)
    parser.add_argument("--out", required=True, help="output path without extension")
    args = parser.parse_args()

    with open(args.histogram) as f:
        rows = list(csv.DictReader(f))
    lo = [100 * float(r["error_lo"]) for r in rows]
    hi = [100 * float(r["error_hi"]) for r in rows]
    counts = [int(r["candidates"]) for r in rows]
    with open(args.references) as f:
        references = [(r["technique"], 100 * float(r["mean_error"])) for r in csv.DictReader(f)]

    fig, ax = plt.subplots(figsize=(7, 3.6))
    ax.bar(lo, counts, width=[h - l for l, h in zip(lo, hi)], align="edge", color="#7f9fbf", edgecolor="#4f6f8f",
           linewidth=0.4, label="candidates")
    top = max(counts) if counts else 1
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for i, (name, error) in enumerate(r for r in references if r[0] != "pcf"):
        ax.axvline(error, color=colours[i % len(colours)], linestyle="--", linewidth=1)
        ax.text(error, top * (0.95 - 0.08 * (i % 6)), " " + name, color=colours[i % len(colours)], fontsize=7,
                rotation=0, va="top")
    ax.yaxis.set_major_locator(matplotlib.ticker.MaxNLocator(integer=True))
    ax.set_xlabel("mean |PCF - G| over receiver fragments (%)")
    ax.set_ylabel("candidates")
    ax.set_title("Sweep candidates by mean error")
    save_png_and_pdf(fig, args.out, "plot_histogram.py")


if __name__ == "__main__":
    main()
