// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "frontend/frontend.hpp"
#include "named_values.hpp"

#include <opencv2/features2d.hpp>
#include <opencv2/flann.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace essential_samples {

namespace {

// ORB's descriptor patch is 31 x 31 pixels; the orientation uses a disc of this radius.
const int kPatchSize = 31;
const int kOrientationRadius = kPatchSize / 2;

void checkParams(const FrontEndParams& params)
{
    if (params.fastThreshold < 1 || params.fastThreshold > 254)
        throw std::invalid_argument("front end: fastThreshold must be in [1, 254]");
    if (params.border < kOrientationRadius + 1)
        throw std::invalid_argument("front end: border must be at least " +
                                    std::to_string(kOrientationRadius + 1));
    if (params.minLevelSize < 2 * params.border + 1)
        throw std::invalid_argument("front end: minLevelSize must exceed twice the border");
    if (!(params.keepFraction > 0.0 && params.keepFraction <= 1.0))
        throw std::invalid_argument("front end: keepFraction must be in (0, 1]");
    if (params.siftFeatures < 0)
        throw std::invalid_argument("front end: siftFeatures must be >= 0 (0: all)");
    if (!(params.ratio > 0.0 && params.ratio <= 1.0))
        throw std::invalid_argument("front end: ratio must be in (0, 1]");
    if (params.detector == Detector::Fast9Pyramid && params.descriptor == Descriptor::Sift)
        throw std::invalid_argument("front end: the SIFT descriptor needs Detector::Sift");
    if (params.detector == Detector::Sift && params.descriptor != Descriptor::Sift &&
        params.descriptor != FrontEndParams().descriptor)
        throw std::invalid_argument("front end: Detector::Sift computes SIFT descriptors; the "
                                    "descriptor must be Sift or the default");
}

// Orientation of the intensity centroid of the disc of radius kOrientationRadius around (x, y),
// in degrees in [0, 360), as ORB computes it. (x, y) must be at least the radius from the border.
float intensityCentroidAngle(const cv::Mat& image, int x, int y)
{
    const int r = kOrientationRadius;
    double m10 = 0.0, m01 = 0.0;
    for (int dy = -r; dy <= r; ++dy) {
        const int half = static_cast<int>(std::floor(std::sqrt(double(r * r - dy * dy))));
        const uchar* row = image.ptr<uchar>(y + dy);
        for (int dx = -half; dx <= half; ++dx) {
            const double v = row[x + dx];
            m10 += dx * v;
            m01 += dy * v;
        }
    }
    double angle = std::atan2(m01, m10) * 180.0 / CV_PI;
    if (angle < 0.0) angle += 360.0;
    return static_cast<float>(angle);
}

// The grey patch: kPatchGrid x kPatchGrid samples kPatchStep pixels apart, on the level smoothed
// with a Gaussian of sigma kPatchSigma.
const int kPatchGrid = 8;
const int kPatchStep = 2;
const double kPatchSigma = 1.2;

// Describes `keypoints` (level coordinates, all at least `border` from the edges) by normalised
// grey patches of the smoothed level; drops the corners whose patch is flat.
void describePatches(const cv::Mat& levelImage, std::vector<cv::KeyPoint>& keypoints,
                     cv::Mat& descriptors)
{
    cv::Mat smooth;
    cv::GaussianBlur(levelImage, smooth, cv::Size(), kPatchSigma, kPatchSigma,
                     cv::BORDER_REFLECT_101);
    const int half = (kPatchGrid - 1) * kPatchStep / 2; // 7: samples at -7, -5, ..., 7
    std::vector<cv::KeyPoint> kept;
    kept.reserve(keypoints.size());
    descriptors.create(static_cast<int>(keypoints.size()), kPatchGrid * kPatchGrid, CV_32F);
    int rows = 0;
    for (const cv::KeyPoint& kp : keypoints) {
        const int x0 = cvRound(kp.pt.x) - half, y0 = cvRound(kp.pt.y) - half;
        float* d = descriptors.ptr<float>(rows);
        double sum = 0.0;
        for (int i = 0; i < kPatchGrid; ++i) {
            const uchar* row = smooth.ptr<uchar>(y0 + i * kPatchStep);
            for (int j = 0; j < kPatchGrid; ++j) {
                d[i * kPatchGrid + j] = row[x0 + j * kPatchStep];
                sum += row[x0 + j * kPatchStep];
            }
        }
        const float mean = static_cast<float>(sum / (kPatchGrid * kPatchGrid));
        double norm2 = 0.0;
        for (int k = 0; k < kPatchGrid * kPatchGrid; ++k) {
            d[k] -= mean;
            norm2 += double(d[k]) * d[k];
        }
        if (norm2 < 1e-6) continue; // flat: no descriptor
        const float scale = static_cast<float>(1.0 / std::sqrt(norm2));
        for (int k = 0; k < kPatchGrid * kPatchGrid; ++k)
            d[k] *= scale;
        kept.push_back(kp);
        ++rows;
    }
    descriptors = descriptors.rowRange(0, rows).clone();
    keypoints.swap(kept);
}

// Matcher::Grid: keeps, in each cell of a kGridCells x kGridCells grid over the image, the
// kGridCorners / kGridCells^2 corners of highest response (the FAST score, or SIFT's contrast;
// ties: detection order), whatever their level.
void keepStrongestPerCell(cv::Size imageSize, Features& features)
{
    const int perCell = kGridCorners / (kGridCells * kGridCells);
    std::vector<std::vector<int>> cells(kGridCells * kGridCells);
    for (size_t i = 0; i < features.keypoints.size(); ++i) {
        const cv::Point2f& p = features.keypoints[i].pt;
        const int cx =
            std::min(kGridCells - 1, std::max(0, int(p.x * kGridCells / imageSize.width)));
        const int cy =
            std::min(kGridCells - 1, std::max(0, int(p.y * kGridCells / imageSize.height)));
        cells[cy * kGridCells + cx].push_back(static_cast<int>(i));
    }
    std::vector<int> kept;
    for (std::vector<int>& cell : cells) {
        std::stable_sort(cell.begin(), cell.end(), [&](int a, int b) {
            return features.keypoints[a].response > features.keypoints[b].response;
        });
        if (cell.size() > size_t(perCell)) cell.resize(perCell);
        kept.insert(kept.end(), cell.begin(), cell.end());
    }
    std::sort(kept.begin(), kept.end()); // detection order, as the other matchers see them
    std::vector<cv::KeyPoint> keypoints;
    cv::Mat descriptors(static_cast<int>(kept.size()), features.descriptors.cols,
                        features.descriptors.type());
    keypoints.reserve(kept.size());
    for (size_t r = 0; r < kept.size(); ++r) {
        keypoints.push_back(features.keypoints[kept[r]]);
        features.descriptors.row(kept[r]).copyTo(descriptors.row(static_cast<int>(r)));
    }
    features.keypoints.swap(keypoints);
    features.descriptors = descriptors;
}

// Nearest neighbour in features1 of every descriptor of features2, approximately: FLANN's LSH
// (binary descriptors) or randomised k-d trees (patch). A query LSH finds no candidate for gets no
// match.
std::vector<cv::DMatch> flannNearest(const Features& features1, const Features& features2)
{
    cv::Ptr<cv::flann::IndexParams> index;
    // LSH: 4 tables of 12-bit keys, one probe level, the fastest of the settings measured with the
    // same inlier ratio as brute force (docs/FRONTEND.md, "Faster matching").
    if (features1.descriptor == Descriptor::Patch)
        index = cv::makePtr<cv::flann::KDTreeIndexParams>(4);
    else
        index = cv::makePtr<cv::flann::LshIndexParams>(4, 12, 1);
    cv::FlannBasedMatcher matcher(index, cv::makePtr<cv::flann::SearchParams>(32));
    std::vector<std::vector<cv::DMatch>> knn;
    matcher.knnMatch(features2.descriptors, features1.descriptors, knn, 1);
    std::vector<cv::DMatch> nearest;
    nearest.reserve(knn.size());
    for (const std::vector<cv::DMatch>& candidates : knn)
        if (!candidates.empty()) nearest.push_back(candidates.front());
    return nearest;
}

// Detector::Sift: cv::SIFT's keypoints and descriptors of the grey image (then Matcher::Grid's
// selection, as for the FAST corners).
Features detectSift(const cv::Mat& gray, const FrontEndParams& params)
{
    Features features;
    features.descriptor = Descriptor::Sift;
    const cv::Ptr<cv::SIFT> sift = cv::SIFT::create(params.siftFeatures);
    sift->detectAndCompute(gray, cv::noArray(), features.keypoints, features.descriptors);
    features.cornersDetected = static_cast<int>(features.keypoints.size());
    if (!features.keypoints.empty()) {
        // cv::SIFT packs the octave into the low byte of `octave` (signed; -1: doubled image).
        int lowest = 255, highest = -255;
        for (const cv::KeyPoint& kp : features.keypoints) {
            const int octave = static_cast<signed char>(kp.octave & 255);
            lowest = std::min(lowest, octave);
            highest = std::max(highest, octave);
        }
        features.levels = highest - lowest + 1;
    }
    if (params.matcher == Matcher::Grid) keepStrongestPerCell(gray.size(), features);
    return features;
}

// SIFT descriptors: the two nearest neighbours in features1 of every descriptor of features2 (L2;
// brute force, or randomised k-d trees with Matcher::Flann), and the nearest of those that pass
// Lowe's ratio test. `candidates`: the descriptors of features2 that got two neighbours.
std::vector<cv::DMatch> ratioTestMatches(const Features& features1, const Features& features2,
                                         const FrontEndParams& params, int& candidates)
{
    std::vector<std::vector<cv::DMatch>> knn;
    if (params.matcher == Matcher::Flann) {
        cv::FlannBasedMatcher matcher(cv::makePtr<cv::flann::KDTreeIndexParams>(4),
                                      cv::makePtr<cv::flann::SearchParams>(32));
        matcher.knnMatch(features2.descriptors, features1.descriptors, knn, 2);
    } else {
        cv::BFMatcher matcher(cv::NORM_L2, false);
        matcher.knnMatch(features2.descriptors, features1.descriptors, knn, 2);
    }
    candidates = 0;
    std::vector<cv::DMatch> kept;
    kept.reserve(knn.size());
    for (const std::vector<cv::DMatch>& neighbours : knn) {
        if (neighbours.size() < 2) continue;
        ++candidates;
        if (neighbours[0].distance < params.ratio * neighbours[1].distance)
            kept.push_back(neighbours[0]);
    }
    return kept;
}

const NamedValue<Detector> kDetectorNames[] = {{"fast", Detector::Fast9Pyramid},
                                               {"sift", Detector::Sift}};

const NamedValue<Matcher> kMatcherNames[] = {
    {"brute-force", Matcher::BruteForce}, {"grid", Matcher::Grid}, {"flann", Matcher::Flann}};

const NamedValue<Descriptor> kDescriptorNames[] = {{"brief", Descriptor::UprightBrief},
                                                   {"orb", Descriptor::RotatedBrief},
                                                   {"patch", Descriptor::Patch},
                                                   {"sift", Descriptor::Sift}};

} // namespace

