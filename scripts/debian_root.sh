#!/usr/bin/env bash
# Makes (once) and prints the path of a Debian root file system in which the module is built and
# tested against another OpenCV than the host's, as a user of that Debian release would:
#
#   scripts/debian_root.sh trixie     # Debian 13: OpenCV 4.10, GCC 14, Python 3.13, numpy 2
#   scripts/debian_root.sh opencv5    # Debian unstable with OpenCV 5.0 from experimental
#                                     # (libopencv-dev 5.0.0+dfsg-1~exp1 and python3-opencv)
#
# debootstrap (minbase) writes the root into ${ESSENTIAL_DEBIAN_CACHE:-${XDG_CACHE_HOME:-
# $HOME/.cache}/opencv_essential}/debian-NAME, outside the clone; the project's own
# scripts/bootstrap.sh then installs the build and test packages inside it, as the README's
# commands do on a fresh machine. A root is reused while the packages it was made with are the
# same (a stamp holds the bootstrap list's hash); a changed list reruns bootstrap.sh in place.
# Needs root (debootstrap, chroot) and the network on the first run: measured on the 2-core
# machine, 21 s for debootstrap and 66 s for the packages (trixie). The host's apt configuration
# is not touched. Licensed under the Apache License, Version 2.0.
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."

die() {
    echo "debian_root.sh: $*" >&2
    exit 1
}

[[ $# -eq 1 ]] || die "usage: debian_root.sh trixie|opencv5"
name=$1
mirror=${DEBIAN_MIRROR:-http://deb.debian.org/debian}
case "$name" in
trixie) suite=trixie ;;
opencv5) suite=sid ;;
*) die "unknown root '$name' (trixie or opencv5)" ;;
esac

[[ $(id -u) -eq 0 ]] || die "needs root (debootstrap and chroot); run it as root or with sudo"
if ! command -v debootstrap >/dev/null; then
    echo "debian_root.sh: installing debootstrap" >&2
    DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends debootstrap >&2 ||
        { apt-get update -q >&2 && DEBIAN_FRONTEND=noninteractive apt-get install -y -q \
            --no-install-recommends debootstrap >&2; } || die "cannot install debootstrap"
fi

cache=${ESSENTIAL_DEBIAN_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/opencv_essential}
root="$cache/debian-$name"
mkdir -p "$cache"
exec 9>"$root.lock"
flock 9

if [[ ! -x "$root/usr/bin/apt-get" ]]; then
    rm -rf "$root.partial"
    start=$SECONDS
    echo "debian_root.sh: debootstrap $suite into $root" >&2
    debootstrap --variant=minbase "$suite" "$root.partial" "$mirror" >"$root.debootstrap.log" 2>&1 ||
        { tail -n 20 "$root.debootstrap.log" >&2; die "debootstrap $suite failed (log: $root.debootstrap.log)"; }
    if [[ "$name" == opencv5 ]]; then
        # OpenCV 5.0 is only in experimental: its packages (and only those) are preferred from
        # there; everything else comes from unstable, which experimental's builds are made for.
        echo "deb $mirror experimental main" >"$root.partial/etc/apt/sources.list.d/experimental.list"
        printf 'Package: *opencv*\nPin: release a=experimental\nPin-Priority: 990\n' \
            >"$root.partial/etc/apt/preferences.d/opencv5"
        # Unstable's and experimental's Release files expire within days (Valid-Until); a mirror
        # or snapshot that is behind (one here was 26 days behind) is refused by apt although
        # its signatures are good. The signatures are still checked; only the date is not.
        echo 'Acquire::Check-Valid-Until "false";' >"$root.partial/etc/apt/apt.conf.d/99valid-until"
    fi
    mv "$root.partial" "$root"
    echo "debian_root.sh: debootstrap took $((SECONDS - start)) s" >&2
fi

stamp="$root/.essential-packages"
want=$(sha256sum scripts/bootstrap.sh | cut -d' ' -f1)
if [[ ! -f "$stamp" || "$(cat "$stamp")" != "$want" ]]; then
    start=$SECONDS
    echo "debian_root.sh: installing the project's packages in $root (scripts/bootstrap.sh)" >&2
    cp /etc/resolv.conf "$root/etc/resolv.conf" 2>/dev/null || true
    mkdir -p "$root/tmp/essential-bootstrap"
    cp scripts/bootstrap.sh "$root/tmp/essential-bootstrap/"
    scripts/in_debian_root.sh "$root" bash /tmp/essential-bootstrap/bootstrap.sh >&2 ||
        die "bootstrap.sh failed inside $root"
    echo "$want" >"$stamp"
    echo "debian_root.sh: packages took $((SECONDS - start)) s" >&2
fi
echo "$root"
