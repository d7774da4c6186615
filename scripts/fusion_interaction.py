"""Occluder fusion and short-range leaking (results/FINDINGS.md §11) from one `eval` of the fusion
dataset (configs/datasets/fusion.yaml): usage fusion_interaction.py OUT_DIR.

Each scene's error sum S (mean error times receivers, per technique and view) is additive over
receivers that one occluder alone shadows; the interaction S_both - S_pillars - S_wall + S_ground
is then the error the pillars and the wall cause only together: occluder fusion, the blocker
search averaging the distant wall into the pillars' short-range shadows (seed 004 Fig. 13). The
area light's shadow is the reference, so its own interaction is zero by construction. The leak
table compares each technique's leak on the short-range pillars with the long-range wall."""
import csv
import sys
from collections import defaultdict

rows = list(csv.DictReader(open(sys.argv[1] + "/errors.csv")))
sums = defaultdict(dict)  # (technique, view) -> scene -> (error sum, leak sum, receivers)
for r in rows:
    if r["scene"] == "all" or r["view"] == "all":
        continue
    n = int(r["receivers"])
    sums[(r["technique"], r["view"])][r["scene"].replace("fusion_", "")] = (
        float(r["mean_error"]) * n, float(r["leak"]) * n, n)

techniques = list(dict.fromkeys(t for t, _ in sums))
views = sorted(dict.fromkeys(v for _, v in sums), key=lambda v: (float(v.rsplit("_", 1)[1][:-3]), v))


def interaction(s):
    inter = s["both"][0] - s["pillars"][0] - s["wall"][0] + s["ground"][0]
    own = s["pillars"][0] - s["ground"][0]
    return "%.1f (%+.0f %%)" % (inter, 100 * inter / own if own > 0 else 0)


def leak(s):
    return "%.1f / %.1f" % (s["pillars"][1] - s["ground"][1], s["wall"][1] - s["ground"][1])


def table(title, cell):
    print(title + "\n")
    print("| technique | " + " | ".join(views) + " |")
    print("|---|" + "---|" * len(views))
    for t in techniques:
        cells = [cell(sums[(t, v)]) if len(sums[(t, v)]) == 4 else "-" for v in views]
        print("| %s | %s |" % (t, " | ".join(cells)))
    print()


table("Interaction S_both - S_pillars - S_wall + S_ground, in receivers of full error, and as a\n"
      "share of the pillars' own error S_pillars - S_ground:", interaction)
table("Leak, in receivers of full error: pillars (short range) / wall (long range), the ground's\n"
      "removed:", leak)