const char* detectorName(Detector detector)
{
    return nameOfValue(kDetectorNames, detector, "?");
}

bool parseDetector(const std::string& name, Detector& detector)
{
    return parseNamedValue(kDetectorNames, name, detector);
}

const char* matcherName(Matcher matcher)
{
    return nameOfValue(kMatcherNames, matcher, "?");
}

bool parseMatcher(const std::string& name, Matcher& matcher)
{
    return parseNamedValue(kMatcherNames, name, matcher);
}

const char* descriptorName(Descriptor descriptor)
{
    return nameOfValue(kDescriptorNames, descriptor, "?");
}

bool parseDescriptor(const std::string& name, Descriptor& descriptor)
{
    return parseNamedValue(kDescriptorNames, name, descriptor);
}

std::vector<double> pyramidScales(cv::Size imageSize, int minLevelSize)
{
    std::vector<double> scales{1.0};
    // 1, 2/3, 1/2, 1/3, 1/4, 1/6, ...: two interleaved octave ladders, 1/2^k and (2/3)/2^k.
    for (int level = 1;; ++level) {
        const double octave = std::ldexp(1.0, -(level / 2));
        const double scale = (level % 2 == 1) ? octave * 2.0 / 3.0 : octave;
        const int width = cvRound(imageSize.width * scale);
        const int height = cvRound(imageSize.height * scale);
        if (std::min(width, height) < minLevelSize) break;
        scales.push_back(scale);
    }
    return scales;
}

