#!/usr/bin/python3
"""Seed 004 Figure 4 measured: does the house's window look brighter than its wall?

    scripts/scatter_window.py RUN [--base house_low_sun_outside] [--margin 3] [--band 20]

RUN is a `momentbench scatter` output directory with images (docs/scattering.md §4) of the
scattering dataset's house seen from outside. The window is found from S_max (`*_smax.exr`): a
ray through it ends on the interior's far wall, so S_max jumps at its edges (by a fifth or
more). The window's pixels (`margin` pixels in from its edges) are compared with two bands of the
wall beside it, `band` pixels wide, `margin` pixels off the edges, on the same rows. Under the exact
reference the interior adds nothing (tests/scatter_run_test.cpp), so the window differs from the
wall only as the ray's direction moves. Prints per technique the window's mean in-scattering
against the wall's, in float (I from `*_inscatter.exr`, in % of the wall's) and as 8-bit grey
levels of the in-scattering images (`*_inscatter.png`, one exposure per sheet), each also minus
the reference's own difference.
"""
import argparse
import glob
import os
import sys

import numpy as np

from scatter_images import read_channel as read



def window_of(smax):
    """Rows and columns of the window: the largest block where S_max jumps up by a fifth."""
    ratio = smax[:, 1:] / np.maximum(smax[:, :-1], 1e-30)
    best = None
    for y in range(smax.shape[0]):
        ups = np.nonzero(ratio[y] > 1.2)[0]
        downs = np.nonzero(ratio[y] < 1 / 1.2)[0]
        for a in ups:
            later = downs[downs > a]
            if later.size and (best is None or later[0] - a > best[1] - best[0]):
                best = (a + 1, later[0] + 1)
    if best is None:
        sys.exit("scatter_window.py: no window found in S_max")
    left, right = best
    inside = (smax[:, left:right] > 1.2 * smax[:, [left - 1]]).mean(axis=1) > 0.9
    rows = np.nonzero(inside)[0]
    return rows.min(), rows.max() + 1, left, right


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("run")
    parser.add_argument("--base", default="house_low_sun_outside")
    parser.add_argument("--margin", type=int, default=3)
    parser.add_argument("--band", type=int, default=20)
    args = parser.parse_args()
    images = os.path.join(args.run, "images")
    prefix = os.path.join(images, args.base)
    top, bottom, left, right = window_of(read(prefix + "_smax.exr"))
    m, b = args.margin, args.band
    window = (slice(top + m, bottom - m), slice(left + m, right - m))
    wall = [(slice(top + m, bottom - m), slice(left - m - b, left - m)),
            (slice(top + m, bottom - m), slice(right + m, right + m + b))]
    print(f"window rows {top}..{bottom - 1}, columns {left}..{right - 1}; wall bands of {b} "
          f"columns beside it, {m} pixels off its edges\n")

    def contrast(image):
        inside = image[window].mean()
        beside = np.mean([image[w].mean() for w in wall])
        return inside, beside

    names = ["reference"] + [
        os.path.basename(p)[len(args.base) + 1 : -len("_inscatter.exr")]
        for p in sorted(glob.glob(prefix + "_*_inscatter.exr"))
        if not p.endswith("_reference_inscatter.exr")
    ]
    rows = []
    for name in names:
        i_in, i_wall = contrast(read(f"{prefix}_{name}_inscatter.exr"))
        g_in, g_wall = contrast(255 * read(f"{prefix}_{name}_inscatter.png"))
        rows.append((name, 100 * (i_in / i_wall - 1), g_in - g_wall))
    ref = rows[0]
    print("| technique | window against wall, I % | minus the reference's | grey levels (8-bit) "
          "| minus the reference's |")
    print("|---|---|---|---|---|")
    for name, percent, grey in rows:
        print(f"| {name} | {percent:+.2f} | {percent - ref[1]:+.2f} | {grey:+.2f} | "
              f"{grey - ref[2]:+.2f} |")


if __name__ == "__main__":
    main()
