#!/usr/bin/python3
"""Seed 004 Figure 7 measured: what a dragon entering a shaft changes, per technique.

    scripts/scatter_dragon_enters.py RUN [--without SCENE] [--with SCENE] [--view V]
        [--camera C] [--figure PNG] [--tau T]

RUN is a `momentbench scatter` output directory whose dataset holds the same scene without and
with the dragon (configs/datasets/scattering_dragon.yaml) and whose images/ hold the float
radiances (`*_inscatter.exr`, `*_smax.exr`). Per pixel, dI = I(with) - I(without) for every
technique and for the exact reference. Only rays whose end did not move are compared (S_max equal
to 1e-6: the dragon is not seen along them); among those, the reference changes only on rays that
cross the dragon's shadow ("shadow": dI_ref < -T S_max) and on no other ("untouched": |dI_ref| <=
T S_max). Prints a markdown table: per technique, its change on the untouched rays (mean |dI| /
S_max over them, the share darkened by 1 % of S_max or more, the largest darkening, and their
darkening summed against the reference's on the shadow rays) and the share of the reference's
darkening it reproduces on the shadow rays (Sum dI / Sum dI_ref over them; all sums of dI / S_max). With --figure, dI / S_max in a diverging
colour map, one panel per technique (docs/scattering.md §4).
"""
import argparse
import glob
import os
import sys

import numpy as np

from scatter_images import read_channel as read



def techniques_of(images, base):
    found = []
    for path in sorted(glob.glob(os.path.join(images, base + "_*_inscatter.exr"))):
        name = os.path.basename(path)[len(base) + 1 : -len("_inscatter.exr")]
        if name != "reference":
            found.append(name)
    return found


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("run")
    parser.add_argument("--without", default="dragon_shaft_empty")
    parser.add_argument("--with", dest="with_", default="dragon_shaft")
    parser.add_argument("--view", default="low_sun")
    parser.add_argument("--camera", default="along")
    parser.add_argument("--tau", type=float, default=1e-4)
    parser.add_argument("--figure")
    args = parser.parse_args()
    images = os.path.join(args.run, "images")
    base_a = f"{args.without}_{args.view}_{args.camera}"
    base_b = f"{args.with_}_{args.view}_{args.camera}"
    smax_a = read(os.path.join(images, base_a + "_smax.exr"))
    smax_b = read(os.path.join(images, base_b + "_smax.exr"))
    seen = np.abs(smax_b - smax_a) > 1e-6 * np.maximum(smax_a, 1e-30)  # the dragon ends the ray
    if not seen.any():
        sys.exit("scatter_dragon_enters.py: the two scenes' rays all end alike: no dragon in view")
    ref_a = read(os.path.join(images, base_a + "_reference_inscatter.exr"))
    ref_b = read(os.path.join(images, base_b + "_reference_inscatter.exr"))
    smax = np.where(seen, 1.0, smax_a)
    d_ref = (ref_b - ref_a) / smax
    shadow = ~seen & (d_ref < -args.tau)
    untouched = ~seen & (np.abs(d_ref) <= args.tau)
    names = techniques_of(images, base_b)
    print(f"{int(seen.sum())} rays see the dragon; of the others {int(shadow.sum())} cross its "
          f"shadow (the reference darkens by more than {args.tau:g} of S_max) and "
          f"{int(untouched.sum())} are untouched by it.\n")
    print("| technique | untouched: mean abs(dI) / S_max % | untouched darkened >= 1 % | largest "
          "darkening | untouched darkening / the reference's | shadow's darkening reproduced |")
    print("|---|---|---|---|---|---|")
    true_darkening = -d_ref[shadow].sum()
    panels = [("exact reference", d_ref)]
    for name in names:
        a = read(os.path.join(images, f"{base_a}_{name}_inscatter.exr"))
        b = read(os.path.join(images, f"{base_b}_{name}_inscatter.exr"))
        d = np.where(seen, 0.0, (b - a) / smax)
        spurious = np.abs(d[untouched]).sum() / untouched.sum()
        dark = untouched & (d <= -0.01)
        share = dark.sum() / untouched.sum()
        spurious_darkening = -np.minimum(d[untouched], 0).sum() / true_darkening
        largest = max(0.0, -d[untouched].min())
        reproduced = d[shadow].sum() / d_ref[shadow].sum() if shadow.any() else float("nan")
        print(f"| {name} | {100 * spurious:.3f} | {int(dark.sum())} ({100 * share:.1f} %) | "
              f"{largest:.3f} | {spurious_darkening:.2f} | {reproduced:.2f} |")
        if name != "exact":  # the reference's own panel shows it
            panels.append((name, d))
    if args.figure:
        figure(args.figure, panels, seen)


def figure(path, panels, seen):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    columns = 3
    rows = (len(panels) + columns - 1) // columns
    fig, axes = plt.subplots(rows, columns, figsize=(4.6 * columns, 3.2 * rows), squeeze=False)
    limit = 0.05  # the moments' spurious darkening is a few % of S_max
    for axis, (name, d) in zip(axes.flat, panels):
        shown = np.ma.masked_where(seen, d)
        im = axis.imshow(shown, cmap="RdBu", vmin=-limit, vmax=limit)
        axis.imshow(np.ma.masked_where(~seen, seen), cmap="Greys", vmin=0, vmax=2, alpha=0.6)
        axis.set_title(name, fontsize=9)
        axis.set_xticks([]), axis.set_yticks([])
    for axis in list(axes.flat)[len(panels) :]:
        axis.axis("off")
    fig.colorbar(im, ax=axes, shrink=0.8, label="(I with dragon - I without) / S_max")
    fig.savefig(path, dpi=110, bbox_inches="tight")


if __name__ == "__main__":
    main()
