// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.
//
// essential_colmap: COLMAP's geometric verification done by the module. Reads the cameras, images,
// keypoints and raw matches of a COLMAP database, estimates an essential matrix for every
// matched pair in parallel (findEssentialMatBatch) and writes two_view_geometries as COLMAP's own
// verification does, in one transaction; `colmap mapper` then reconstructs from it.

#include "cli_common.hpp"
#include "cli_parser.hpp"
#include "colmap/colmap_database.hpp"
#include "colmap/verify_pairs.hpp"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <map>
#include <mutex>
#include <string>
#include <unistd.h>

namespace {

using essential_colmap::ColmapDatabase;
using essential_colmap::StoredGeometry;
using essential_colmap::twoViewConfigName;
using essential_colmap::Verification;
using essential_colmap::VerificationOptions;
// The command-line helpers the sample programs share (cli_common.hpp).
namespace cli = essential_samples;

const char* const kUsage =
    "usage: essential_colmap --database DB.db [--threads N] [--solver S] [--threshold-px PX]\n"
    "                        [--min-inliers K] [--pairs all|unverified] [--max-iterations N]\n"
    "                        [--seed S] [--dry-run] [--json]\n"
    "\n"
    "Verifies the matched image pairs of a COLMAP database (3.x, or 3.12+ with rigs) with\n"
    "cv::essential and writes its two_view_geometries table (config, inlier matches, E, F,\n"
    "relative pose) in one transaction; nothing else in the database changes. Keypoints are\n"
    "undistorted with each camera's model (SIMPLE_PINHOLE, PINHOLE, SIMPLE_RADIAL, RADIAL,\n"
    "OPENCV).\n"
    "\n"
    "  --database DB.db      the COLMAP database (after feature extraction and matching)\n"
    "  --threads N           worker threads (default: all cores)\n"
    "  --solver S            the module's solver or mix (default gn+nister)\n"
    "  --threshold-px PX     inlier threshold on the Sampson distance in pixels, normalised by\n"
    "                        the mean focal length of the pair's cameras (default 4, COLMAP's\n"
    "                        SiftMatching.max_error)\n"
    "  --min-inliers K       fewer inliers make a pair DEGENERATE (default 15, COLMAP's\n"
    "                        min_num_inliers; at least 6)\n"
    "  --pairs all|unverified  every matched pair (default), or only those without a\n"
    "                        two_view_geometries row\n"
    "  --max-iterations N    the module's iteration cap (default 1000)\n"
    "  --seed S              seed of the batch (decimal or 0x hex)\n"
    "  --dry-run             write nothing; print what would change\n"
    "  --json                print the summary (and each pair's change) as one JSON object\n"
    "  (deprecated spellings, accepted with a warning: --threshold, --max-iters)\n"
    "\n"
    "exit status: 0 done, 1 input error (database refused, unreadable, not written), 2 usage "
    "error\n";

struct Options
{
    std::string database;
    VerificationOptions verification;
    bool dryRun = false;
    bool json = false;
};

/** One option with a value into `options` (its name without "--", deprecated spellings already
renamed by the parser); cli::fail(..., 2) for a bad value. */
void parseValueOption(const std::string& name, const std::string& value, Options& options)
{
    long long number;
    cv::essential::EssentialParams& params = options.verification.params;
    if (name == "database") {
        options.database = value;
    } else if (name == "threads") {
        if (!cli::parseInt(value, number) || number < 1 || number > 1024)
            cli::fail("--threads must be an integer in [1, 1024], not '" + value + "'", 2);
        options.verification.threads = static_cast<int>(number);
    } else if (name == "solver") {
        // One name or mix ("gn+nister"); createSolver() checks it and names the registered ones.
        if (cli::parseSolverList("--solver", value).size() != 1)
            cli::fail("--solver takes one solver or mix (gn+nister), not a list", 2);
        params.solver = value;
    } else if (name == "threshold-px") {
        if (!cli::parseDouble(value, params.threshold) || !(params.threshold > 0.0))
            cli::fail("--threshold-px must be a positive number of pixels, not '" + value + "'", 2);
    } else if (name == "min-inliers") {
        if (!cli::parseInt(value, number) || number < 6 || number > 1000000)
            cli::fail("--min-inliers must be an integer of at least 6, not '" + value + "'", 2);
        options.verification.minInliers = static_cast<int>(number);
    } else if (name == "pairs") {
        if (value != "all" && value != "unverified")
            cli::fail("--pairs must be all or unverified, not '" + value + "'", 2);
        options.verification.unverifiedOnly = value == "unverified";
    } else if (name == "max-iterations") {
        if (!cli::parseInt(value, number) || number < 1 || number > 100000000)
            cli::fail("--max-iterations must be a positive integer, not '" + value + "'", 2);
        params.maxIterations = static_cast<int>(number);
    } else if (name == "seed") {
        if (!cli::parseSeed(value, params.seed))
            cli::fail("--seed must be a non-negative integer, not '" + value + "'", 2);
    }
}

Options parseOptions(int argc, char** argv)
{
    // The same parser and the same option names as essential_pair and essential_sequence; the
    // spellings from before they shared their names are accepted with a warning.
    const std::vector<cli::OptionSpec> specs = {{"database", true, ""},
                                                {"threads", true, ""},
                                                {"solver", true, ""},
                                                {"threshold-px", true, ""},
                                                {"min-inliers", true, ""},
                                                {"pairs", true, ""},
                                                {"max-iterations", true, ""},
                                                {"seed", true, ""},
                                                {"dry-run", false, ""},
                                                {"json", false, ""},
                                                {"threshold", true, "threshold-px"},
                                                {"max-iters", true, "max-iterations"}};
    const cli::CommandLine line = cli::parseCommandLine("essential_colmap", argc, argv, specs);
    if (line.help) {
        std::cout << kUsage;
        std::exit(0);
    }
    if (!line.positional.empty())
        cli::fail("unexpected argument '" + line.positional.front() + "' (see --help)", 2);
    Options options;
    for (const cli::GivenOption& option : line.options) {
        if (option.name == "dry-run")
            options.dryRun = true;
        else if (option.name == "json")
            options.json = true;
        else
            parseValueOption(option.name, option.value, options);
    }
    if (options.database.empty()) cli::fail("missing --database DB.db (see --help)", 2);
    return options;
}

/** A progress line with pairs per second on stderr, at most ten times a second, only on a
terminal (a log or a pipe gets the summary alone). */
class ProgressLine
{
public:
    ProgressLine() : enabled_(isatty(fileno(stderr)) != 0) {}