Features detectAndDescribe(const cv::Mat& image, const FrontEndParams& params)
{
    checkParams(params);
    if (image.empty() || image.depth() != CV_8U)
        throw std::invalid_argument("front end: expected a non-empty 8-bit image");

    cv::Mat gray;
    if (image.channels() == 1)
        gray = image;
    else if (image.channels() == 3)
        cv::cvtColor(image, gray, cv::COLOR_BGR2GRAY);
    else if (image.channels() == 4)
        cv::cvtColor(image, gray, cv::COLOR_BGRA2GRAY);
    else
        throw std::invalid_argument("front end: expected a 1-, 3- or 4-channel image");
    if (params.detector == Detector::Sift) return detectSift(gray, params);

    // One level of ORB, used as a descriptor extractor only: the keypoints come from FAST on our
    // own pyramid, each level described on its own image.
    const cv::Ptr<cv::ORB> orb =
        cv::ORB::create(500, 1.2f, 1, params.border, 0, 2, cv::ORB::HARRIS_SCORE, kPatchSize);

    Features features;
    features.descriptor = params.descriptor;
    const bool rotated = params.descriptor == Descriptor::RotatedBrief;
    const std::vector<double> scales = pyramidScales(gray.size(), params.minLevelSize);
    features.levels = static_cast<int>(scales.size());

    for (int level = 0; level < features.levels; ++level) {
        cv::Mat levelImage;
        if (level == 0) {
            levelImage = gray;
        } else {
            const cv::Size size(cvRound(gray.cols * scales[level]),
                                cvRound(gray.rows * scales[level]));
            cv::resize(gray, levelImage, size, 0, 0, cv::INTER_AREA);
        }

        std::vector<cv::KeyPoint> corners;
        cv::FAST(levelImage, corners, params.fastThreshold, params.nonmaxSuppression,
                 cv::FastFeatureDetector::TYPE_9_16);
        features.cornersDetected += static_cast<int>(corners.size());

        // Keep the corners whose patches fit, as ORB's own border filter would.
        const cv::Rect inside(params.border, params.border, levelImage.cols - 2 * params.border,
                              levelImage.rows - 2 * params.border);
        std::vector<cv::KeyPoint> keypoints;
        keypoints.reserve(corners.size());
        for (cv::KeyPoint kp : corners) {
            if (!inside.contains(kp.pt)) continue;
            kp.octave = 0; // ORB picks the level of its own (one-level) pyramid from this
            kp.size = static_cast<float>(kPatchSize);
            kp.angle = rotated
                           ? intensityCentroidAngle(levelImage, cvRound(kp.pt.x), cvRound(kp.pt.y))
                           : 0.0f;
            keypoints.push_back(kp);
        }
        if (keypoints.empty()) continue;

        cv::Mat descriptors;
        if (params.descriptor == Descriptor::Patch)
            describePatches(levelImage, keypoints, descriptors);
        else
            orb->compute(levelImage, keypoints, descriptors);
        if (keypoints.empty()) continue;

        // Back to level-0 pixel coordinates (pixel centres at integers on every level).
        const double sx = double(gray.cols) / levelImage.cols;
        const double sy = double(gray.rows) / levelImage.rows;
        for (cv::KeyPoint& kp : keypoints) {
            kp.pt.x = static_cast<float>((kp.pt.x + 0.5) * sx - 0.5);
            kp.pt.y = static_cast<float>((kp.pt.y + 0.5) * sy - 0.5);
            kp.size = static_cast<float>(kPatchSize / scales[level]);
            kp.octave = level;
        }
        features.keypoints.insert(features.keypoints.end(), keypoints.begin(), keypoints.end());
        features.descriptors.push_back(descriptors);
    }
    if (params.matcher == Matcher::Grid) keepStrongestPerCell(gray.size(), features);
    return features;
}

