// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.
//
// A COLMAP database whose schema is right but whose content is not (the colmap fuzz target's
// findings, fuzz/fuzz_colmap.cpp): a blob shape whose byte count wraps around is refused with a
// DatabaseError, a keypoint far outside any image makes its matches unusable instead of failing
// the whole verification, and a focal length for which the module would find the camera matrix
// singular is refused before any estimate; a corrupt file SQLite reads without complaint is
// refused before the write, which would have damaged it for good. The databases are built here with
// SQLite alone (no colmap needed).

#include "colmap/colmap_database.hpp"
#include "colmap/pair_id.hpp"
#include "colmap/two_view_geometry.hpp"
#include "colmap/verify_pairs.hpp"

#include <sqlite3.h>

#include <opencv2/calib3d.hpp>

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

using namespace essential_colmap;

namespace {

/** A file with the tables and columns the tools read (checkColmapSchema), and nothing else. */
std::string emptyColmapDatabase(const std::string& name)
{
    const std::string path = std::string(COLMAP_TEST_WORK) + "/" + name + ".db";
    std::remove(path.c_str());
    sqlite3* db = nullptr;
    EXPECT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
    const char* schema =
        "CREATE TABLE cameras (camera_id INTEGER PRIMARY KEY, model INTEGER, width INTEGER, "
        "height INTEGER, params BLOB, prior_focal_length INTEGER);"
        "CREATE TABLE images (image_id INTEGER PRIMARY KEY, name TEXT, camera_id INTEGER);"
        "CREATE TABLE keypoints (image_id INTEGER PRIMARY KEY, rows INTEGER, cols INTEGER, "
        "data BLOB);"
        "CREATE TABLE matches (pair_id INTEGER PRIMARY KEY, rows INTEGER, cols INTEGER, data BLOB);"
        "CREATE TABLE two_view_geometries (pair_id INTEGER PRIMARY KEY, rows INTEGER, "
        "cols INTEGER, data BLOB, config INTEGER, F BLOB, E BLOB, H BLOB, qvec BLOB, tvec BLOB);";
    EXPECT_EQ(sqlite3_exec(db, schema, nullptr, nullptr, nullptr), SQLITE_OK);
    sqlite3_close(db);
    return path;
}

/** Inserts one row: `sql` with integer parameters `values`, then `blob` bound last. */
void insertRow(const std::string& path, const std::string& sql,
               const std::vector<std::int64_t>& values, const void* blob, std::size_t bytes)
{
    SqliteConnection connection(path, false);
    SqliteStatement insert(connection, sql);
    int index = 1;
    for (std::int64_t v : values)
        insert.bind(index++, v);
    insert.bindBlob(index, blob, bytes);
    insert.step();
}

} // namespace

TEST(ColmapMalformedContent, BlobShapeWhoseByteCountWrapsAroundIsRefused)
{
    const std::string path = emptyColmapDatabase("malformed_wrapping_shape");
    // 768614336404564651 x 6 float32 is 2^64 + 8 bytes: 8 modulo 2^64, the blob's size.
    const std::int64_t wrappingRows = 768614336404564651;
    const unsigned char eightBytes[8] = {};
    insertRow(path, "INSERT INTO keypoints VALUES (1, ?, ?, ?)", {wrappingRows, 6}, eightBytes, 8);
    // 2^61 + 1 match pairs of two uint32 are 2^64 + 8 bytes too.
    const std::int64_t wrappingMatches = (std::int64_t(1) << 61) + 1;
    insertRow(path, "INSERT INTO matches VALUES (2147483650, ?, ?, ?)", {wrappingMatches, 2},
              eightBytes, 8);
    // A column count that wraps on its own.
    insertRow(path, "INSERT INTO keypoints VALUES (2, ?, ?, ?)", {1, std::int64_t(1) << 62},
              eightBytes, 0);

    ColmapDatabase db(path, true);
    EXPECT_THROW(db.keypoints(1), DatabaseError);
    EXPECT_THROW(db.matches(2147483650), DatabaseError);
    EXPECT_THROW(db.keypoints(2), DatabaseError);
}

