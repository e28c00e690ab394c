#!/usr/bin/env python3
# Turns the Google Benchmark JSON of essential_perf (scripts/perf.sh) into the markdown tables of
# docs/PERFORMANCE.md: medians over the repetitions, ratios to the module within the same run, and
# the speed targets checked. Licensed under the Apache License, Version 2.0.
#
#   perf_tables.py RESULTS.json [--doc docs/PERFORMANCE.md]
#
# Without --doc the tables go to stdout; with it they replace the text between the markers
# "<!-- perf-tables:begin -->" and "<!-- perf-tables:end -->" of that file.

import json
import re
import statistics
import sys
from collections import defaultdict

BEGIN = "<!-- perf-tables:begin -->"
END = "<!-- perf-tables:end -->"
BASELINES = ["cv_RANSAC", "cv_USAC_MAGSAC", "cv_USAC_ACCURATE"]


def load(path):
    with open(path) as f:
        data = json.load(f)
    runs = defaultdict(list)  # run_name -> list of per-repetition entries
    for b in data["benchmarks"]:
        if b.get("run_type") == "aggregate":
            continue
        name = re.sub(r"/iterations:\d+$", "", b["run_name"])
        name = re.sub(r"/min_time:[0-9.]+$", "", name)
        runs[name].append(b)
    return data["context"], runs


def med(entries, key):
    values = [e[key] for e in entries if key in e]
    return statistics.median(values) if values else float("nan")


def mean(entries, key):
    values = [e[key] for e in entries if key in e]
    return statistics.mean(values) if values else float("nan")


def auc(entries):
    """Mean over the repetitions of the AUC@1 and AUC@5 counters ("-" for a run without them)."""
    if not any("auc1" in e for e in entries):
        return "-"
    return f"{mean(entries, 'auc1'):.3f} / {mean(entries, 'auc5'):.3f}"


def estimate_rows(runs):
    table = defaultdict(dict)  # (n, ratio, camera) -> method -> entries
    for name, entries in runs.items():
        m = re.match(r"Estimate/([^/]+)/N:(\d+)/inliers:(\d+)(?:/camera:(\w+))?$", name)
        if m:
            table[(int(m.group(2)), int(m.group(3)), m.group(4) or "paper")][m.group(1)] = entries
    return table


def size_label(n, camera):
    """The N column: the size, and the camera when it is not the paper's."""
    return f"{n}" if camera == "paper" else f"{n}, {camera} camera"


def targets_table(table):
    out = []
    out.append("| N | inliers | method | reliable (2/5 deg) | AUC@1 / AUC@5 | median CPU ms "
               "| median wall ms | CPU time / ours | target |")
    out.append("|---|---|---|---|---|---|---|---|---|")
    summary = []
    for (n, ratio, camera) in sorted(table, key=lambda k: (k[2] != "paper", k[0], -k[1])):
        methods = table[(n, ratio, camera)]
        size = size_label(n, camera)
        if "essential" not in methods:
            continue
        ours = methods["essential"]
        ours_cpu = med(ours, "median_cpu_ms")
        ours_rel = mean(ours, "reliable")
        out.append(f"| {size} | {ratio}% | **essential** (drop-in) | {ours_rel:.3f} | {auc(ours)} "
                   f"| {ours_cpu:.3f} | {med(ours, 'median_ms'):.3f} | 1.0x | |")
        for base in BASELINES:
            if base not in methods:
                continue
            e = methods[base]
            cpu = med(e, "median_cpu_ms")
            rel = mean(e, "reliable")
            ratio_x = cpu / ours_cpu if ours_cpu > 0 else float("nan")
            target = ""
            # The targets of issue 27: 50x less CPU than RANSAC and 15x less than USAC_MAGSAC at
            # 50-90% inliers (either camera), 5x less than USAC_MAGSAC at 30% (N = 500, the
            # paper's camera); faster than USAC_ACCURATE at 30% and below.
            if ratio >= 50 and base == "cv_RANSAC":
                ok = ratio_x >= 50 and ours_rel >= rel
                target = f"{'met' if ok else 'NOT met'}: >= 50x, reliability {ours_rel:.3f} >= {rel:.3f}"
            elif ratio >= 50 and base == "cv_USAC_MAGSAC":
                ok = ratio_x >= 15 and ours_rel >= rel
                target = f"{'met' if ok else 'NOT met'}: >= 15x, reliability {ours_rel:.3f} >= {rel:.3f}"
            elif ratio == 30 and n == 500 and camera == "paper" and base == "cv_USAC_MAGSAC":
                ok = ratio_x >= 5 and ours_rel >= rel
                target = f"{'met' if ok else 'NOT met'}: >= 5x, reliability {ours_rel:.3f} >= {rel:.3f}"
            elif ratio <= 30 and base == "cv_USAC_ACCURATE":
                ok = ratio_x > 1 and ours_rel >= rel
                target = f"{'met' if ok else 'NOT met'}: faster, reliability {ours_rel:.3f} >= {rel:.3f}"
            if target:
                summary.append((size, ratio, base, ratio_x, ours_rel, rel, target.split(":")[0]))
            out.append(f"| {size} | {ratio}% | {base} | {rel:.3f} | {auc(e)} | {cpu:.3f} "
                       f"| {med(e, 'median_ms'):.3f} | {ratio_x:.1f}x | {target} |")
    return out, summary