Matches matchFeatures(const Features& features1, const Features& features2,
                      const FrontEndParams& params)
{
    checkParams(params);
    Matches result;
    if (features1.descriptor != features2.descriptor)
        throw std::invalid_argument("front end: the two feature sets hold different descriptors");
    if (features1.keypoints.empty() || features2.keypoints.empty()) return result;

    std::vector<cv::DMatch> matches;
    if (features1.descriptor == Descriptor::Sift) {
        // SIFT: the nearest of two neighbours, when clearly nearer than the second.
        matches = ratioTestMatches(features1, features2, params, result.candidates);
    } else {
        // Every corner of image 2 against the corners of image 1; the nearest wins, however far.
        if (params.matcher == Matcher::Flann) {
            matches = flannNearest(features1, features2);
        } else {
            cv::BFMatcher matcher(
                features1.descriptor == Descriptor::Patch ? cv::NORM_L2 : cv::NORM_HAMMING, false);
            matcher.match(features2.descriptors, features1.descriptors, matches);
        }
        result.candidates = static_cast<int>(matches.size());
    }
    result.ratioTestPassed = static_cast<int>(matches.size());

    // The best fraction by distance (stable, so that ties keep the order of the corners).
    std::stable_sort(matches.begin(), matches.end(), [](const cv::DMatch& a, const cv::DMatch& b) {
        return a.distance < b.distance;
    });
    const size_t keep = std::min(
        matches.size(),
        static_cast<size_t>(std::ceil(params.keepFraction * double(matches.size()) - 1e-9)));
    matches.resize(keep);

    // Random order with a fixed seed (Fisher-Yates on cv::RNG, identical on every platform).
    cv::RNG rng(params.shuffleSeed);
    for (size_t i = matches.size(); i > 1; --i) {
        const size_t j = static_cast<size_t>(rng.uniform(0, static_cast<int>(i)));
        std::swap(matches[i - 1], matches[j]);
    }

    result.points1.reserve(keep);
    result.points2.reserve(keep);
    result.distances.reserve(keep);
    for (const cv::DMatch& m : matches) {
        result.points1.push_back(features1.keypoints[m.trainIdx].pt);
        result.points2.push_back(features2.keypoints[m.queryIdx].pt);
        result.distances.push_back(m.distance);
        result.maxDistance = std::max(result.maxDistance, m.distance);
    }
    return result;
}

} // namespace essential_samples
