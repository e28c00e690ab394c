#!/usr/bin/env bash
# Fetches Debian's source package of the installed OpenCV (the source version of
# libopencv-calib3d-dev, e.g. opencv 4.6.0+dfsg-12) and extracts into DEST the few parts that the
# ctest entries opencv_calib3d/* compile (test/opencv_calib3d/CMakeLists.txt): OpenCV's test
# framework modules/ts, the calib3d tests modules/calib3d/test, two private core headers that
# modules/ts includes, and LICENSE.
#
#   scripts/fetch_opencv_source.sh DEST
#   scripts/fetch_opencv_source.sh --full DEST
#
# With --full, DEST gets the whole upstream tree with every Debian patch applied (what
# scripts/build_in_opencv.sh configures; 168 MB extracted).
#
# apt-get does the work, with every directory it writes private to the cache below, so the system's
# apt sources and lists are neither read nor changed and neither root nor sudo is needed:
#   apt-get update       reads deb-src entries made from the system's own `deb` entries for its
#                        release (bookworm, bookworm-updates, bookworm-security: the same archive
#                        and keyring, /etc/apt/sources.list{,.d}), so the script names no server;
#                        the InRelease files are checked against the keyring those entries name;
#   apt-get --print-uris source opencv=VERSION
#                        gives each file of that exact version with its SHA256 from the signed index;
#   apt-helper download-file URI FILE SHA256:...
#                        downloads one file and checks its hash; only the main upstream tarball
#                        (74 MB) and the Debian tarball (36 kB) are taken, not the contrib tarball
#                        (54 MB) nor the .dsc, which nothing reads (the hashes come from the signed
#                        index; a mirror that lost the .dsc, as one did for 4.10.0+dfsg-5, does
#                        not stop the fetch). dpkg-source (dpkg-dev) is not needed.
# The tarballs stay in ${OPENCV_SOURCE_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/opencv_essential/
# opencv-source}, outside the clone: a warm run verifies their hashes and extracts without the
# network (8 s on a 2-core machine); DEST is left as is when it already holds the same version.
# The Debian patches (debian/patches/series) that change an extracted file are applied with patch
# -p1, in the series' order; the other files they change are extracted too, so that they apply
# whole (for 4.6.0+dfsg-12: one patch, which changes a comment in core/private.hpp).
# Exits non-zero with a message naming the failing step (no package, no network, unknown version).
# Licensed under the Apache License, Version 2.0.
set -euo pipefail

die() {
    echo "fetch_opencv_source.sh: $*" >&2
    if [[ ${full:-0} -eq 1 ]]; then
        echo "fetch_opencv_source.sh: the in-tree build needs this source; scripts/test.sh" \
            "skips it with ESSENTIAL_INTREE=0" >&2
    else
        echo "fetch_opencv_source.sh: the ctest entries opencv_calib3d/* need this source;" \
            "configure with -DESSENTIAL_OPENCV_OWN_TESTS=OFF to leave them out" >&2
    fi
    exit 1
}

