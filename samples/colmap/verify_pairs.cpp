// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "colmap/verify_pairs.hpp"

#include "colmap/pair_id.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <stdexcept>

namespace essential_colmap {

namespace {

double msSince(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

/** The keypoints of one image, undistorted to normalised coordinates. */
struct NormalisedKeypoints
{
    std::vector<cv::Point2d> points;
    std::vector<unsigned char> valid; //!< undistortion converged
};

/** A pair ready for the batch: its matches, the usable ones' indices and points. */
struct PreparedPair
{
    std::vector<FeatureMatch> matches;
    std::vector<int> usable; //!< indices into matches
    cv::essential::EssentialPair input;
};

/** The largest normalised coordinate the module accepts (essential.hpp: points more than 1e8 focal
lengths from the principal point are invalid input). A keypoint beyond it (a corrupt keypoints
blob: no camera images such a point) is unusable, as one whose undistortion did not converge, so
that it cannot make the estimate of its pair, and with it the whole verification, fail. */
constexpr double kMaxNormalisedCoordinate = 1e8;

NormalisedKeypoints normaliseKeypoints(const std::vector<cv::Point2f>& pixels,
                                       const CameraIntrinsics& camera)
{
    NormalisedKeypoints out;
    out.points.resize(pixels.size());
    out.valid.resize(pixels.size());
    for (std::size_t i = 0; i < pixels.size(); ++i) {
        cv::Point2d& n = out.points[i];
        out.valid[i] = undistortPixel(camera, cv::Point2d(pixels[i].x, pixels[i].y), n) &&
                       std::abs(n.x) <= kMaxNormalisedCoordinate &&
                       std::abs(n.y) <= kMaxNormalisedCoordinate;
    }
    return out;
}

/** The record of a pair without a geometry. */
TwoViewGeometryRecord degenerateRecord(std::int64_t pairId)
{
    TwoViewGeometryRecord r;
    r.pairId = pairId;
    r.config = CONFIG_DEGENERATE;
    return r;
}

/** COLMAP's configuration for an estimate with enough inliers: CALIBRATED, or UNCALIBRATED when a
focal length is only a guess; PANORAMIC when a rotation alone explains the inliers, PLANAR when a
homography does (the module's degeneracy report, EssentialReport::degenerate). */
int configOf(const cv::essential::EssentialReport& report, bool calibrated)
{
    if (report.degenerate)
        return report.rotationOnlyFraction >= report.homographyFraction ? CONFIG_PANORAMIC
                                                                        : CONFIG_PLANAR;
    return calibrated ? CONFIG_CALIBRATED : CONFIG_UNCALIBRATED;
}

} // namespace

Verification verifyPairs(ColmapDatabase& database, const VerificationOptions& options)
{
    if (options.minInliers < 6)
        throw std::invalid_argument("minimum inliers must be at least 6, got " +
                                    std::to_string(options.minInliers));
    Verification out;
    auto start = std::chrono::steady_clock::now();
    const std::map<std::int64_t, ColmapCamera> cameras = database.cameras();
    const std::map<std::int64_t, ColmapImage> images = database.images();

    std::vector<std::int64_t> pairIds = database.matchedPairs();
    if (options.unverifiedOnly) {
        const std::map<std::int64_t, StoredGeometry> stored = database.storedGeometries();
        pairIds.erase(std::remove_if(pairIds.begin(), pairIds.end(),
                                     [&](std::int64_t id) { return stored.count(id) > 0; }),
                      pairIds.end());
    }

    // The camera of every image that takes part, checked before anything is estimated.
    std::map<std::int64_t, CameraIntrinsics> intrinsicsOfImage;
    std::map<std::int64_t, bool> calibratedImage;
    for (std::int64_t pairId : pairIds) {
        const auto ids = imagesOfPair(pairId);
        for (std::int64_t id : {ids.first, ids.second}) {
            if (intrinsicsOfImage.count(id)) continue;
            const auto image = images.find(id);
            if (image == images.end())
                throw DatabaseError("pair " + std::to_string(pairId) + ": image " +
                                    std::to_string(id) + " is not in the images table");
            const auto camera = cameras.find(image->second.cameraId);
            if (camera == cameras.end())
                throw DatabaseError("image " + std::to_string(id) + " ('" + image->second.name +
                                    "'): camera " + std::to_string(image->second.cameraId) +
                                    " is not in the cameras table");
            intrinsicsOfImage[id] = cameraIntrinsics(camera->second);
            calibratedImage[id] = camera->second.priorFocalLength;
        }
    }
    std::map<std::int64_t, NormalisedKeypoints> keypoints;
    for (const auto& entry : intrinsicsOfImage)
        keypoints[entry.first] = normaliseKeypoints(database.keypoints(entry.first), entry.second);
    out.readMs += msSince(start);

    const int total = static_cast<int>(pairIds.size());
    const int minMatches = options.minInliers;
    int finished = 0;
    for (int first = 0; first < total; first += options.chunkSize) {
        start = std::chrono::steady_clock::now();
        const int last = std::min(total, first + options.chunkSize);
        std::vector<PreparedPair> prepared(static_cast<std::size_t>(last - first));
        std::vector<cv::essential::EssentialPair> batch;
        std::vector<int> batchSlot; // prepared index of each batch entry
        for (int k = first; k < last; ++k) {
            const std::int64_t pairId = pairIds[static_cast<std::size_t>(k)];
            const auto ids = imagesOfPair(pairId);
            const NormalisedKeypoints& kp1 = keypoints[ids.first];
            const NormalisedKeypoints& kp2 = keypoints[ids.second];
            PreparedPair& p = prepared[static_cast<std::size_t>(k - first)];
            // Both views in pixels of one virtual camera, focal length the mean of the two cameras'
            // and principal point at 0: the pixel threshold then means what COLMAP's max_error
            // means for a pair of cameras (normalised by their mean focal length). Summed in
            // quarters: the sum of four finite focal lengths may overflow, their mean cannot.
            const CameraIntrinsics& c1 = intrinsicsOfImage[ids.first];
            const CameraIntrinsics& c2 = intrinsicsOfImage[ids.second];
            const double focal = 0.25 * c1.fx + 0.25 * c1.fy + 0.25 * c2.fx + 0.25 * c2.fy;
            // A point whose virtual pixel is not finite (a focal length near the largest double)
            // is unusable too.
            const auto pixelFinite = [focal](const cv::Point2d& n) {
                return std::isfinite(focal * n.x) && std::isfinite(focal * n.y);
            };
            p.matches = database.matches(pairId);
            for (std::size_t m = 0; m < p.matches.size(); ++m) {
                const FeatureMatch& match = p.matches[m];
                if (match[0] >= kp1.points.size() || match[1] >= kp2.points.size())
                    throw DatabaseError(
                        "matches of pair " + std::to_string(pairId) + ": match " +
                        std::to_string(m) + " indexes keypoint " + std::to_string(match[0]) +
                        " / " + std::to_string(match[1]) + ", images " + std::to_string(ids.first) +
                        " and " + std::to_string(ids.second) + " have " +
                        std::to_string(kp1.points.size()) + " and " +
                        std::to_string(kp2.points.size()));
                if (kp1.valid[match[0]] && kp2.valid[match[1]] &&
                    pixelFinite(kp1.points[match[0]]) && pixelFinite(kp2.points[match[1]]))
                    p.usable.push_back(static_cast<int>(m));
            }
            if (static_cast<int>(p.usable.size()) < minMatches) continue;
            cv::Mat points1(static_cast<int>(p.usable.size()), 2, CV_64F);
            cv::Mat points2(points1.size(), CV_64F);
            for (std::size_t u = 0; u < p.usable.size(); ++u) {
                const FeatureMatch& match = p.matches[static_cast<std::size_t>(p.usable[u])];
                const cv::Point2d& a = kp1.points[match[0]];
                const cv::Point2d& b = kp2.points[match[1]];
                points1.at<double>(static_cast<int>(u), 0) = focal * a.x;
                points1.at<double>(static_cast<int>(u), 1) = focal * a.y;
                points2.at<double>(static_cast<int>(u), 0) = focal * b.x;
                points2.at<double>(static_cast<int>(u), 1) = focal * b.y;
            }
            p.input.points1 = points1;
            p.input.points2 = points2;
            p.input.cameraMatrix = cv::Mat(cv::Matx33d(focal, 0, 0, 0, focal, 0, 0, 0, 1));
            batch.push_back(p.input);
            batchSlot.push_back(k - first);
        }
        out.readMs += msSince(start);

        // Seeds from the chunk's position in the list of pairs (firstIndex): the results do not
        // depend on the number of threads.
        start = std::chrono::steady_clock::now();
        cv::essential::BatchProgress progress;
        if (options.progress) {
            const int base = finished;
            progress = [&options, base, total](int done, int) {
                options.progress(base + done, total);
            };
        }
        const std::vector<cv::essential::EssentialPairResult> results =
            cv::essential::findEssentialMatBatch(batch, options.params, options.threads, progress,
                                                 first);
        out.estimateMs += msSince(start);

        std::vector<int> resultOf(prepared.size(), -1);
        for (std::size_t b = 0; b < batchSlot.size(); ++b)
            resultOf[static_cast<std::size_t>(batchSlot[b])] = static_cast<int>(b);
        for (std::size_t s = 0; s < prepared.size(); ++s) {
            const std::int64_t pairId = pairIds[static_cast<std::size_t>(first) + s];
            const auto ids = imagesOfPair(pairId);
            const PreparedPair& p = prepared[s];
            PairVerification info;
            info.image1 = ids.first;
            info.image2 = ids.second;
            info.matches = static_cast<int>(p.matches.size());
            info.unusableMatches = static_cast<int>(p.matches.size() - p.usable.size());
            TwoViewGeometryRecord record = degenerateRecord(pairId);
            if (resultOf[s] >= 0) {
                const cv::essential::EssentialPairResult& result =
                    results[static_cast<std::size_t>(resultOf[s])];
                if (!result.error.empty())
                    throw std::runtime_error("pair " + std::to_string(pairId) + ": " +
                                             result.error);
                info.estimated = true;
                const cv::essential::EssentialReport& report = result.report;
                info.degenerateReport = report.degenerate;
                info.rotationOnlyFraction = report.rotationOnlyFraction;
                info.homographyFraction = report.homographyFraction;
                if (report.success && report.inliers >= options.minInliers) {
                    const bool calibrated =
                        calibratedImage[ids.first] && calibratedImage[ids.second];
                    record.config = configOf(report, calibrated);
                    const cv::Mat mask = result.mask;
                    for (std::size_t u = 0; u < p.usable.size(); ++u)
                        if (mask.at<unsigned char>(static_cast<int>(u)))
                            record.inlierMatches.push_back(
                                p.matches[static_cast<std::size_t>(p.usable[u])]);
                    record.E = report.E;
                    const cv::Matx33d K1 = intrinsicsOfImage[ids.first].K();
                    const cv::Matx33d K2 = intrinsicsOfImage[ids.second].K();
                    record.F = K2.inv().t() * report.E * K1.inv();
                    const double norm = cv::norm(record.F);
                    if (norm > 0) record.F *= 1.0 / norm;
                    if (report.poseRecovered) {
                        record.qvec = quaternionOf(report.R);
                        record.tvec = report.t;
                    }
                }
            }
            out.records.push_back(record);
            out.pairs.push_back(info);
        }
        finished = last;
    }
    return out;
}

} // namespace essential_colmap
