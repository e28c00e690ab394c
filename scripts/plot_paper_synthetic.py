#!/usr/bin/python3
# Plots the CSVs of essential_paper_synthetic (bench/paper_synthetic.cpp) as the paper's
# synthetic figures. Uses Debian's python3-matplotlib (hence /usr/bin/python3).
#
#   scripts/plot_paper_synthetic.py --csv DIR --figures DIR
#
# Writes synthetic_figA.png (time to 99% reliability against the inlier ratio, a panel per number
# of matches), synthetic_figA_points.png (the same per solver, a
# line per number of matches) and synthetic_figB.png (reliability against time at very few inliers,
# and at 60% inliers for several block sizes), when the CSVs they need exist.
# Licensed under the Apache License, Version 2.0.

import argparse
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# One colour per method, fixed across figures; the module's solvers first, OpenCV's last.
COLOURS = {
    "lm": "tab:red",
    "gn": "tab:green",
    "nister": "tab:blue",
    "robust": "tab:purple",
    "ours-adaptive": "tab:orange",
    "cv-RANSAC": "tab:gray",
    "cv-USAC_MAGSAC": "black",
}
LABELS = {
    "lm": "LM (Alg. 1), preemptive",
    "gn": "GN (Alg. 2), preemptive",
    "nister": "5-point (Alg. 4), preemptive",
    "robust": "Robust (Alg. 3), preemptive",
    "ours-adaptive": "findEssentialMatIter default (adaptive)",
    "cv-RANSAC": "cv::findEssentialMat RANSAC",
    "cv-USAC_MAGSAC": "cv::findEssentialMat USAC_MAGSAC",
}
MARKERS = {100: "o", 250: "s", 500: "^", 1000: "D"}


