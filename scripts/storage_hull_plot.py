#!/usr/bin/python3
"""The m = 3 curve b(z) and its convex hull before and after a quantization transform, both in the
unit cube, like seed 000 Figure 5 (docs/reference.md §8). Reads the JSON of

    momentbench storage --basis z,z^2,z^3 --transform optimized --curve-samples 400 > m3.json
    /usr/bin/python3 scripts/storage_hull_plot.py m3.json docs/images/storage_hull_m3

The hull of a curve of order 3 (an affine image of (z, z^2, z^3), as both curves here are) is
bounded by the triangles from either end point to each chord b(z_k) b(z_k+1) (Gale's evenness
condition for the cyclic polytope); the script draws those, so it refuses other m."""
import json
import sys

from plot_common import save_png_and_pdf

import matplotlib.pyplot as plt
from mpl_toolkits.mplot3d.art3d import Poly3DCollection


def hull_triangles(points):
    first, last = points[0], points[-1]
    triangles = []
    for a, b in zip(points[:-1], points[1:]):
        triangles.append([first, a, b])
        triangles.append([a, b, last])
    return triangles


def unit_cube(ax):
    corners = [(x, y, z) for x in (0, 1) for y in (0, 1) for z in (0, 1)]
    for p in corners:
        for q in corners:
            if sum(abs(a - b) for a, b in zip(p, q)) == 1 and p < q:
                ax.plot(*zip(p, q), color="#999999", linewidth=0.6)


def panel(ax, points, title):
    unit_cube(ax)
    hull = Poly3DCollection(hull_triangles(points), facecolor="#4c72b0", alpha=0.25,
                            edgecolor="none")
    ax.add_collection3d(hull)
    ax.plot(*zip(*points), color="#c44e52", linewidth=1.8)
    ax.set_xlim(0, 1), ax.set_ylim(0, 1), ax.set_zlim(0, 1)
    ax.set_box_aspect((1, 1, 1))
    ax.set_title(title, fontsize=9, pad=-4)
    ax.set_xlabel("q1", fontsize=8), ax.set_ylabel("q2", fontsize=8), ax.set_zlabel("q3", fontsize=8)
    ax.tick_params(labelsize=7)
    ax.view_init(elev=22, azim=-58)


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: storage_hull_plot.py STORAGE_JSON OUT_STEM")
    data = json.load(open(sys.argv[1]))
    if len(data["basis"]) != 3 or "curve" not in data:
        sys.exit("storage_hull_plot.py: needs a basis of 3 functions and --curve-samples > 0")
    before = [tuple(p) for p in data["curve"]["b"]]
    after = [tuple(p) for p in data["curve"]["stored"]]
    fig = plt.figure(figsize=(9, 4.8))
    names = ", ".join(data["basis"])
    panel(fig.add_subplot(1, 2, 1, projection="3d"), before,
          f"b(z) = ({names}), hull volume {data['hull_volume']:.4g}")
    panel(fig.add_subplot(1, 2, 2, projection="3d"), after,
          f"{data['kind']} A b(z) + c, hull volume {data['transformed_hull_volume']:.3f}\n"
          f"{data['volume_ratio']:.1f} times larger, {data['entropy_gain_bits']:.2f} bits "
          f"(bound {data['bounds']['best_bits']:.2f})")
    fig.subplots_adjust(left=0.0, right=0.96, bottom=0.04, top=0.9, wspace=0.05)
    save_png_and_pdf(fig, sys.argv[2], "storage_hull_plot.py", layout=False)


if __name__ == "__main__":
    main()
