"""What the plot scripts share: the headless backend and saving a figure as PNG and PDF."""
import matplotlib

matplotlib.use("Agg")


def save_png_and_pdf(fig, out, script, layout=True):
    """Writes <out>.png and <out>.pdf and says so, naming the script (layout=False: the caller
    has laid the figure out, e.g. before placing labels by their pixel extents)."""
    if layout:
        fig.tight_layout()
    for extension in ("png", "pdf"):
        fig.savefig(f"{out}.{extension}", dpi=150)
    name = out.rsplit("/", 1)[-1]
    print(f"{script}: wrote {name}.png and {name}.pdf")


def stack_labels(ax, marks, top, fontsize=6.5, pad_px=4):
    """Names at vertical lines (name, x), written horizontally above the bars at height `top`: each
    label goes to the lowest lane where it overlaps no other label, so that references a hair apart
    stay legible. Returns the Text objects and the number of lanes used; the caller sets the y
    limit to leave room for them (label_room)."""
    renderer = ax.figure.canvas.get_renderer()
    lanes = []  # per lane: the right end (pixels) of its last label
    texts = []
    step = top * 0.075
    for name, x in sorted(marks, key=lambda m: m[1]):
        text = ax.text(x, top, " " + name, color="#333333", fontsize=fontsize, va="bottom",
                       ha="left", clip_on=False,
                       bbox={"facecolor": "white", "edgecolor": "none", "pad": 0.3, "alpha": 0.85})
        box = text.get_window_extent(renderer)
        lane = next((i for i, right in enumerate(lanes) if box.x0 > right + pad_px), len(lanes))
        if lane == len(lanes):
            lanes.append(0)
        lanes[lane] = box.x1
        text.set_y(top * 1.03 + lane * step)
        texts.append(text)
    return texts, len(lanes)


def label_room(top, lanes):
    """The y limit that holds `lanes` stacked labels above bars of height `top`."""
    return top * (1.12 + 0.075 * max(lanes, 1))
