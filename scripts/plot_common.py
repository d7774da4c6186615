"""What the plot scripts share: the headless backend and saving a figure as PNG and PDF."""
import matplotlib

matplotlib.use("Agg")


def save_png_and_pdf(fig, out, script):
    """Writes <out>.png and <out>.pdf and says so, naming the script."""
    fig.tight_layout()
    for extension in ("png", "pdf"):
        fig.savefig(f"{out}.{extension}", dpi=150)
    name = out.rsplit("/", 1)[-1]
    print(f"{script}: wrote {name}.png and {name}.pdf")
