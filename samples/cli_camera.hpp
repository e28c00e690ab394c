// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.
//
// The camera of the command-line sample programs: "--camera fx,fy,cx,cy", "--distortion k1,k2,...",
// and camera files, either text (`fx fy cx cy [width height]` on one line, or the 3 x 3 matrix on
// three lines) or OpenCV FileStorage (.yml, .yaml, .json, .xml, optionally .gz) as written by
// cv::FileStorage after cv::calibrateCamera: `camera_matrix` and `distortion_coefficients` (the
// names of OpenCV's calibration sample), or `K` and `D`, and optionally `image_width` and
// `image_height`; or KITTI odometry's calib.txt (P0). Header-only; nothing here is part of the
// library.

#ifndef ESSENTIAL_SAMPLES_CLI_CAMERA_HPP
#define ESSENTIAL_SAMPLES_CLI_CAMERA_HPP

#include "cli_common.hpp"

#include <opencv2/core.hpp>

#include <cmath>
#include <fstream>
#include <istream>
#include <sstream>
#include <string>
#include <vector>

namespace essential_samples {

/** Intrinsics: the camera matrix, the distortion coefficients (empty: none) and, when the file
states it, the image size they belong to (empty otherwise). */
struct Camera
{
    cv::Matx33d K;
    cv::Mat distortion;
    cv::Size imageSize;
};

/** Fails (exit status 1) unless K is finite with fx, fy > 0 and last row 0 0 1. */
inline void checkCamera(const cv::Matx33d& K, const std::string& origin)
{
    for (int i = 0; i < 9; ++i)
        if (!std::isfinite(K.val[i])) fail("malformed camera (" + origin + "): non-finite value");
    if (!(K(0, 0) > 0.0) || !(K(1, 1) > 0.0))
        fail("malformed camera (" + origin + "): fx and fy must be positive");
    if (K(2, 0) != 0.0 || K(2, 1) != 0.0 || K(2, 2) != 1.0)
        fail("malformed camera (" + origin + "): the last row of the matrix must be 0 0 1");
}

/** Whether `count` distortion coefficients are a model cv::undistortPoints reads (4, 5, 8, 12 or
14: k1 k2 p1 p2 [k3 [k4 k5 k6 [s1 s2 s3 s4 [tx ty]]]]). */
inline bool isDistortionCount(int count)
{
    return count == 4 || count == 5 || count == 8 || count == 12 || count == 14;
}

/** "--camera fx,fy,cx,cy": fails with exit status 2 when malformed. */
inline cv::Matx33d parseCameraOption(const std::string& text)
{
    const std::vector<std::string> parts = split(text, ',');
    double v[4];
    if (parts.size() != 4)
        fail("malformed camera '" + text + "': expected --camera fx,fy,cx,cy (four numbers)", 2);
    for (int i = 0; i < 4; ++i)
        if (!parseDouble(parts[i], v[i]))
            fail("malformed camera '" + text + "': '" + parts[i] + "' is not a number", 2);
    const cv::Matx33d K(v[0], 0, v[2], 0, v[1], v[3], 0, 0, 1);
    checkCamera(K, "--camera " + text);
    return K;
}

/** "--distortion k1,k2,p1,p2[,k3...]": 4, 5, 8, 12 or 14 finite numbers as a 1 x n CV_64F row;
fails with exit status 2 otherwise. */
inline cv::Mat parseDistortionOption(const std::string& text)
{
    const std::vector<std::string> parts = split(text, ',');
    cv::Mat d(1, static_cast<int>(parts.size()), CV_64F);
    for (size_t i = 0; i < parts.size(); ++i)
        if (!parseDouble(parts[i], d.at<double>(static_cast<int>(i))))
            fail("--distortion: '" + parts[i] + "' is not a number", 2);
    if (!isDistortionCount(d.cols))
        fail("--distortion: " + std::to_string(d.cols) +
                 " coefficients; expected 4, 5, 8, 12 or 14 (k1,k2,p1,p2[,k3[,k4,k5,k6[,...]]])",
             2);
    return d;
}

/** Whether `path` names an OpenCV FileStorage file (by its extension, as cv::FileStorage reads
it). */
inline bool isFileStoragePath(std::string path)
{
    if (path.size() > 3 && path.compare(path.size() - 3, 3, ".gz") == 0)
        path.resize(path.size() - 3);
    for (const char* ext : {".yml", ".yaml", ".json", ".xml"}) {
        const std::string e(ext);
        if (path.size() > e.size() && path.compare(path.size() - e.size(), e.size(), e) == 0)
            return true;
    }
    return false;
}

/** The first of `names` that `fs` holds, or an empty node. */
inline cv::FileNode firstNode(const cv::FileStorage& fs, std::initializer_list<const char*> names)
{
    for (const char* name : names) {
        const cv::FileNode node = fs[name];
        if (!node.empty() && !node.isNone()) return node;
    }
    return cv::FileNode();
}

/** A numeric matrix of a FileStorage file as CV_64F; fails with `malformed` when the node is not
one. */
inline cv::Mat readFileStorageMatrix(const cv::FileNode& node, const std::string& malformed)
{
    cv::Mat m;
    try {
        node >> m;
    } catch (const cv::Exception&) {
        m.release();
    }
    if (m.empty() || m.channels() != 1) fail(malformed);
    m.convertTo(m, CV_64F);
    return m;
}

inline Camera readFileStorageCamera(const std::string& path)
{
    if (!std::ifstream(path)) fail("cannot open camera file '" + path + "'");
    cv::FileStorage fs;
    try {
        fs.open(path, cv::FileStorage::READ);
    } catch (const cv::Exception& e) {
        fail("malformed camera file '" + path + "': " + e.err);
    }
    if (!fs.isOpened()) fail("cannot open camera file '" + path + "'");
    const std::string malformed = "malformed camera file '" + path + "'";
    const cv::FileNode kNode =
        firstNode(fs, {"camera_matrix", "cameraMatrix", "K", "camera_matrix_1"});
    if (kNode.empty()) fail(malformed + ": no camera_matrix (or K) 3 x 3 matrix in it");
    const cv::Mat k = readFileStorageMatrix(kNode, malformed + ": camera_matrix is not a matrix");
    if (k.rows != 3 || k.cols != 3) fail(malformed + ": camera_matrix is not 3 x 3");
    Camera camera;
    camera.K = cv::Matx33d(k.ptr<double>());
    const cv::FileNode dNode =
        firstNode(fs, {"distortion_coefficients", "dist_coeffs", "distCoeffs", "D", "distortion"});
    if (!dNode.empty()) {
        cv::Mat d = readFileStorageMatrix(dNode, malformed + ": the distortion is not a matrix");
        if (std::min(d.rows, d.cols) != 1 || !isDistortionCount(static_cast<int>(d.total())))
            fail(malformed + ": " + std::to_string(d.total()) +
                 " distortion coefficients; expected 4, 5, 8, 12 or 14 in one row or column");
        for (size_t i = 0; i < d.total(); ++i)
            if (!std::isfinite(d.at<double>(static_cast<int>(i))))
                fail(malformed + ": non-finite distortion coefficient");
        camera.distortion = d.reshape(1, 1);
        if (cv::countNonZero(camera.distortion) == 0) camera.distortion.release();
    }
    const cv::FileNode width = fs["image_width"], height = fs["image_height"];
    if (!width.empty() && !height.empty() && width.isInt() && height.isInt() && int(width) > 0 &&
        int(height) > 0)
        camera.imageSize = cv::Size(int(width), int(height));
    checkCamera(camera.K, path);
    return camera;
}

/** KITTI odometry's calib.txt: lines `P0: p00 p01 .. p23` (the 3 x 4 projection matrices of the
cameras, row by row); the camera matrix is the left 3 x 3 block of P0, the left grey camera. */
inline Camera readKittiCalibration(std::istream& in, const std::string& path)
{
    const std::string malformed = "malformed camera file '" + path + "'";
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind("P0:", 0) != 0) continue;
        std::istringstream numbers(line.substr(3));
        const std::vector<std::vector<double>> rows = readNumberRows(numbers, malformed);
        if (rows.size() != 1 || rows[0].size() != 12)
            fail(malformed + ": P0 must have 12 numbers (a 3 x 4 matrix)");
        const std::vector<double>& p = rows[0];
        Camera camera;
        camera.K = cv::Matx33d(p[0], p[1], p[2], p[4], p[5], p[6], p[8], p[9], p[10]);
        checkCamera(camera.K, path);
        return camera;
    }
    fail(malformed + ": no line `P0: ...` (KITTI calib.txt)");
}

