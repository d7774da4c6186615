#!/usr/bin/python3
"""The sweep histogram's reference labels stay legible when references cluster (issue 45): with
lp:power4, hausdorff4 and hamburger4 within 0.02 pp of each other, and the other references spread,
no two labels' bounding boxes overlap, none overlaps the legend, and each lies inside the figure,
in the full panel and in the zoomed one. usage: plot_histogram_test.py SCRIPTS_DIR OUT_DIR"""
import os
import sys

sys.path.insert(0, sys.argv[1])
import plot_histogram  # noqa: E402


def main():
    out = sys.argv[2]
    os.makedirs(out, exist_ok=True)
    rows = [{"series": "4 functions", "error_lo": str(0.007 + 0.0002 * b),
             "error_hi": str(0.0072 + 0.0002 * b), "candidates": str(max(0, 40 - abs(b - 12) * 3))}
            for b in range(30)]
    series = [{"series": "4 functions", "evaluated": "600", "best": "0.0071", "median": "0.0095",
               "size": "4"}]
    references = [("lp:power4", 0.7905), ("hausdorff4", 0.7920), ("hamburger4", 0.7949),
                  ("tmsm", 0.8225), ("lp:trig4", 0.8207), ("hamburger6", 0.4865), ("vsm", 1.8404),
                  ("esm", 4.3545)]
    candidates = [("4 functions", 0.71 + 0.001 * k) for k in range(500)]
    fig, labels = plot_histogram.figure(rows, series, references, (candidates, 0.71, 1.2))
    fig.savefig(os.path.join(out, "clustered.png"), dpi=150)
    renderer = fig.canvas.get_renderer()
    # The boxes as the saved file has them.
    boxes = [(t.get_text().strip(), t.get_window_extent(renderer)) for t in labels]
    assert len(boxes) >= 12, f"expected labels in both panels, got {len(boxes)}"
    figure_box = fig.bbox
    failures = []
    for i, (a, box_a) in enumerate(boxes):
        if not (figure_box.x0 <= box_a.x0 and box_a.x1 <= figure_box.x1 and box_a.y1 <= figure_box.y1):
            failures.append(f"{a} leaves the figure")
        for b, box_b in boxes[i + 1:]:
            if box_a.overlaps(box_b):
                failures.append(f"{a} overlaps {b}")
    for ax in fig.axes:
        legend = ax.get_legend()
        if legend is None:
            continue
        lbox = legend.get_window_extent(renderer)
        failures += [f"{a} overlaps the legend" for a, box in boxes if box.overlaps(lbox)]
    if failures:
        sys.exit("plot_histogram_test: " + "; ".join(failures))
    print(f"plot_histogram_test: {len(boxes)} labels, none overlapping")
    # A transparency sweep's axis says what its error is, and MBOIT's closed forms are drawn.
    plot_histogram.ERROR.update({"of": "mean |T_ref - T|", "over": "transparent fragments"})
    fig, labels = plot_histogram.figure(rows, series, [("mboit_power4", 0.75), ("wboit", 0.9)])
    label = fig.axes[0].get_xlabel()
    if not label.startswith("mean |T_ref - T| over transparent fragments"):
        sys.exit(f"plot_histogram_test: transparency axis reads {label!r}")
    if {t.get_text().strip() for t in labels} != {"mboit_power4", "wboit"}:
        sys.exit("plot_histogram_test: MBOIT and WBOIT reference lines are not labelled")


if __name__ == "__main__":
    main()
