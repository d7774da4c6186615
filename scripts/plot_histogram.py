#!/usr/bin/python3
"""Histogram of sweep candidates by mean error, one series per results database (e.g. two, three
and four functions per candidate), with each series' best and median and the reference techniques
marked, as in the seed paper's Figures 3 and 4. Reads momentbench report's histogram.csv,
series.csv and references.csv; writes <out>.png and <out>.pdf. Run with Debian's /usr/bin/python3
(python3-matplotlib)."""
import argparse
import csv

from plot_common import label_room, save_png_and_pdf, stack_labels  # first: headless backend

import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker  # noqa: E402

# References drawn as lines; the others stay in the report's table (too many labels overlap).
SHOWN_REFERENCES = ("vsm", "esm", "hamburger4", "hausdorff4", "hamburger6", "tmsm", "lp:power4",
                    "lp:trig4", "oracle", "wboit", "mboit_power4", "mboit_power6", "mboit_power8",
                    "mboit_trig2", "mboit_trig3", "mboit_trig4", "lp:power6", "pss_msm4", "pss_msm6",
                    "pss_csm")
# What a candidate's mean error is of, and over what (--error, --over: a transparency sweep's
# differ from a shadow sweep's).
ERROR = {"of": "mean |PCF - G|", "over": "receiver fragments"}


def draw(ax, rows, series, references):
    """Every series over its whole range, binned as report wrote histogram.csv."""
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    several = len(series) > 1
    top = 1
    for i, s in enumerate(series):
        mine = [r for r in rows if r["series"] == s["series"]]
        lo = [100 * float(r["error_lo"]) for r in mine]
        hi = [100 * float(r["error_hi"]) for r in mine]
        counts = [int(r["candidates"]) for r in mine]
        top = max([top] + counts)
        colour = colours[i % len(colours)]
        label = f"{s['series']} ({s['evaluated']} candidates)"
        if several:
            edges = lo + hi[-1:]
            ax.stairs(counts, edges, color=colour, linewidth=1.2, fill=False, label=label)
            ax.stairs(counts, edges, color=colour, alpha=0.15, fill=True)
        else:
            width = [h - l for l, h in zip(lo, hi)]
            # A screened series: its exact means (dark, at the bottom of each bar) told apart from
            # its estimates (light, stacked on top).
            exact = [int(r.get("exact") or 0) for r in mine]
            estimated = sum(counts) - sum(exact)
            if estimated:
                label = f"{s['series']}: {estimated} screened estimates"
            # Without estimates every bar is exact: drawn whole, not as zero-height tops.
            light = [c - e for c, e in zip(counts, exact)] if estimated else counts
            ax.bar(lo, light, bottom=exact if estimated else 0, width=width, align="edge",
                   color="#7f9fbf", edgecolor="#4f6f8f", linewidth=0.4, label=label)
            if estimated and sum(exact):
                ax.bar(lo, exact, width=width, align="edge", color="#1f3f5f", edgecolor="#1f3f5f",
                       linewidth=0.4, label=f"{sum(exact)} exact means")
            colour = "#2f4f6f"
        ax.axvline(100 * float(s["best"]), color=colour, linestyle="-", linewidth=1.2)
        ax.axvline(100 * float(s["median"]), color=colour, linestyle=":", linewidth=1.2)
    shown = [r for r in references if r[0] in SHOWN_REFERENCES]
    for name, error in shown:
        ax.axvline(error, color="#555555", linestyle="--", linewidth=0.8)
    ax.set_ylim(0, top * 1.35)  # the labels' pixel widths depend on the axes' final x range
    ax.plot([], [], color="#555555", linestyle="-", label="best (solid), median (dotted)")
    ax.yaxis.set_major_locator(matplotlib.ticker.MaxNLocator(integer=True))
    ax.set_xlabel(f"{ERROR['of']} over {ERROR['over']} (%)")
    ax.set_ylabel("candidates")
    ax.set_title("Sweep candidates by mean error" + (" and functions per candidate" if several else ""))
    ax.legend(fontsize=7, loc="upper left", ncol=1, frameon=False)
    return shown, top


