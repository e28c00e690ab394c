#!/usr/bin/env python3
# Summarises runs of essential_real_pairs over several seeds (one --csv per seed): for each group
# (all pairs of a set, then its true-inlier-ratio buckets) and method, the mean over the seeds of
# AUC@5/10/20, the right-rate, the no-pose count and the median and mean CPU time, with each
# figure's range over the seeds. One seed moves the search's failures (docs/REAL_PAIRS.md), so a comparison of
# two randomised methods that differ by less than that range says nothing; this table shows it.
#
#   scripts/real_pairs_seeds.py [--set real] [--md FILE] RUN.csv [RUN.csv ...]
#
# The AUC is that of test/pose_auc.hpp (trapezoidal, errors max(rotation, translation direction)
# in degrees, no pose = 180); right: rotation < 5 and translation direction < 10 degrees; buckets
# as in bench/real_pairs.cpp. Licensed under the Apache License, Version 2.0.
import argparse
import csv
import statistics
import sys


def pose_auc(errors, limit):
    errors = sorted(errors)
    n = float(len(errors))
    area = prev_err = prev_recall = 0.0
    for i, e in enumerate(errors):
        if e >= limit:
            break
        recall = (i + 1) / n
        area += 0.5 * (prev_recall + recall) * (e - prev_err)
        prev_err, prev_recall = e, recall
    area += prev_recall * (limit - prev_err)
    return area / limit


def bucket_of(ratio):
    if ratio < 0.15:
        return "< 15%"
    if ratio < 0.30:
        return "15-30%"
    if ratio < 0.50:
        return "30-50%"
    return ">= 50%"


def summary(rows):
    err, right, nopose, ms = [], 0, 0, []
    for r in rows:
        posed = r["posed"] == "1"
        rot = float(r["r_err_deg"]) if posed else 180.0
        tra = float(r["t_err_deg"]) if posed else 180.0
        err.append(max(rot, tra))
        right += posed and rot < 5 and tra < 10
        nopose += not posed
        ms.append(float(r["cpu_ms"]))
    n = len(rows)
    return {
        "AUC@5": pose_auc(err, 5),
        "AUC@10": pose_auc(err, 10),
        "AUC@20": pose_auc(err, 20),
        "right": right / n,
        "no pose": nopose,
        "median ms": statistics.median(ms),
        "mean ms": sum(ms) / n,
    }


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--set", default="real", help="the set family to summarise (default real)")
    ap.add_argument("--md", help="write the tables to this file too")
    ap.add_argument("runs", nargs="+", help="one essential_real_pairs --csv file per seed")
    a = ap.parse_args()

    # group -> method -> per-run summaries
    groups = {}
    order = []
    for path in a.runs:
        by = {}
        with open(path, newline="") as f:
            for r in csv.DictReader(f):
                # the set column is "<family> <scene>", e.g. "real fountain-P11"
                if r["set"].split(" ")[0] != a.set:
                    continue
                for g in ("%s: all pairs" % a.set,
                          "%s %s true inliers" % (a.set, bucket_of(float(r["true_ratio"])))):
                    by.setdefault(g, {}).setdefault(r["method"], []).append(r)
        if not by:
            sys.exit("%s: no rows of set '%s'" % (path, a.set))
        for g, methods in by.items():
            for m, rows in methods.items():
                groups.setdefault(g, {}).setdefault(m, []).append((len(rows), summary(rows)))
                if m not in order:
                    order.append(m)
    keys = ["AUC@5", "AUC@10", "AUC@20", "right", "no pose", "median ms", "mean ms"]
    out = []
    bucket_order = ["all pairs", "< 15%", "15-30%", "30-50%", ">= 50%"]
    for g in sorted(groups, key=lambda g: [b in g for b in bucket_order].index(True)):
        sizes = {n for m in groups[g].values() for n, _ in m}
        runs_per_method = sorted({len(m) for m in groups[g].values()})
        out.append("*%s (%s pairs), mean over %s runs per method [min, max]*\n" %
                   (g, "/".join(str(s) for s in sorted(sizes)),
                    "/".join(str(r) for r in runs_per_method)))
        out.append("| method | " + " | ".join(keys) + " |")
        out.append("|---|" + "---:|" * len(keys))
        for m in order:
            runs = groups[g].get(m)
            if not runs:
                continue
            cells = []
            for k in keys:
                v = [s[k] for _, s in runs]
                fmt = "%.1f" if k in ("no pose", "median ms", "mean ms") else "%.3f"
                mean = statistics.fmean(v)
                cells.append((fmt % mean) + (" [" + fmt % min(v) + ", " + fmt % max(v) + "]"
                                             if len(v) > 1 else ""))
            out.append("| %s | %s |" % (m, " | ".join(cells)))
        out.append("")
    text = "\n".join(out)
    print(text)
    if a.md:
        with open(a.md, "w") as f:
            f.write(text + "\n")


if __name__ == "__main__":
    main()
