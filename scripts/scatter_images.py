"""Reading `momentbench scatter`'s images (docs/scattering.md §4) for the scatter_*.py scripts: one
channel of an EXR or PNG as float64, through OpenImageIO's Python binding."""
import os
import sys

import numpy as np

try:
    import OpenImageIO as oiio
except ImportError:
    sys.exit(f"{os.path.basename(sys.argv[0])}: needs python3-openimageio (scripts/setup installs it)")


def read_channel(path, channel=0):
    """Channel `channel` of the image at `path` (rows, columns), or exit naming the file."""
    image = oiio.ImageInput.open(path)
    if image is None:
        sys.exit(f"{os.path.basename(sys.argv[0])}: cannot read {path}: {oiio.geterror()}")
    pixels = np.asarray(image.read_image(format="float"), dtype=np.float64)
    image.close()
    return pixels[:, :, channel]