def draw_zoom(ax, series, references, candidates, lo, hi, bins=60):
    """The same series between the best candidate and the 95th percentile of the largest series."""
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    width = (hi - lo) / bins
    edges = [lo + width * b for b in range(bins + 1)]
    top = 1
    for i, s in enumerate(series):
        counts = [0] * bins
        for name, error in candidates:
            if name == s["series"] and lo <= error <= hi:
                counts[min(bins - 1, int((error - lo) / width))] += 1
        top = max([top] + counts)
        colour = colours[i % len(colours)] if len(series) > 1 else "#2f4f6f"
        ax.stairs(counts, edges, color=colour, linewidth=1.2, fill=False, label=s["series"])
        ax.stairs(counts, edges, color=colour, alpha=0.15, fill=True)
        for value, style in ((float(s["best"]), "-"), (float(s["median"]), ":")):
            if lo <= 100 * value <= hi:
                ax.axvline(100 * value, color=colour, linestyle=style, linewidth=1.2)
    shown = [r for r in references if r[0] in SHOWN_REFERENCES and lo <= r[1] <= hi]
    for name, error in shown:
        ax.axvline(error, color="#555555", linestyle="--", linewidth=0.8)
    ax.set_xlim(lo, hi)
    ax.yaxis.set_major_locator(matplotlib.ticker.MaxNLocator(integer=True))
    ax.set_xlabel(f"{ERROR['of']} (%), zoomed on the bulk of the candidates with the most functions")
    ax.set_ylabel("candidates")
    ax.set_ylim(0, top * 1.35)
    return shown, top


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--histogram", required=True)
    parser.add_argument("--series", required=True)
    parser.add_argument("--references", required=True)
    parser.add_argument("--candidates", help="candidates.csv: adds a panel zoomed on the largest candidates' bulk")
    parser.add_argument("--out", required=True, help="output path without extension")
    parser.add_argument("--error", default=ERROR["of"], help="what the mean error is of")
    parser.add_argument("--over", default=ERROR["over"], help="what it is averaged over")
    args = parser.parse_args()
    ERROR["of"], ERROR["over"] = args.error, args.over

    with open(args.histogram) as f:
        rows = list(csv.DictReader(f))
    with open(args.series) as f:
        series = list(csv.DictReader(f))
    with open(args.references) as f:
        references = [(r["technique"], 100 * float(r["mean_error"])) for r in csv.DictReader(f)]

    zoom = None
    if args.candidates:
        with open(args.candidates) as f:
            candidates = [(r["series"], 100 * float(r["mean_error"])) for r in csv.DictReader(f)]
        # The zoom: from the best candidate of any series to the 95th percentile of the series with
        # the most functions (its bulk, where the seed paper's Figure 4 looks).
        main = max(series, key=lambda s: int(s["size"]))["series"]
        errors = sorted(e for name, e in candidates if name == main)
        if errors:
            lo = min(100 * float(s["best"]) for s in series)
            hi = errors[min(len(errors) - 1, int(0.95 * len(errors)))]
            if hi > lo:
                zoom = (candidates, lo, hi)
    fig, _ = figure(rows, series, references, zoom)
    save_png_and_pdf(fig, args.out, "plot_histogram.py", layout=False)


def figure(rows, series, references, zoom=None):
    """The whole figure: the histogram, and the zoomed panel when `zoom` = (candidates, lo, hi),
    laid out, with the reference labels placed last (by their pixel extents) so that the layout
    does not move them onto each other. Returns the figure and every label."""
    fig, axes = plt.subplots(2 if zoom else 1, 1, figsize=(7.5, 7.2 if zoom else 4.0), squeeze=False)
    panels = [(axes[0][0], *draw(axes[0][0], rows, series, references), 0.0)]
    if zoom:
        panels.append((axes[1][0], *draw_zoom(axes[1][0], series, references, *zoom), 0.0))
    fig.tight_layout()
    labels = []
    renderer = fig.canvas.get_renderer()
    for ax, shown, top, legend_room in panels:
        texts, lanes = stack_labels(ax, shown, top)
        ax.set_ylim(0, label_room(top, lanes) + top * legend_room)
        legend = ax.get_legend()
        # Raise the y limit (the labels sink in pixels, the legend stays) until no label meets it.
        for _ in range(20):
            if legend is None:
                break
            box = legend.get_window_extent(renderer)
            if not any(box.overlaps(t.get_window_extent(renderer)) for t in texts):
                break
            ax.set_ylim(0, ax.get_ylim()[1] * 1.12)
        labels += texts
    return fig, labels


if __name__ == "__main__":
    main()
