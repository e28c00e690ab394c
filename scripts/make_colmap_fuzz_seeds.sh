#!/usr/bin/env bash
# Makes the seed corpus of the colmap fuzz target (fuzz/fuzz_colmap.cpp) in fuzz/corpus/colmap/:
# a COLMAP 3.8 database of the rail frames (data/rail/sfm) made by COLMAP itself with few features
# (test/colmap/make_colmap_database.sh), cut down to three images, no descriptors (the tools do not
# read them) and 512-byte pages, then written as the target's inputs: an options byte (bit 0:
# write two_view_geometries, else a dry run) and the database file, or the options byte and the
# database as SQL (the target's second input form).
#   scripts/make_colmap_fuzz_seeds.sh [MAX_FEATURES]   (default 40)
# Needs colmap (scripts/bootstrap.sh installs it). Licensed under the Apache License, Version 2.0.
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."
max_features=${1:-40}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
test/colmap/make_colmap_database.sh data/rail/sfm "$work/rail.db" "$max_features" >/dev/null
out=fuzz/corpus/colmap
mkdir -p "$out"
/usr/bin/python3 - "$work/rail.db" "$work/small.db" "$out" <<'PY'
import sqlite3, sys
source, small, out = sys.argv[1:4]
db = sqlite3.connect(source)
kept_images = [r[0] for r in db.execute("SELECT image_id FROM images ORDER BY image_id LIMIT 3")]
max_id = max(kept_images)
db.execute("DELETE FROM descriptors")
db.execute("DELETE FROM images WHERE image_id > ?", (max_id,))
db.execute("DELETE FROM keypoints WHERE image_id > ?", (max_id,))
# pair_id = id1 * 2147483647 + id2 (id1 < id2): both images kept when id2 <= max_id.
db.execute("DELETE FROM matches WHERE pair_id % 2147483647 > ?", (max_id,))
db.execute("DELETE FROM two_view_geometries")
db.commit()
db.execute("PRAGMA page_size=512")
db.execute("VACUUM INTO ?", (small,))
db.close()
db = sqlite3.connect(small)
pairs = db.execute("SELECT pair_id, rows FROM matches").fetchall()
print("seed database: images", kept_images, "pairs (pair_id, matches)", pairs)
raw = open(small, "rb").read()
dump = "\n".join(line for line in db.iterdump()
                 if not line.startswith(("BEGIN", "COMMIT"))).encode()
for name, options, body in [("rail3_dry_run.db", 0x00, raw), ("rail3_write.db", 0x01, raw),
                            ("rail3_write_fail_row1.db", 0x03, raw),
                            ("rail3_dry_run.sql", 0x00, dump), ("rail3_write.sql", 0x01, dump)]:
    with open(f"{out}/{name}", "wb") as f:
        f.write(bytes([options]) + body)
    print(f"{out}/{name}: {len(body) + 1} bytes")
PY