full=0
if [[ $# -eq 2 && "$1" == --full ]]; then
    full=1
    shift
fi
[[ $# -eq 1 ]] || die "usage: fetch_opencv_source.sh [--full] DEST"
dest=$1

binary_package=libopencv-core-dev # in every version (5.0 has no calib3d package)
source_package=$(dpkg-query -W -f='${source:Package}' "$binary_package" 2>/dev/null) ||
    die "$binary_package is not installed (dpkg-query): the tests are those of the installed OpenCV"
version=$(dpkg-query -W -f='${source:Version}' "$binary_package")
# The extracted paths, relative to the top of the upstream tarball.
subset=(modules/ts modules/calib3d/test modules/core/include/opencv2/core/private.hpp
    modules/core/include/opencv2/core/utils/configuration.private.hpp LICENSE)
extent=subset
if [[ $full -eq 1 ]]; then
    # The upstream tarball's top-level entries: the Debian patches for the contrib tarball (not
    # taken) touch none of them and are skipped.
    subset=(CMakeLists.txt CONTRIBUTING.md COPYRIGHT LICENSE README.md SECURITY.md apps cmake data doc
        include modules platforms samples)
    extent=full
fi

stamp="$dest/.opencv-source-version"
if [[ -f "$stamp" && "$(cat "$stamp")" == "$source_package $version $extent" ]]; then
    exit 0
fi

if [[ -z "${OPENCV_SOURCE_CACHE:-}" && -z "${XDG_CACHE_HOME:-}" && -z "${HOME:-}" ]]; then
    die "no cache directory: set OPENCV_SOURCE_CACHE, XDG_CACHE_HOME or HOME"
fi
cache=${OPENCV_SOURCE_CACHE:-${XDG_CACHE_HOME:-${HOME:-}/.cache}/opencv_essential/opencv-source}
files_dir="$cache/$source_package-$version"
manifest="$files_dir/SHA256SUMS"
mkdir -p "$files_dir"

# Writes to $1 a deb822 sources file with a deb-src entry for every `deb` entry of the system's apt
# sources (one-line *.list and deb822 *.sources) whose suite is this release (VERSION_CODENAME of
# /etc/os-release, or a suite starting with it, such as bookworm-security) or sid, unstable or
# experimental (an unstable system's codename is that of testing, and OpenCV 5.0 is in
# experimental): the same URIs, components and Signed-By. Fails when there is none.
debsrc_entries() {
    local codename out=$1
    codename=$(. /etc/os-release && echo "${VERSION_CODENAME:-}")
    [[ -n "$codename" ]] || die "no VERSION_CODENAME in /etc/os-release"
    : >"$out"
    local files=() f
    [[ -r /etc/apt/sources.list ]] && files+=(/etc/apt/sources.list)
    for f in /etc/apt/sources.list.d/*.list /etc/apt/sources.list.d/*.sources; do
        [[ -r "$f" ]] && files+=("$f")
    done
    for f in "${files[@]}"; do
        if [[ "$f" == *.sources ]]; then
            # deb822: paragraphs of Field: value lines; a deb paragraph becomes a deb-src one.
            awk -v cn="$codename" '
                function flush() {
                    if (types ~ /(^| )deb( |$)/ && uris != "" && suites != "") {
                        n = split(suites, list, " "); keep = ""
                        for (i = 1; i <= n; i++)
                            if (list[i] == cn || index(list[i], cn "-") == 1 || list[i] ~ /^(sid|unstable|experimental)$/) keep = keep " " list[i]
                        if (keep != "") {
                            print "Types: deb-src"; print "URIs: " uris; print "Suites:" keep
                            print "Components: " comps
                            if (signed != "") print "Signed-By: " signed
                            print ""
                        }
                    }
                    types = uris = suites = comps = signed = ""
                }
                /^[[:space:]]*#/ { next }
                /^[[:space:]]*$/ { flush(); next }
                { line = $0; sub(/^[^:]*:[[:space:]]*/, "", line) }
                tolower($1) == "types:" { types = line }
                tolower($1) == "uris:" { uris = line }
                tolower($1) == "suites:" { suites = line }
                tolower($1) == "components:" { comps = line }
                tolower($1) == "signed-by:" { signed = line }
                END { flush() }' "$f" >>"$out"
        else
            # One-line format: deb [options] URI SUITE COMPONENT...
            awk -v cn="$codename" '
                $1 != "deb" { next }
                {
                    opts = ""; i = 2
                    if ($2 ~ /^\[/) { while ($i !~ /\]$/) { opts = opts " " $i; i++ } opts = opts " " $i; i++ }
                    uri = $i; suite = $(i + 1); comps = ""
                    for (j = i + 2; j <= NF; j++) comps = comps " " $j
                    if (suite != cn && index(suite, cn "-") != 1 && suite !~ /^(sid|unstable|experimental)$/) next
                    signed = ""
                    if (match(opts, /signed-by=[^] ]*/)) signed = substr(opts, RSTART + 10, RLENGTH - 10)
                    print "Types: deb-src"; print "URIs: " uri; print "Suites: " suite
                    print "Components:" comps
                    if (signed != "") print "Signed-By: " signed
                    print ""
                }' "$f" >>"$out"
        fi
    done
    [[ -s "$out" ]] || die "the system's apt sources have no deb entry for $codename to make deb-src entries from"
}

# True when every file of the manifest is present with its hash.
cached_files_valid() {
    [[ -s "$manifest" ]] && (cd "$files_dir" && sha256sum --check --quiet --status SHA256SUMS)
}

if ! cached_files_valid; then
    apt_dir="$cache/apt"
    mkdir -p "$apt_dir/lists/partial" "$apt_dir/cache/archives/partial" "$apt_dir/sources.list.d"
    : >"$apt_dir/sources.list"
    debsrc_entries "$apt_dir/sources.list.d/debian-src.sources"
    apt_options=(-o "Dir::Etc::sourcelist=$apt_dir/sources.list"
        -o "Dir::Etc::sourceparts=$apt_dir/sources.list.d"
        -o "Dir::State::Lists=$apt_dir/lists"
        -o "Dir::Cache=$apt_dir/cache")
    echo "fetch_opencv_source.sh: apt-get update (deb-src, private lists in $apt_dir)" >&2
    # --error-on=any: a list that cannot be fetched is an error, not a warning.
    apt-get "${apt_options[@]}" -q --error-on=any update >&2 ||
        die "apt-get update of the deb-src lists failed (no network, or the archive is unreachable)"
    uris=$(apt-get "${apt_options[@]}" --print-uris -q source "$source_package=$version" 2>&1) ||
        die "apt-get source $source_package=$version: the archive does not have this version: $uris"
    : >"$manifest.new"
    # Lines: 'URI' FILE SIZE SHA256:HASH. The upstream and Debian tarballs only.
    while read -r uri file _size hash; do
        uri=${uri//\'/}
        [[ "$file" == *.orig.tar.* || "$file" == *.debian.tar.* ]] || continue
        [[ "$hash" == SHA256:* ]] || die "no SHA256 for $file in the source index: $hash"
        echo "fetch_opencv_source.sh: downloading $file" >&2
        /usr/lib/apt/apt-helper "${apt_options[@]}" download-file "$uri" "$files_dir/$file" "$hash" >&2 ||
            die "downloading $uri failed"
        echo "${hash#SHA256:}  $file" >>"$manifest.new"
    done < <(grep "^'" <<<"$uris")
    mv "$manifest.new" "$manifest"
    cached_files_valid || die "the downloaded files do not match their SHA256 ($manifest)"
fi

# The manifest lists the files by name (second column).
orig=$(awk '$2 ~ /\.orig\.tar\./ { print $2; exit }' "$manifest")
debian=$(awk '$2 ~ /\.debian\.tar\./ { print $2; exit }' "$manifest")
[[ -n "$orig" && -n "$debian" ]] || die "no upstream or Debian tarball in $files_dir"

# The Debian patches that change an extracted file, and every file they change.
rm -rf "$dest.partial"
mkdir -p "$dest.partial"
tar -xf "$files_dir/$debian" -C "$dest.partial" debian/patches || die "no debian/patches in $debian"
# Files a patch changes (not those it creates): its '--- a/X' lines that are not /dev/null.
changed_files() {
    sed -e '\|^--- /dev/null|d' -n -e 's|^--- [^/[:space:]]*/\([^[:space:]]*\).*|\1|p' "$1" | sort -u
}
touches_subset() {
    local changed path
    for changed in "$@"; do
        for path in "${subset[@]}"; do
            [[ "$changed" == "$path" || "$changed" == "$path"/* ]] && return 0
        done
    done
    return 1
}
needed_patches=()
extract=("${subset[@]}")
if [[ -f "$dest.partial/debian/patches/series" ]]; then
    while read -r patch_name _; do
        [[ -z "$patch_name" || "$patch_name" == \#* ]] && continue
        mapfile -t changed < <(changed_files "$dest.partial/debian/patches/$patch_name")
        if touches_subset "${changed[@]}"; then
            needed_patches+=("$patch_name")
            extract+=("${changed[@]}")
        fi
    done <"$dest.partial/debian/patches/series"
fi

if [[ $full -eq 1 ]]; then
    echo "fetch_opencv_source.sh: extracting all of $orig into $dest" >&2
    tar -xf "$files_dir/$orig" -C "$dest.partial" --strip-components=1 ||
        die "extracting from $orig failed"
else
    echo "fetch_opencv_source.sh: extracting ${subset[*]} from $orig into $dest" >&2
    # Each path once: tar reports a second pattern for a member it has already extracted as not
    # found.
    mapfile -t extract < <(printf '%s\n' "${extract[@]}" | sort -u)
    patterns=()
    for path in "${extract[@]}"; do patterns+=("*/$path"); done
    # --no-wildcards-match-slash: '*' is the top directory (opencv-4.6.0) only; a matched directory
    # comes with everything below it.
    tar -xf "$files_dir/$orig" -C "$dest.partial" --strip-components=1 --wildcards \
        --no-wildcards-match-slash "${patterns[@]}" || die "extracting from $orig failed"
fi
for path in "${subset[@]}"; do
    [[ -e "$dest.partial/$path" ]] || die "$orig has no $path"
done
if [[ ${#needed_patches[@]} -gt 0 ]]; then
    command -v patch >/dev/null || die "the Debian patches ${needed_patches[*]} need the program patch"
    for patch_name in "${needed_patches[@]}"; do
        echo "fetch_opencv_source.sh: applying debian/patches/$patch_name" >&2
        patch -d "$dest.partial" -p1 -s --forward --no-backup-if-mismatch \
            <"$dest.partial/debian/patches/$patch_name" || die "debian/patches/$patch_name does not apply"
    done
fi
echo "$source_package $version $extent" >"$dest.partial/.opencv-source-version"
rm -rf "$dest"
mv "$dest.partial" "$dest"
