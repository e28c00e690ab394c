#!/usr/bin/env bash
# Runs a command inside a Debian root file system made by scripts/debian_root.sh:
#
#   scripts/in_debian_root.sh ROOT COMMAND [ARG...]
#
# In a mount namespace of its own (unshare), so that /proc, /sys and /dev, mounted into ROOT for
# the command, go away with it even when it is killed; with a clean environment (PATH, HOME=/root,
# LANG=C.UTF-8, and JOBS, CI, FUZZ_SECONDS and the ESSENTIAL_* switches passed through).
# Needs root. Licensed under the Apache License, Version 2.0.
set -euo pipefail

[[ $# -ge 2 ]] || { echo "usage: in_debian_root.sh ROOT COMMAND [ARG...]" >&2; exit 2; }
root=$1
shift
[[ -x "$root/usr/bin/env" ]] || { echo "in_debian_root.sh: $root is not a root file system" >&2; exit 1; }

pass=(PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin HOME=/root LANG=C.UTF-8
    DEBIAN_FRONTEND=noninteractive)
for var in JOBS CI FUZZ_SECONDS $(compgen -v | grep '^ESSENTIAL_' || true); do
    [[ -n "${!var:-}" ]] && pass+=("$var=${!var}")
done

exec unshare --mount --propagation private -- bash -c '
    root=$1; shift
    mount -t proc proc "$root/proc"
    mount --rbind /sys "$root/sys"
    mount --rbind /dev "$root/dev"
    exec chroot "$root" "$@"' bash "$root" /usr/bin/env -i "${pass[@]}" "$@"