    cv::essential::BatchProgress callback()
    {
        if (!enabled_) return cv::essential::BatchProgress();
        return [this](int done, int total) { update(done, total); };
    }

    void finish()
    {
        if (enabled_ && shown_) std::fprintf(stderr, "\r%70s\r", "");
    }

private:
    void update(int done, int total)
    {
        std::lock_guard<std::mutex> lock(mutex_);
        const double ms = cli::elapsedMs(start_);
        if (done != total && ms - lastMs_ < 100) return;
        lastMs_ = ms;
        shown_ = true;
        std::fprintf(stderr, "\ressential_colmap: %d / %d pairs, %.0f pairs/s   ", done, total,
                     ms > 0 ? 1000.0 * done / ms : 0.0);
        std::fflush(stderr);
    }

    bool enabled_;
    bool shown_ = false;
    std::mutex mutex_;
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
    double lastMs_ = -1e9;
};

int run(int argc, char** argv)
{
    const Options options = parseOptions(argc, argv);
    const auto start = std::chrono::steady_clock::now();
    ColmapDatabase database(options.database, options.dryRun);
    const std::map<std::int64_t, StoredGeometry> before = database.storedGeometries();
    const std::map<std::int64_t, essential_colmap::ColmapImage> images = database.images();

    ProgressLine progress;
    VerificationOptions verification = options.verification;
    verification.progress = progress.callback();
    const Verification result = essential_colmap::verifyPairs(database, verification);
    progress.finish();

    const auto writeStart = std::chrono::steady_clock::now();
    if (!options.dryRun) essential_colmap::writeTwoViewGeometries(database, result.records);
    const double writeMs = cli::elapsedMs(writeStart);
    const double totalMs = cli::elapsedMs(start);

    std::map<std::string, int> configCounts;
    int replaced = 0, inserted = 0;
    long long inliers = 0;
    nlohmann::json pairs = nlohmann::json::array();
    const auto nameOf = [&](std::int64_t id) {
        const auto image = images.find(id);
        return image == images.end() ? std::to_string(id) : image->second.name;
    };
    for (std::size_t i = 0; i < result.records.size(); ++i) {
        const auto& record = result.records[i];
        const auto& info = result.pairs[i];
        ++configCounts[twoViewConfigName(record.config)];
        inliers += static_cast<long long>(record.inlierMatches.size());
        const auto old = before.find(record.pairId);
        (old == before.end() ? inserted : replaced) += 1;
        nlohmann::json entry = {
            {"pair_id", record.pairId},
            {"image1", nameOf(info.image1)},
            {"image2", nameOf(info.image2)},
            {"matches", info.matches},
            {"before", old == before.end()
                           ? nlohmann::json(nullptr)
                           : nlohmann::json{{"config", twoViewConfigName(old->second.config)},
                                            {"inliers", old->second.inliers}}},
            {"after",
             {{"config", twoViewConfigName(record.config)},
              {"inliers", record.inlierMatches.size()}}}};
        if (info.unusableMatches > 0) entry["unusable_matches"] = info.unusableMatches;
        pairs.push_back(entry);
    }
    const int threads = verification.threads > 0 ? verification.threads : cv::getNumThreads();
    const double pairsPerSecond =
        result.estimateMs > 0 ? 1000.0 * result.records.size() / result.estimateMs : 0.0;

    if (options.json) {
        nlohmann::json out = {{"database", options.database},
                              {"schema", essential_colmap::schemaName(database.schema())},
                              {"dry_run", options.dryRun},
                              {"solver", verification.params.solver},
                              {"threshold_px", verification.params.threshold},
                              {"min_inliers", verification.minInliers},
                              {"threads", threads},
                              {"pairs_verified", result.records.size()},
                              {"configs", configCounts},
                              {"inlier_matches", inliers},
                              {"rows_replaced", replaced},
                              {"rows_inserted", inserted},
                              {"read_ms", result.readMs},
                              {"estimate_ms", result.estimateMs},
                              {"write_ms", writeMs},
                              {"total_ms", totalMs},
                              {"pairs_per_second", pairsPerSecond},
                              {"pairs", pairs}};
        std::cout << out.dump(2) << "\n";
        return 0;
    }
    if (options.dryRun)
        for (const auto& entry : pairs) {
            const auto& b = entry["before"];
            std::printf("pair %s - %s: %s -> %s (%d inliers of %d matches)\n",
                        entry["image1"].get<std::string>().c_str(),
                        entry["image2"].get<std::string>().c_str(),
                        b.is_null() ? "no row"
                                    : (b["config"].get<std::string>() + " (" +
                                       std::to_string(b["inliers"].get<long long>()) + " inliers)")
                                          .c_str(),
                        entry["after"]["config"].get<std::string>().c_str(),
                        entry["after"]["inliers"].get<int>(), entry["matches"].get<int>());
        }
    std::printf("%s (%s): %zu pairs verified with %s, threshold %.3g px, %d threads\n",
                options.database.c_str(), essential_colmap::schemaName(database.schema()),
                result.records.size(), verification.params.solver.c_str(),
                verification.params.threshold, threads);
    std::printf("time: %.1f ms reading and undistorting, %.1f ms estimating (%.0f pairs/s), "
                "%.1f ms writing, %.1f ms in all\n",
                result.readMs, result.estimateMs, pairsPerSecond, writeMs, totalMs);
    std::printf("configs:");
    for (const auto& count : configCounts)
        std::printf(" %s %d", count.first.c_str(), count.second);
    std::printf("; %lld inlier matches\n", inliers);
    std::printf("%s %d two_view_geometries rows replaced, %d inserted\n",
                options.dryRun ? "dry run, nothing written:" : "written:", replaced, inserted);
    return 0;
}

} // namespace

int main(int argc, char** argv)
{
    return cli::runCli("essential_colmap", run, argc, argv);
}