def variants_table(table):
    out = ["| N | inliers | solver | engine | reliable (2/5 deg) | median CPU ms | median wall ms |",
           "|---|---|---|---|---|---|---|"]
    for (n, ratio, camera) in sorted(table, key=lambda k: (k[2] != "paper", k[0], -k[1])):
        for method, e in sorted(table[(n, ratio, camera)].items()):
            if not method.startswith("essential:"):
                continue
            _, solver, engine = method.split(":")
            out.append(f"| {size_label(n, camera)} | {ratio}% | {solver} | {engine} | {mean(e, 'reliable'):.3f} "
                       f"| {med(e, 'median_cpu_ms'):.3f} | {med(e, 'median_ms'):.3f} |")
    return out if len(out) > 2 else []


def cpu_ns(entries):
    """Median CPU time per iteration in ns."""
    scale = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}
    values = [e["cpu_time"] * scale[e.get("time_unit", "ns")] for e in entries]
    return statistics.median(values)


def kernels_tables(runs):
    out = []
    solvers = [(k, v) for k, v in runs.items() if k.startswith("BM_Solver/")]
    if solvers:
        out += ["| solver (one call = one hypothesis) | ns per call (CPU) | solutions per call |",
                "|---|---|---|"]
        for name, e in solvers:
            out.append(f"| {name.split('/')[1].replace('_', '+')} | {cpu_ns(e):.0f} "
                       f"| {med(e, 'solutions_per_call'):.2f} |")
        out.append("")
    per_point = [(k, v) for k, v in runs.items()
                 if k.startswith(("BM_ScoreMsac/", "BM_ScoreSprt/", "BM_InlierMask/"))]
    if per_point:
        out += ["| per-point kernel | N | ns per point (CPU) |", "|---|---|---|"]
        for name, e in per_point:
            kernel, n = name.split("/")[0][3:], name.split("/")[1]
            out.append(f"| {kernel} | {n} | {med(e, 'ns_per_point'):.2f} |")
        out.append("")
    refine = [(k, v) for k, v in runs.items() if k.startswith("BM_RefineIrls/")]
    if refine:
        out += ["| IRLS refinement | N | us per call (CPU) | iterations | ns per point and "
                "iteration |", "|---|---|---|---|---|"]
        for name, e in refine:
            out.append(f"| refineIrls | {name.split('/')[1]} | {cpu_ns(e) / 1e3:.1f} "
                       f"| {med(e, 'iterations'):.0f} | {med(e, 'ns_per_point_iteration'):.1f} |")
        out.append("")
    pose = {k: v for k, v in runs.items() if k.startswith("RecoverPose/")}
    if pose:
        out += ["| recoverPose, same E, points and mask | N | us per call (CPU) "
                "| cv::recoverPose / ours |", "|---|---|---|---|"]
        for n in sorted({k.split("/")[-1] for k in pose}, key=int):
            ours = pose.get(f"RecoverPose/essential/{n}")
            cv = pose.get(f"RecoverPose/cv/{n}")
            if ours and cv:
                out.append(f"| cv::essential::recoverPose | {n} | {cpu_ns(ours) / 1e3:.1f} "
                           f"| {cpu_ns(cv) / cpu_ns(ours):.0f}x |")
                out.append(f"| cv::recoverPose | {n} | {cpu_ns(cv) / 1e3:.1f} | |")
        out.append("")
    stages = [(k, v) for k, v in runs.items() if k.startswith("BM_Stages/")]
    if stages:
        out += ["| stages (EssentialReport, mean over scenes, wall) | N | inliers | setup ms "
                "| search ms | refine + mask ms | pose ms | samples | LO runs |",
                "|---|---|---|---|---|---|---|---|---|"]
        for name, e in stages:
            _, n, r = name.split("/")
            out.append(f"| findEssentialMatIter | {n} | {r}% | {med(e, 'setup_ms'):.3f} "
                       f"| {med(e, 'search_ms'):.3f} | {med(e, 'refine_ms'):.3f} "
                       f"| {med(e, 'pose_ms'):.3f} | {med(e, 'samples'):.0f} "
                       f"| {med(e, 'lo_runs'):.1f} |")
        out.append("")
    return out


