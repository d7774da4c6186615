#!/usr/bin/python3
"""How much of a scattering row's error its fall-backs make, per light view and camera.

    scripts/scatter_failed_rays.py RUN [--technique NAME ...]

RUN is a `momentbench scatter` output directory with images (docs/scattering.md §4). A ray whose
own answer failed (an LP without a certified answer) is answered lit, I = S_max (§3.2); from the
float radiances such a ray shows as I == S_max where the reference has I_ref < S_max (a ray the
technique answered lit on its own and that the reference shadows counts too, so this is an upper
count of the failures that matter; report.md has the exact count of failures). Prints per camera
and technique: those rays, the largest |I - I_ref| / S_max and where, the largest over the other
rays, the mean error (Sum |I - I_ref| / Sum S_max) over all rays and over the others, and the
share of the error the lit rays hold.
"""
import argparse
import glob
import os
import sys

import numpy as np

from scatter_images import read_channel as read



def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("run")
    parser.add_argument("--technique", action="append",
                        help="file stem of a technique (pss_lp_power6); default: every one")
    args = parser.parse_args()
    images = os.path.join(args.run, "images")
    bases = sorted(p[: -len("_smax.exr")] for p in glob.glob(os.path.join(images, "*_smax.exr")))
    if not bases:
        sys.exit(f"scatter_failed_rays.py: no *_smax.exr in {images} (run scatter with images)")
    print("| camera | technique | answered lit | largest error (pixel) | largest of the others | "
          "mean % | mean % of the others | lit rays' share of the error |")
    print("|---|---|---|---|---|---|---|---|")
    for base in bases:
        smax = read(base + "_smax.exr")
        ref = read(base + "_reference_inscatter.exr")
        scale = np.where(smax > 0, smax, 1.0)
        for path in sorted(glob.glob(base + "_*_inscatter.exr")):
            name = path[len(base) + 1 : -len("_inscatter.exr")]
            if name == "reference" or (args.technique and name not in args.technique):
                continue
            inscatter = read(path)
            lit = (inscatter == smax) & (ref < smax)
            error = np.abs(inscatter - ref)
            relative = error / scale
            y, x = np.unravel_index(np.argmax(relative), relative.shape)
            others = relative[~lit].max() if (~lit).any() else 0.0
            total = error.sum()
            share = error[lit].sum() / total if total > 0 else 0.0
            print(f"| {os.path.basename(base)} | {name} | {int(lit.sum())} | "
                  f"{relative.max():.3f} ({x}, {y}) | {others:.3f} | "
                  f"{100 * total / smax.sum():.3f} | {100 * error[~lit].sum() / smax.sum():.3f} | "
                  f"{share:.2f} |")


if __name__ == "__main__":
    main()
