#!/usr/bin/env bash
# The test command against another OpenCV: builds the module and runs its whole suite inside a
# Debian root file system (scripts/debian_root.sh makes it, cached outside the clone):
#
#   scripts/test_in_debian.sh trixie        # Debian 13, OpenCV 4.10
#   scripts/test_in_debian.sh opencv5       # Debian unstable, OpenCV 5.0 (experimental)
#   scripts/test_in_debian.sh trixie demo   # scripts/demo.sh there instead
#
# The clone's files (tracked and untracked, not ignored: what a fresh clone of this tree would
# hold) are copied to /root/src in the root, their times kept, so that the build trees beside it
# (/root/build, /root/build-sanitize, kept between runs) rebuild only what changed; then
# scripts/test.sh runs there with ESSENTIAL_INTREE=0 (the in-tree stage builds OpenCV from source,
# done on the host only) and, unless ESSENTIAL_SANITIZE is set, ESSENTIAL_SANITIZE=0 (the
# sanitizer and fuzz stages check the module's own code, which does not change with OpenCV; they
# run on the host). Its suite is the host's: the drop-in parity tests against that root's
# cv::findEssentialMat / cv::recoverPose, that version's own tests (opencv_calib3d/*, from its
# Debian source package) and the Python package against its cv2 and numpy.
# The last line is "debian-NAME: N passed, M failed, K skipped" (scripts/test.sh adds it to its
# total).
# Licensed under the Apache License, Version 2.0.
set -uo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."

[[ $# -ge 1 && $# -le 2 ]] || { echo "usage: test_in_debian.sh trixie|opencv5 [demo]" >&2; exit 2; }
name=$1
what=${2:-test}
start=$SECONDS
root=$(scripts/debian_root.sh "$name" | tail -n1) && [[ -d "$root" ]] || {
    echo "test_in_debian.sh: no Debian root $name"
    echo "debian-$name: 0 passed, 1 failed, 0 skipped"
    exit 1
}
echo "test_in_debian.sh: root ready in $((SECONDS - start)) s: $(. "$root/etc/os-release" && echo "$PRETTY_NAME"), OpenCV $(chroot "$root" dpkg-query -W -f='${Version}' libopencv-core-dev 2>/dev/null)"

rm -rf "$root/root/src"
mkdir -p "$root/root/src"
git ls-files -z --cached --others --exclude-standard | tar --null -T - -cf - 2>/dev/null |
    tar -xf - -C "$root/root/src" || { echo "debian-$name: 0 passed, 1 failed, 0 skipped"; exit 1; }

if [[ "$what" == demo ]]; then
    scripts/in_debian_root.sh "$root" bash -c 'cd /root/src && BUILD_DIR=/root/build-demo scripts/demo.sh'
    exit $?
fi

log=$(mktemp)
ESSENTIAL_INTREE=0 ESSENTIAL_DEBIAN13=0 ESSENTIAL_OPENCV5=0 ESSENTIAL_SANITIZE=${ESSENTIAL_SANITIZE:-0} \
    scripts/in_debian_root.sh "$root" \
    bash -c 'cd /root/src && BUILD_DIR=/root/build SANITIZE_BUILD_DIR=/root/build-sanitize scripts/test.sh' \
    2>&1 | tee "$log"
summary=$(grep -E '^[0-9]+ passed, [0-9]+ failed, [0-9]+ skipped$' "$log" | tail -n1)
rm -f "$log"
echo "test_in_debian.sh: $name took $((SECONDS - start)) s"
if [[ -z "$summary" ]]; then
    echo "debian-$name: 0 passed, 1 failed, 0 skipped"
    exit 1
fi
echo "debian-$name: $summary"
[[ "$summary" == *" 0 failed, "* ]]
