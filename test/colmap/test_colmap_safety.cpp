// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.
//
// essential_colmap never damages a database: a file that is not a COLMAP database is refused
// with a clear message and left unchanged byte for byte; an error part-way through writing rolls
// everything back; --dry-run writes nothing; --pairs unverified leaves the verified rows as they
// were.

#include "colmap/colmap_database.hpp"
#include "colmap/two_view_geometry.hpp"
#include "colmap/verify_pairs.hpp"
#include "colmap_test_support.hpp"

#include <sqlite3.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <regex>
#include <stdexcept>

using namespace essential_colmap;

namespace {

const std::string kProgram = ESSENTIAL_COLMAP_PROGRAM;

/** Runs SQL on a file through SQLite directly (creating it if needed). */
void runSql(const std::string& path, const std::string& sql)
{
    sqlite3* db = nullptr;
    ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
    char* message = nullptr;
    const int rc = sqlite3_exec(db, sql.c_str(), nullptr, nullptr, &message);
    const std::string text = message ? message : "";
    sqlite3_free(message);
    sqlite3_close(db);
    ASSERT_EQ(rc, SQLITE_OK) << text;
}

/** Runs essential_colmap on `path` with `arguments` and checks that the file did not change and
that the exit status and message are the refusal's. */
void expectRefusedUnchanged(const std::string& name, const std::string& path,
                            const std::string& expectedMessage)
{
    const std::vector<char> before = colmap_test::fileBytes(path);
    ASSERT_FALSE(before.empty());
    std::string output;
    const int status = colmap_test::runCommand(name, kProgram + " --database " + path, output);
    EXPECT_EQ(status, 1) << output;
    EXPECT_NE(output.find(expectedMessage), std::string::npos) << output;
    EXPECT_EQ(output.find('\n'), output.size() - 1) << "not one line: " << output;
    EXPECT_TRUE(colmap_test::fileBytes(path) == before) << "the file changed";
}

} // namespace

TEST(ColmapSafety, NonColmapDatabaseRefusedAndUnchanged)
{
    const std::string path = std::string(COLMAP_TEST_WORK) + "/not_colmap.db";
    std::remove(path.c_str());
    runSql(path, "CREATE TABLE notes (id INTEGER PRIMARY KEY, text TEXT);"
                 "INSERT INTO notes (text) VALUES ('keep me');");
    expectRefusedUnchanged("safety_not_colmap", path,
                           "is not a COLMAP database: no table 'cameras'");
    EXPECT_THROW(ColmapDatabase(path, true), DatabaseError);
}

TEST(ColmapSafety, FileThatIsNotSqliteRefusedAndUnchanged)
{
    const std::string path = std::string(COLMAP_TEST_WORK) + "/not_sqlite.db";
    std::ofstream(path) << "this is a text file, not a database\n";
    expectRefusedUnchanged("safety_not_sqlite", path, "file is not a database");
}

TEST(ColmapSafety, MissingColumnRefusedByName)
{
    const std::string path = colmap_test::copyOfColmapDatabase("safety_missing_column");
    if (path.empty()) GTEST_SKIP() << colmap_test::missingDatabaseReason();
    runSql(path, "ALTER TABLE two_view_geometries DROP COLUMN qvec");
    expectRefusedUnchanged("safety_missing_column", path,
                           "table 'two_view_geometries' has no column 'qvec'");
}

TEST(ColmapSafety, HalfOfTheRigSchemaRefused)
{
    // COLMAP 3.12+ makes rigs and frames together; one without the other is neither generation.
    const std::string path = colmap_test::copyOfColmapDatabase("safety_half_rig_schema");
    if (path.empty()) GTEST_SKIP() << colmap_test::missingDatabaseReason();
    const bool made = [&] {
        ColmapDatabase db(path, true);
        return db.schema() == ColmapSchema::WithRigs;
    }();
    if (made) {
        runSql(path, "DROP TABLE frame_data; DROP TABLE frames");
        expectRefusedUnchanged("safety_half_rig_schema", path,
                               "it has a table 'rigs' but no table 'frames'");
    } else {
        runSql(path, "CREATE TABLE frames (frame_id INTEGER PRIMARY KEY, rig_id INTEGER)");
        expectRefusedUnchanged("safety_half_rig_schema", path,
                               "it has a table 'frames' but no table 'rigs'");
    }
}