/** A camera file: FileStorage by extension (see the top of this file), KITTI's calib.txt (when it
starts with 'P'), otherwise text with `fx fy cx cy [width height]` on one line, or a 3 x 3 camera
matrix as three lines of three numbers (blank lines and lines starting with '#' ignored). Fails
(exit status 1) with one line naming the file. */
inline Camera readCameraFile(const std::string& path)
{
    if (isFileStoragePath(path)) return readFileStorageCamera(path);
    std::ifstream file(path);
    if (!file) fail("cannot open camera file '" + path + "'");
    if (file.peek() == 'P') return readKittiCalibration(file, path);
    const std::vector<std::vector<double>> rows =
        readNumberRows(file, "malformed camera file '" + path + "'");

    Camera camera;
    cv::Matx33d& K = camera.K;
    if (rows.size() == 1 && (rows[0].size() == 4 || rows[0].size() == 6)) {
        const std::vector<double>& r = rows[0];
        K = cv::Matx33d(r[0], 0, r[2], 0, r[1], r[3], 0, 0, 1);
        if (r.size() == 6) {
            if (r[4] < 1 || r[5] < 1 || r[4] != std::floor(r[4]) || r[5] != std::floor(r[5]))
                fail("malformed camera file '" + path +
                     "': width and height must be positive integers");
            camera.imageSize = cv::Size(static_cast<int>(r[4]), static_cast<int>(r[5]));
        }
    } else if (rows.size() == 3 && rows[0].size() == 3 && rows[1].size() == 3 &&
               rows[2].size() == 3) {
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                K(i, j) = rows[i][j];
    } else {
        fail("malformed camera file '" + path +
             "': expected one line `fx fy cx cy [width height]`, three lines of three numbers, "
             "or a .yml/.yaml/.json/.xml file with camera_matrix");
    }
    checkCamera(K, path);
    return camera;
}

} // namespace essential_samples

#endif