def read(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def num(x):
    try:
        v = float(x)
    except (TypeError, ValueError):
        return math.nan
    return v


def figure_a(rows, column, target, path):
    ns = sorted({int(r["n"]) for r in rows})
    methods = [m for m in COLOURS if any(r["method"] == m for r in rows)]
    cols = 2 if len(ns) > 1 else 1
    nrows = (len(ns) + cols - 1) // cols
    fig, axes = plt.subplots(nrows, cols, figsize=(6 * cols, 4.2 * nrows), squeeze=False)
    for k, n in enumerate(ns):
        ax = axes[k // cols][k % cols]
        for m in methods:
            pts = sorted(
                (num(r["inlier_ratio"]), num(r[column]))
                for r in rows
                if r["method"] == m and int(r["n"]) == n
            )
            xs = [p[0] for p in pts if not math.isnan(p[1])]
            ys = [p[1] for p in pts if not math.isnan(p[1])]
            if not xs:
                continue
            ax.plot(xs, ys, marker="o", ms=4, color=COLOURS[m], label=LABELS[m],
                    linestyle="--" if m.startswith("cv-") else "-")
        ax.set_yscale("log")
        ax.set_title(f"N = {n} matches")
        ax.set_xlabel("inlier fraction")
        ax.set_ylabel(f"mean CPU time for {target:.0%} reliability [ms]")
        ax.grid(True, which="both", alpha=0.3)
    for k in range(len(ns), nrows * cols):
        axes[k // cols][k % cols].axis("off")
    handles, labels = axes[0][0].get_legend_handles_labels()
    for ax in axes.flat:
        for h, lab in zip(*ax.get_legend_handles_labels()):
            if lab not in labels:
                handles.append(h)
                labels.append(lab)
    fig.legend(handles, labels, loc="lower center", ncol=min(4, len(labels)), fontsize=8)
    fig.suptitle(f"Time to reach {target:.0%} reliability (missing point: not reached "
                 "within the time cap)", fontsize=10)
    fig.tight_layout(rect=(0, 0.07 + 0.02 * (len(labels) > 4), 1, 0.96))
    fig.savefig(path, dpi=110)
    plt.close(fig)


def figure_a_points(rows, path):
    solvers = [m for m in ("lm", "gn", "nister") if any(r["method"] == m for r in rows)]
    if not solvers:
        return
    fig, axes = plt.subplots(1, len(solvers), figsize=(5 * len(solvers), 4), squeeze=False)
    for k, m in enumerate(solvers):
        ax = axes[0][k]
        for n in sorted({int(r["n"]) for r in rows}):
            pts = sorted(
                (num(r["inlier_ratio"]), num(r["time_to_099_ms"]))
                for r in rows
                if r["method"] == m and int(r["n"]) == n
            )
            xs = [p[0] for p in pts if not math.isnan(p[1])]
            ys = [p[1] for p in pts if not math.isnan(p[1])]
            if xs:
                ax.plot(xs, ys, marker=MARKERS.get(n, "o"), ms=4, color=COLOURS[m],
                        alpha=0.35 + 0.65 * n / 1000, label=f"N = {n}")
        ax.set_yscale("log")
        ax.set_title(LABELS[m])
        ax.set_xlabel("inlier fraction")
        ax.set_ylabel("mean CPU time for 99% reliability [ms]")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def figure_b(rows, path):
    hard = [r for r in rows if r["part"] == "B-hard"]
    b60 = [r for r in rows if r["part"] == "B-60"]
    fig, axes = plt.subplots(1, 3, figsize=(17, 4.5))
    ax = axes[0]
    styles = ["-", "--", ":", "-."]
    for k, ratio in enumerate(sorted({num(r["inlier_ratio"]) for r in hard}, reverse=True)):
        for m in [m for m in COLOURS if any(r["method"] == m for r in hard)]:
            # The curve is parameterised by M: points in the order of M.
            pts = [(num(r["mean_ms"]), num(r["reliability"])) for r in
                   sorted((r for r in hard if r["method"] == m
                           and num(r["inlier_ratio"]) == ratio), key=lambda r: int(r["knob"]))]
            if pts:
                ax.plot([p[0] for p in pts], [p[1] for p in pts], marker="o", ms=3,
                        color=COLOURS[m], linestyle=styles[k % 4],
                        label=f"{LABELS[m].split(',')[0]}, {ratio:.0%} inliers")
    n_hard = sorted({int(r["n"]) for r in hard})
    ax.set_xscale("log")
    ax.set_xlabel("mean CPU time per estimate [ms]")
    ax.set_ylabel("reliability")
    ax.set_title(f"N = {n_hard[0] if n_hard else '?'}, block 100, curve over M")
    ax.set_ylim(-0.02, 1.02)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)

    solvers60 = [m for m in COLOURS if any(r["method"] == m for r in b60)]
    blocks = sorted({int(r["block"]) for r in b60})
    cmap = plt.get_cmap("viridis")
    iterations = axes[2].twinx()
    for k, m in enumerate(solvers60):
        for j, b in enumerate(blocks):
            pts = sorted(((num(r["mean_ms"]), num(r["reliability"]), num(r["mean_refine_ms"]),
                           int(r["knob"]), num(r["mean_refine_iterations"])) for r in b60
                          if r["method"] == m and int(r["block"]) == b), key=lambda p: p[3])
            if not pts:
                continue
            colour = cmap(j / max(1, len(blocks) - 1))
            axes[1].plot([p[0] for p in pts], [p[1] for p in pts], marker="o", ms=3,
                         color=colour, linestyle=styles[k % 4], label=f"{m}, B = {b}")
            if j == len(blocks) // 2:
                axes[2].plot([p[3] for p in pts], [p[0] for p in pts], marker="o", ms=3,
                             color=COLOURS[m], linestyle="-", label=f"{m}: CPU time (B = {b})")
                iterations.plot([p[3] for p in pts], [p[4] for p in pts], marker="x", ms=4,
                                color=COLOURS[m], linestyle=":",
                                label=f"{m}: final IRLS iterations (right axis)")
    n60 = sorted({int(r["n"]) for r in b60})
    axes[1].set_xscale("log")
    # The interesting part is the hook at small M (fewer hypotheses, slower refinement).
    lo = min((num(r["mean_ms"]) for r in b60), default=1.0)
    axes[1].set_xlim(lo * 0.9, lo * 12)
    axes[1].set_xlabel("mean CPU time per estimate [ms]")
    axes[1].set_ylabel("reliability")
    axes[1].set_title(f"N = {n60[0] if n60 else '?'}, 60% inliers, curve over M")
    axes[1].grid(True, which="both", alpha=0.3)
    axes[1].legend(fontsize=7, ncol=2)
    axes[2].set_xscale("log")
    axes[2].set_yscale("log")
    axes[2].set_xlabel("hypotheses M")
    axes[2].set_ylabel("mean CPU time [ms]")
    axes[2].set_title("60% inliers: where the time goes")
    axes[2].grid(True, which="both", alpha=0.3)
    iterations.set_ylabel("final IRLS iterations (mean)")
    h1, l1 = axes[2].get_legend_handles_labels()
    h2, l2 = iterations.get_legend_handles_labels()
    axes[2].legend(h1 + h2, l1 + l2, fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--csv", required=True, help="folder with the bench's CSVs")
    ap.add_argument("--figures", required=True, help="folder for the PNGs")
    a = ap.parse_args()
    os.makedirs(a.figures, exist_ok=True)
    written = []
    fig_a = os.path.join(a.csv, "synthetic_figA.csv")
    if os.path.exists(fig_a):
        rows = read(fig_a)
        figure_a(rows, "time_to_099_ms", 0.99, os.path.join(a.figures, "synthetic_figA.png"))
        written.append("synthetic_figA.png")
        figure_a_points(rows, os.path.join(a.figures, "synthetic_figA_points.png"))
        written.append("synthetic_figA_points.png")
    levels_b = os.path.join(a.csv, "synthetic_levels_B.csv")
    if os.path.exists(levels_b):
        figure_b(read(levels_b), os.path.join(a.figures, "synthetic_figB.png"))
        written.append("synthetic_figB.png")
    if not written:
        sys.exit("plot_paper_synthetic.py: no CSV found in " + a.csv)
    print("plot_paper_synthetic.py: wrote " + ", ".join(written))


if __name__ == "__main__":
    main()