def main():
    args = sys.argv[1:]
    if not args:
        sys.exit(__doc__ or "usage: perf_tables.py RESULTS.json [--doc FILE]")
    doc = None
    if "--doc" in args:
        i = args.index("--doc")
        doc = args[i + 1]
        del args[i:i + 2]
    context, runs = load(args[0])
    table = estimate_rows(runs)
    lines = []
    lines.append(f"Run {context.get('date', '')} on {context.get('host_name', '')}, "
                 f"{context.get('num_cpus', '?')} CPUs at {context.get('mhz_per_cpu', '?')} MHz.")
    lines.append("")
    targets, summary = targets_table(table)
    if len(targets) > 2:
        lines += ["### Whole estimates against cv::findEssentialMat (pose recovery included)", ""]
        lines += targets + [""]
    variants = variants_table(table)
    if variants:
        lines += ["### Solver x engine (EssentialParams overload)", ""] + variants + [""]
    kernels = kernels_tables(runs)
    if kernels:
        lines += ["### Kernels", ""] + kernels
    pose = {k: v for k, v in runs.items() if k.startswith("RecoverPose/")}
    pose_lines = []
    for n in sorted({k.split("/")[-1] for k in pose}, key=int):
        ours, cv = pose.get(f"RecoverPose/essential/{n}"), pose.get(f"RecoverPose/cv/{n}")
        if ours and cv:
            x = cpu_ns(cv) / cpu_ns(ours)
            pose_lines.append(f"- recoverPose, N = {n}: cv::essential::recoverPose {x:.0f}x faster "
                              f"than cv::recoverPose (target >= 10x): "
                              f"{'met' if x >= 10 else 'NOT met'}.")
    if summary or pose_lines:
        lines += ["### Targets", ""] + pose_lines
        for n, ratio, base, x, ours_rel, rel, verdict in summary:
            lines.append(f"- N = {n}, {ratio}% inliers, vs {base}: {x:.1f}x faster (CPU time), "
                         f"reliability {ours_rel:.3f} vs {rel:.3f}: {verdict}.")
        lines.append("")
    text = "\n".join(lines)
    if doc is None:
        print(text)
        return
    with open(doc) as f:
        content = f.read()
    if BEGIN not in content or END not in content:
        sys.exit(f"{doc} has no {BEGIN} ... {END} markers")
    head, rest = content.split(BEGIN, 1)
    _, tail = rest.split(END, 1)
    with open(doc, "w") as f:
        f.write(head + BEGIN + "\n" + text + "\n" + END + tail)


if __name__ == "__main__":
    main()
