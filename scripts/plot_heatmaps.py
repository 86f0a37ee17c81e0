#!/usr/bin/python3
"""Lays out the heatmap panels written by `vdc heatmap` into one figure with titles and colour
bars. Usage: plot_heatmaps.py DIR/heatmaps.json OUT.png

The panels are rendered by vdc itself (exact occlusion, the paper's colour scale: white at 0,
black at the row's `black_at`); this script only arranges them and draws the matching scales.
"""
import json
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402
import matplotlib.patches as mpatches  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402


def main(manifest_path, out_path):
    manifest_path = pathlib.Path(manifest_path)
    manifest = json.loads(manifest_path.read_text())
    rows = {}
    for panel in manifest["panels"]:
        rows.setdefault(panel["row"], []).append(panel)
    columns = max(len(panels) for panels in rows.values())
    figure, axes = plt.subplots(len(rows), columns + 1, squeeze=False,
                                figsize=(2.6 * columns + 1.2, 2.9 * len(rows)),
                                gridspec_kw={"width_ratios": [1] * columns + [0.08]})
    unobservable = [c / 255 for c in manifest["unobservable_colour"]]
    for r, (row_title, panels) in enumerate(rows.items()):
        for c in range(columns):
            ax = axes[r][c]
            ax.axis("off")
            if c < len(panels):
                ax.imshow(mpimg.imread(manifest_path.parent / panels[c]["file"]))
                ax.set_title(panels[c]["title"], fontsize=8)
        axes[r][0].text(-0.08, 0.5, row_title, transform=axes[r][0].transAxes, rotation=90,
                        va="center", ha="right", fontsize=9)
        black_at = panels[0]["black_at"]
        scale = plt.cm.ScalarMappable(cmap="gray_r",
                                      norm=matplotlib.colors.Normalize(0, max(black_at, 1e-9)))
        bar = figure.colorbar(scale, cax=axes[r][columns])
        bar.set_label("KL divergence [nats]", fontsize=8)
        bar.ax.tick_params(labelsize=7)
    figure.legend(handles=[mpatches.Patch(color=unobservable, label="not observable (K = -1)")],
                  loc="lower center", fontsize=8, frameon=False)
    figure.suptitle(f"Surface informativeness of {manifest['model']} "
                    f"(white: features recognise their view; black: ambiguous)", fontsize=10)
    figure.tight_layout(rect=(0.02, 0.03, 1, 0.96))
    figure.savefig(out_path, dpi=110)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: plot_heatmaps.py MANIFEST.json OUT.png")
    main(sys.argv[1], sys.argv[2])