namespace {

/** Two images of one PINHOLE camera with `params` (fx, fy, cx, cy; a known focal length) and 40
matched keypoints of a scene seen from two positions 1 apart, projected with f = 500 and principal
point (320, 240); keypoint `farIndex` of the first image (if >= 0) moved to x = 1e12 px. */
std::string twoViewDatabase(const std::string& name, const std::vector<double>& params,
                            int farIndex)
{
    const std::string path = emptyColmapDatabase(name);
    insertRow(path, "INSERT INTO cameras VALUES (1, 1, 640, 480, ?, 1)", {}, params.data(),
              params.size() * sizeof(double));
    {
        SqliteConnection connection(path, false);
        connection.execute("INSERT INTO images VALUES (1, 'a.jpg', 1), (2, 'b.jpg', 1)");
    }
    const int n = 40;
    cv::RNG rng(7);
    std::vector<float> kp1, kp2;
    for (int i = 0; i < n; ++i) {
        const cv::Vec3d X(rng.uniform(-2.0, 2.0), rng.uniform(-1.5, 1.5), rng.uniform(4.0, 8.0));
        const cv::Vec3d Y = X - cv::Vec3d(1, 0, 0);
        kp1.push_back(static_cast<float>(500 * X[0] / X[2] + 320));
        kp1.push_back(static_cast<float>(500 * X[1] / X[2] + 240));
        kp2.push_back(static_cast<float>(500 * Y[0] / Y[2] + 320));
        kp2.push_back(static_cast<float>(500 * Y[1] / Y[2] + 240));
    }
    if (farIndex >= 0) kp1[2 * static_cast<std::size_t>(farIndex)] = 1e12f;
    insertRow(path, "INSERT INTO keypoints VALUES (1, ?, 2, ?)", {n}, kp1.data(),
              kp1.size() * sizeof(float));
    insertRow(path, "INSERT INTO keypoints VALUES (2, ?, 2, ?)", {n}, kp2.data(),
              kp2.size() * sizeof(float));
    std::vector<FeatureMatch> matches;
    for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(n); ++i)
        matches.push_back({i, i});
    insertRow(path, "INSERT INTO matches VALUES (?, ?, 2, ?)", {pairIdOf(1, 2), n}, matches.data(),
              matches.size() * sizeof(FeatureMatch));
    return path;
}

} // namespace

TEST(ColmapMalformedContent, KeypointFarOutsideTheImageIsUnusableNotAnError)
{
    // One keypoint 1e12 pixels away: 2e9 focal lengths, beyond the module's 1e8.
    const std::string path = twoViewDatabase("malformed_far_keypoint", {500, 500, 320, 240}, 5);
    ColmapDatabase db(path, true);
    Verification verification;
    ASSERT_NO_THROW(verification = verifyPairs(db, VerificationOptions()));
    ASSERT_EQ(verification.pairs.size(), 1u);
    EXPECT_EQ(verification.pairs[0].unusableMatches, 1);
    EXPECT_TRUE(verification.pairs[0].estimated);
    // The 39 exact correspondences are the inliers of a calibrated pair.
    EXPECT_EQ(verification.records[0].config, CONFIG_CALIBRATED);
    EXPECT_EQ(verification.records[0].inlierMatches.size(), 39u);
}

TEST(ColmapMalformedContent, FocalLengthTheModuleWouldFindSingularIsRefused)
{
    // fx fy of 1e-320 (a denormal), 1e-160 (its square underflows) and 1e200 (its square
    // overflows): the module calls such a camera matrix singular; the database is refused before
    // any estimate, with a DatabaseError naming the camera.
    for (double f : {1e-320, 1e-160, 1e200}) {
        const std::string path = twoViewDatabase("malformed_focal", {f, f, 320, 240}, -1);
        ColmapDatabase db(path, true);
        try {
            verifyPairs(db, VerificationOptions());
            ADD_FAILURE() << "focal length " << f << " accepted";
        } catch (const DatabaseError& e) {
            EXPECT_NE(std::string(e.what()).find("camera 1"), std::string::npos) << e.what();
        }
    }
    // The ends of the accepted range go through (the points are then far outside or deep inside
    // the image: no pair verifies, but nothing fails).
    for (double f : {1e-100, 1e100}) {
        const std::string path = twoViewDatabase("malformed_focal", {f, f, 320, 240}, -1);
        ColmapDatabase db(path, true);
        EXPECT_NO_THROW(verifyPairs(db, VerificationOptions())) << "focal length " << f;
    }
}

TEST(ColmapMalformedContent, CorruptDatabaseRefusedBeforeTheWrite)
{
    // The fuzz target's input (an options byte, then the file): a database of the rail seed whose
    // b-tree pages 1 and 22 both claim a child page. SQLite reads it without complaint; writing
    // two_view_geometries into it made it unreadable ("malformed database schema").
    std::ifstream in(COLMAP_TEST_CORRUPT_INPUT, std::ios::binary);
    const std::vector<char> input((std::istreambuf_iterator<char>(in)),
                                  std::istreambuf_iterator<char>());
    ASSERT_GT(input.size(), 100u);
    const std::string path = std::string(COLMAP_TEST_WORK) + "/malformed_corrupt.db";
    std::ofstream(path, std::ios::binary)
        .write(input.data() + 1, std::streamsize(input.size() - 1));
    const std::vector<char> before(input.begin() + 1, input.end());
    {
        ColmapDatabase db(path, false);
        const Verification verification = verifyPairs(db, VerificationOptions());
        ASSERT_FALSE(verification.records.empty());
        try {
            writeTwoViewGeometries(db, verification.records);
            ADD_FAILURE() << "a corrupt database was written";
        } catch (const DatabaseError& e) {
            EXPECT_NE(std::string(e.what()).find("corrupt"), std::string::npos) << e.what();
        }
    }
    std::ifstream after(path, std::ios::binary);
    EXPECT_TRUE(std::vector<char>((std::istreambuf_iterator<char>(after)),
                                  std::istreambuf_iterator<char>()) == before)
        << "the file changed";
}
