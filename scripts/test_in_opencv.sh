#!/usr/bin/env bash
# The module's checks inside an OpenCV 4.6 source build (scripts/build_in_opencv.sh builds it):
#   1. opencv_test_essential, the accuracy tests in OpenCV's ts (the files of test/, shared with
#      the standalone build), in two shards run side by side;
#   2. opencv_perf_essential, a short run (PERF_MIN_SAMPLES, default 3 samples per case; the pose
#      of every case is checked against the scene's ground truth);
#   3. the Python test of cv2.essential (modules/essential/misc/python/test/test_essential.py),
#      through OpenCV's own runner modules/python/test/test.py.
# Each test case counts once; the last line is "in-tree: N passed, M failed, K skipped" (scripts/test.sh
# adds it to its total). Exits non-zero if anything failed. Extra arguments go to
# opencv_test_essential (e.g. --gtest_filter=OpenCvLoop*).
# Licensed under the Apache License, Version 2.0.
set -uo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."

build=$(scripts/build_in_opencv.sh | tail -n1) || {
    echo "test_in_opencv.sh: the in-tree build failed"
    echo "in-tree: 0 passed, 1 failed, 0 skipped"
    exit 1
}
cache=$(dirname "$build")
src="$cache/opencv-4.6-src"
results=$(mktemp -d)
trap 'rm -rf "$results"' EXIT

# Counts the test cases of a GoogleTest XML report: "passed failed skipped"; a missing or unreadable
# report is one failure.
count_xml() {
    /usr/bin/python3 - "$1" <<'EOF'
import sys
import xml.etree.ElementTree as ET
try:
    root = ET.parse(sys.argv[1]).getroot()
except Exception:
    print(0, 1, 0)
    sys.exit()
cases = root.iter("testcase")
passed = failed = skipped = 0
for case in cases:
    if case.find("failure") is not None or case.find("error") is not None:
        failed += 1
    elif case.find("skipped") is not None or case.get("result") == "skipped":
        skipped += 1
    else:
        passed += 1
print(passed, failed if passed + failed + skipped else 1, skipped)
EOF
}

# OpenCV's ts reports a GTEST_SKIP only on its log ("[ SKIPSTAT ] N tests skipped"; the XML says
# status="run"): counts "passed failed skipped" of count_xml ($1) with the log's skips ($2) moved from
# passed to skipped.
with_ts_skips() {
    local p f k s
    read -r p f k <<<"$1"
    s=$(sed -n 's/^\[ SKIPSTAT \] \([0-9]*\) tests\? skipped$/\1/p' "$2" | tail -n1)
    s=${s:-0}
    if [[ $s -gt 0 && $k -eq 0 ]]; then
        p=$((p - s))
        k=$s
    fi
    echo "$p $f $k"
}

total_passed=0
total_failed=0
total_skipped=0
add_counts() {
    local p f k
    read -r p f k <<<"$1"
    k=${k:-0}
    total_passed=$((total_passed + p))
    total_failed=$((total_failed + f))
    total_skipped=$((total_skipped + k))
    echo "test_in_opencv.sh: $2: $p passed, $f failed, $k skipped"
}

start=$SECONDS
echo "== opencv_test_essential (OpenCV ts, 2 shards) =="
pids=()
for shard in 0 1; do
    GTEST_TOTAL_SHARDS=2 GTEST_SHARD_INDEX=$shard "$build/bin/opencv_test_essential" \
        --gtest_output="xml:$results/test_$shard.xml" "$@" \
        >"$results/test_$shard.log" 2>&1 &
    pids+=($!)
done
for shard in 0 1; do
    wait "${pids[$shard]}"
    status=$?
    grep -E '^\[  (FAILED|PASSED|SKIPPED) ' "$results/test_$shard.log" || true
    if [[ $status -ne 0 ]]; then
        grep -B30 -E '^\[  FAILED  \] [A-Za-z]' "$results/test_$shard.log" | head -n 80
    fi
    add_counts "$(with_ts_skips "$(count_xml "$results/test_$shard.xml")" "$results/test_$shard.log")" \
        "accuracy shard $shard"
done
echo "test_in_opencv.sh: accuracy tests took $((SECONDS - start)) s"

start=$SECONDS
echo "== opencv_perf_essential (--perf_min_samples=${PERF_MIN_SAMPLES:-3}) =="
"$build/bin/opencv_perf_essential" --perf_min_samples="${PERF_MIN_SAMPLES:-3}" \
    --perf_force_samples="${PERF_MIN_SAMPLES:-3}" --gtest_output="xml:$results/perf.xml" \
    >"$results/perf.log" 2>&1
status=$?
grep -E '^\[ (PERFSTAT|  FAILED|  PASSED) ' "$results/perf.log" || true
[[ $status -ne 0 ]] && tail -n 60 "$results/perf.log"
add_counts "$(with_ts_skips "$(count_xml "$results/perf.xml")" "$results/perf.log")" "perf"
echo "test_in_opencv.sh: perf run took $((SECONDS - start)) s"

start=$SECONDS
echo "== cv2.essential (modules/essential/misc/python/test, OpenCV's test runner) =="
(cd "$build" && PYTHONPATH="$build/lib/python3" OPENCV_PYTEST_FILTER=test_essential \
    /usr/bin/python3 "$src/modules/python/test/test.py" --repo "$src" -v) >"$results/python.log" 2>&1
status=$?
grep -E '(ok|FAIL|ERROR|skipped.*)$|^Ran |^OK|^FAILED' "$results/python.log" || true
ran=$(sed -n 's/^Ran \([0-9]*\) tests\?.*/\1/p' "$results/python.log")
bad=$(grep -cE '^(FAIL|ERROR): ' "$results/python.log")
if [[ -z "$ran" || "$ran" -eq 0 ]]; then
    tail -n 40 "$results/python.log"
    add_counts "0 1 0" "python"
else
    [[ $status -ne 0 && $bad -eq 0 ]] && bad=1
    [[ $bad -gt 0 ]] && grep -A30 -E '^(FAIL|ERROR): ' "$results/python.log" | head -n 80
    skips=$(sed -n 's/^OK (skipped=\([0-9]*\)).*/\1/p; s/^FAILED (.*skipped=\([0-9]*\).*/\1/p' \
        "$results/python.log" | tail -n1)
    skips=${skips:-0}
    add_counts "$((ran - bad - skips)) $bad $skips" "python"
fi
echo "test_in_opencv.sh: python tests took $((SECONDS - start)) s"

echo "in-tree: ${total_passed} passed, ${total_failed} failed, ${total_skipped} skipped"
[[ $total_failed -eq 0 ]]
