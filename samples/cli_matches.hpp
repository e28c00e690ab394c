// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.
//
// Correspondences from any front end for essential_pair --matches FILE: CSV, one `x1,y1,x2,y2` per
// line (pixels; blank lines, lines starting with '#' and a header line `x1,y1,x2,y2` are skipped),
// or OpenCV FileStorage (.yml, .yaml, .json, .xml, optionally .gz) with two N x 2 matrices
// `points1` and `points2` (N x 1 two-channel matrices, as cv::FileStorage writes a
// std::vector<cv::Point2f>, too). Header-only; nothing here is part of the library.

#ifndef ESSENTIAL_SAMPLES_CLI_MATCHES_HPP
#define ESSENTIAL_SAMPLES_CLI_MATCHES_HPP

#include "cli_camera.hpp"
#include "cli_common.hpp"

#include <opencv2/core.hpp>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

namespace essential_samples {

/** The points of one image, from a FileStorage node: N x 2 (one channel) or N x 1 / 1 x N (two
channels), any numeric depth. Fails with `malformed` + reason otherwise. */
inline std::vector<cv::Point2f> readFileStoragePoints(const cv::FileStorage& fs, const char* key,
                                                      const std::string& malformed)
{
    const cv::FileNode node = fs[key];
    if (node.empty() || node.isNone()) fail(malformed + ": no '" + key + "' matrix (N x 2) in it");
    cv::Mat m;
    try {
        node >> m;
    } catch (const cv::Exception&) {
        m.release();
    }
    if (m.empty()) fail(malformed + ": '" + key + "' is not a matrix");
    if (m.channels() == 1 && m.cols == 2)
        m = m.reshape(2, m.rows);
    else if (m.channels() != 2 || (m.cols != 1 && m.rows != 1))
        fail(malformed + ": '" + key + "' must be N x 2 (or N x 1 with two channels), not " +
             std::to_string(m.rows) + " x " + std::to_string(m.cols) + " with " +
             std::to_string(m.channels()) + " channels");
    m = m.reshape(2, static_cast<int>(m.total()));
    cv::Mat points;
    m.convertTo(points, CV_32FC2);
    std::vector<cv::Point2f> out(points.begin<cv::Point2f>(), points.end<cv::Point2f>());
    for (const cv::Point2f& p : out)
        if (!std::isfinite(p.x) || !std::isfinite(p.y))
            fail(malformed + ": non-finite coordinate in '" + key + "'");
    return out;
}

/** Reads the correspondences of `path` (see the top of this file) into points1, points2. Fails
(exit status 1) with one line naming the file and the problem. */
inline void readMatchesFile(const std::string& path, std::vector<cv::Point2f>& points1,
                            std::vector<cv::Point2f>& points2)
{
    const std::string malformed = "malformed matches file '" + path + "'";
    points1.clear();
    points2.clear();
    if (isFileStoragePath(path)) {
        if (!std::ifstream(path)) fail("cannot open matches file '" + path + "'");
        cv::FileStorage fs;
        try {
            fs.open(path, cv::FileStorage::READ);
        } catch (const cv::Exception& e) {
            fail(malformed + ": " + e.err);
        }
        if (!fs.isOpened()) fail("cannot open matches file '" + path + "'");
        points1 = readFileStoragePoints(fs, "points1", malformed);
        points2 = readFileStoragePoints(fs, "points2", malformed);
        if (points1.size() != points2.size())
            fail(malformed + ": points1 has " + std::to_string(points1.size()) +
                 " points and points2 " + std::to_string(points2.size()));
        return;
    }

    std::ifstream file(path);
    if (!file) fail("cannot open matches file '" + path + "'");
    std::string line;
    int lineNumber = 0;
    bool first = true;
    while (std::getline(file, line)) {
        ++lineNumber;
        std::string compact;
        for (char c : line)
            if (c != ' ' && c != '\t' && c != '\r') compact += c;
        if (compact.empty() || compact[0] == '#') continue;
        if (first && compact == "x1,y1,x2,y2") { // a header line
            first = false;
            continue;
        }
        first = false;
        const std::vector<std::string> fields = split(compact, ',');
        double v[4];
        bool ok = fields.size() == 4;
        for (size_t i = 0; ok && i < 4; ++i)
            ok = parseDouble(fields[i], v[i]);
        if (!ok)
            fail(malformed + ": line " + std::to_string(lineNumber) +
                 " is not `x1,y1,x2,y2` (four numbers)");
        points1.emplace_back(static_cast<float>(v[0]), static_cast<float>(v[1]));
        points2.emplace_back(static_cast<float>(v[2]), static_cast<float>(v[3]));
    }
}

} // namespace essential_samples

#endif