TEST(ColmapSafety, ErrorMidWriteRollsBackEverything)
{
    const std::string path = colmap_test::copyOfColmapDatabase("safety_rollback");
    if (path.empty()) GTEST_SKIP() << colmap_test::missingDatabaseReason();
    const std::vector<char> before = colmap_test::fileBytes(path);
    {
        ColmapDatabase db(path, false);
        const Verification verification = verifyPairs(db, VerificationOptions());
        ASSERT_GT(verification.records.size(), 3u);
        // The third row fails after it was written: the transaction must take the first three
        // back.
        EXPECT_THROW(writeTwoViewGeometries(db, verification.records,
                                            [](std::size_t written) {
                                                if (written == 3)
                                                    throw std::runtime_error("injected failure");
                                            }),
                     std::runtime_error);
    }
    EXPECT_TRUE(colmap_test::fileBytes(path) == before) << "the file changed";
}

TEST(ColmapSafety, DryRunWritesNothing)
{
    const std::string path = colmap_test::copyOfColmapDatabase("safety_dry_run");
    if (path.empty()) GTEST_SKIP() << colmap_test::missingDatabaseReason();
    const std::vector<char> before = colmap_test::fileBytes(path);
    std::string output;
    EXPECT_EQ(colmap_test::runCommand("safety_dry_run",
                                      kProgram + " --database " + path + " --dry-run", output),
              0)
        << output;
    EXPECT_NE(output.find("dry run, nothing written: 10 two_view_geometries rows replaced"),
              std::string::npos)
        << output;
    // One line per pair saying what would change (image ids follow COLMAP's extraction order).
    const std::regex change("pair \\d{3}\\.jpg - \\d{3}\\.jpg: CALIBRATED \\(\\d+ inliers\\) -> "
                            "CALIBRATED \\(\\d+ inliers of \\d+ matches\\)");
    EXPECT_EQ(std::distance(std::sregex_iterator(output.begin(), output.end(), change),
                            std::sregex_iterator()),
              10)
        << output;
    EXPECT_TRUE(colmap_test::fileBytes(path) == before) << "the file changed";
}

TEST(ColmapSafety, UnverifiedPairsOnlyLeaveTheOthersAsTheyWere)
{
    const std::string path = colmap_test::copyOfColmapDatabase("safety_unverified");
    if (path.empty()) GTEST_SKIP() << colmap_test::missingDatabaseReason();
    // Three pairs lose their verification; the seven others are COLMAP's and must stay so.
    runSql(path, "DELETE FROM two_view_geometries WHERE pair_id IN (SELECT pair_id FROM "
                 "two_view_geometries ORDER BY pair_id LIMIT 3)");
    const auto dumpRows = [&]() {
        ColmapDatabase db(path, true);
        SqliteStatement rows(db.connection(), "SELECT pair_id, hex(data), config, hex(F), hex(E) "
                                              "FROM two_view_geometries ORDER BY pair_id");
        std::map<std::int64_t, std::string> out;
        while (rows.step())
            out[rows.integer(0)] = rows.text(1) + rows.text(2) + rows.text(3) + rows.text(4);
        return out;
    };
    const auto before = dumpRows();
    ASSERT_EQ(before.size(), 7u);
    std::string output;
    ASSERT_EQ(colmap_test::runCommand(
                  "safety_unverified",
                  kProgram + " --database " + path + " --pairs unverified --json", output),
              0)
        << output;
    EXPECT_NE(output.find("\"pairs_verified\": 3"), std::string::npos) << output;
    EXPECT_NE(output.find("\"rows_inserted\": 3"), std::string::npos) << output;
    const auto after = dumpRows();
    EXPECT_EQ(after.size(), 10u);
    for (const auto& row : before)
        EXPECT_EQ(after.at(row.first), row.second) << "pair " << row.first;
}

TEST(ColmapSafety, UsageErrorsExitWithTwo)
{
    std::string output;
    EXPECT_EQ(colmap_test::runCommand("safety_usage_missing", kProgram, output), 2) << output;
    EXPECT_NE(output.find("missing --database"), std::string::npos) << output;
    EXPECT_EQ(colmap_test::runCommand("safety_usage_pairs",
                                      kProgram + " --database x.db --pairs some", output),
              2)
        << output;
    EXPECT_NE(output.find("--pairs must be all or unverified"), std::string::npos) << output;
    EXPECT_EQ(colmap_test::runCommand("safety_usage_min_inliers",
                                      kProgram + " --database x.db --min-inliers 5", output),
              2)
        << output;
    EXPECT_EQ(colmap_test::runCommand(
                  "safety_missing_file",
                  kProgram + " --database " + COLMAP_TEST_WORK + "/no_such_file.db", output),
              1)
        << output;
    EXPECT_NE(output.find("cannot open database"), std::string::npos) << output;
    EXPECT_FALSE(colmap_test::fileExists(std::string(COLMAP_TEST_WORK) + "/no_such_file.db"))
        << "a missing database must not be created";
}
