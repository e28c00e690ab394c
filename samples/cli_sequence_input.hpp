// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.
//
// The input of essential_sequence: the frames of a directory and their ground-truth poses.
// Frames: DIR/NNN.jpg, .jpeg or .png (the name a frame number, any number of digits), or the images
// DIR/rgb.txt lists (`timestamp path` per line, path relative to DIR or absolute: the TUM RGB-D
// layout), then
// numbered 0, 1, ... in the order of the list. Poses, one of three formats (told apart by the
// number of values per line, or named):
// - rail: `k r00 r01 .. r22 Cx Cy Cz`, frame number, world-to-camera rotation, camera centre;
// - tum:  `timestamp tx ty tz qx qy qz qw`, camera-to-world (the camera centre t and the unit
//         quaternion of the camera-to-world rotation); a frame gets the pose of the nearest
//         timestamp within 0.02 s (as TUM's associate.py), so the frames need DIR/rgb.txt;
// - kitti: 12 numbers per line, the 3 x 4 camera-to-world matrix [R | t] row by row; line i is
//         frame i.
// Header-only; nothing here is part of the library.

#ifndef ESSENTIAL_SAMPLES_CLI_SEQUENCE_INPUT_HPP
#define ESSENTIAL_SAMPLES_CLI_SEQUENCE_INPUT_HPP

#include "cli_common.hpp"
#include "frontend/sequence_io.hpp"

#include <opencv2/core.hpp>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace essential_samples {

/** A pose file's format. */
enum class PoseFormat { Auto, Rail, Tum, Kitti };

inline constexpr NamedValue<PoseFormat> kPoseFormatNames[] = {{"auto", PoseFormat::Auto},
                                                              {"rail", PoseFormat::Rail},
                                                              {"tum", PoseFormat::Tum},
                                                              {"kitti", PoseFormat::Kitti}};

inline bool parsePoseFormat(const std::string& name, PoseFormat& format)
{
    return parseNamedValue(kPoseFormatNames, name, format);
}

inline const char* poseFormatName(PoseFormat format)
{
    return nameOfValue(kPoseFormatNames, format, "auto");
}

/** The frames of a sequence: path by frame number, and the timestamp of each when DIR/rgb.txt
gave them. */
struct SequenceFrames
{
    std::map<int, std::string> paths;
    std::map<int, double> timestamps;
    bool fromList = false; //!< read from DIR/rgb.txt
};

inline bool fileExists(const std::string& path)
{
    return static_cast<bool>(std::ifstream(path));
}

/** The frames of `dir` (see the top of this file). Fails when the directory cannot be read or
DIR/rgb.txt is malformed; an empty result is the caller's to report. */
inline SequenceFrames listFrames(const std::string& dir)
{
    SequenceFrames frames;
    const std::string list = dir + "/rgb.txt";
    if (fileExists(list)) {
        std::ifstream file(list);
        std::string line;
        int lineNumber = 0;
        while (std::getline(file, line)) {
            ++lineNumber;
            const size_t first = line.find_first_not_of(" \t\r");
            if (first == std::string::npos || line[first] == '#') continue;
            std::istringstream stream(line);
            std::string stamp, path, extra;
            double timestamp;
            if (!(stream >> stamp >> path) || (stream >> extra) || !parseDouble(stamp, timestamp))
                fail("malformed frame list '" + list + "': line " + std::to_string(lineNumber) +
                     " is not `timestamp path`");
            const int k = static_cast<int>(frames.paths.size());
            frames.paths[k] = path[0] == '/' ? path : dir + "/" + path;
            frames.timestamps[k] = timestamp;
        }
        frames.fromList = true;
        return frames;
    }
    for (const char* pattern : {"/*.jpg", "/*.jpeg", "/*.png"}) {
        std::vector<cv::String> files;
        try {
            cv::glob(dir + pattern, files, false);
        } catch (const cv::Exception&) {
            fail("cannot open directory '" + dir + "'");
        }
        for (const cv::String& file : files) {
            const size_t slash = file.find_last_of("/\\");
            const std::string name = file.substr(slash == std::string::npos ? 0 : slash + 1);
            const std::string stem = name.substr(0, name.find_last_of('.'));
            if (stem.empty() || stem.size() > 9 ||
                stem.find_first_not_of("0123456789") != std::string::npos)
                continue;
            const int k = std::stoi(stem);
            if (frames.paths.count(k))
                fail("frame " + std::to_string(k) + " twice in '" + dir + "': " + frames.paths[k] +
                     " and " + file);
            frames.paths[k] = file;
        }
    }
    return frames;
}

/** The rotation of the unit quaternion (x, y, z, w). */
inline cv::Matx33d quaternionRotation(double x, double y, double z, double w)
{
    return cv::Matx33d(1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w),
                       2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w),
                       2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y));
}

/** Whether R is a rotation to within 1e-3 (KITTI writes 6 to 9 significant digits). */
inline bool isRotation(const cv::Matx33d& R)
{
    return cv::norm(R.t() * R - cv::Matx33d::eye()) < 1e-3 && cv::determinant(R) > 0;
}

/** Reads the poses of `path` in `format` (Auto: by the values per line, 13 rail, 12 kitti, 8 tum)
for the frames; returns the pose of each frame that has one and sets `format` to the format read.
Fails (exit status 1) on a malformed file. */
inline std::map<int, Pose> readPoses(const std::string& path, PoseFormat& format,
                                     const SequenceFrames& frames)
{
    std::ifstream file(path);
    if (!file) fail("cannot open poses '" + path + "'");
    const std::string malformed = "malformed poses '" + path + "'";
    const std::vector<std::vector<double>> rows = readNumberRows(file, malformed);
    if (rows.empty()) fail(malformed + ": no pose in it");
    if (format == PoseFormat::Auto) {
        const size_t values = rows.front().size();
        if (values == 13)
            format = PoseFormat::Rail;
        else if (values == 12)
            format = PoseFormat::Kitti;
        else if (values == 8)
            format = PoseFormat::Tum;
        else
            fail(malformed + ": " + std::to_string(values) +
                 " values per line; expected 13 (rail), 12 (kitti) or 8 (tum)");
    }
    std::map<int, Pose> poses;
    if (format == PoseFormat::Rail) {
        for (const std::vector<double>& row : rows) {
            if (row.size() != 13 || row[0] < 0 || row[0] != std::floor(row[0]))
                fail(malformed + ": expected `k r00 .. r22 Cx Cy Cz` (13 numbers) per line");
            Pose pose;
            for (int i = 0; i < 9; ++i)
                pose.R.val[i] = row[1 + i];
            pose.C = cv::Vec3d(row[10], row[11], row[12]);
            poses[static_cast<int>(row[0])] = pose;
        }
    } else if (format == PoseFormat::Kitti) {
        for (size_t k = 0; k < rows.size(); ++k) {
            const std::vector<double>& row = rows[k];
            if (row.size() != 12)
                fail(malformed + ": expected 12 numbers (3 x 4 camera-to-world) per line");
            const cv::Matx33d Rcw(row[0], row[1], row[2], row[4], row[5], row[6], row[8], row[9],
                                  row[10]);
            if (!isRotation(Rcw))
                fail(malformed + ": the 3 x 3 part of line " + std::to_string(k + 1) +
                     " is not a rotation");
            poses[static_cast<int>(k)] = Pose{Rcw.t(), cv::Vec3d(row[3], row[7], row[11])};
        }
    } else {
        if (!frames.fromList)
            fail("TUM poses '" + path +
                 "' are matched to frames by timestamp: the directory needs rgb.txt "
                 "(`timestamp path` per frame)");
        std::map<double, Pose> byTime;
        for (const std::vector<double>& row : rows) {
            if (row.size() != 8) fail(malformed + ": expected `timestamp tx ty tz qx qy qz qw`");
            const double norm =
                std::sqrt(row[4] * row[4] + row[5] * row[5] + row[6] * row[6] + row[7] * row[7]);
            if (std::abs(norm - 1.0) > 1e-3)
                fail(malformed + ": the quaternion at time " + cv::format("%.6f", row[0]) +
                     " is not a unit quaternion");
            const cv::Matx33d Rcw =
                quaternionRotation(row[4] / norm, row[5] / norm, row[6] / norm, row[7] / norm);
            byTime[row[0]] = Pose{Rcw.t(), cv::Vec3d(row[1], row[2], row[3])};
        }
        const double maxGap = 0.02; // seconds, as TUM's associate.py
        for (const auto& frame : frames.timestamps) {
            const double t = frame.second;
            auto after = byTime.lower_bound(t);
            auto best = byTime.end();
            if (after != byTime.end()) best = after;
            if (after != byTime.begin()) {
                auto before = std::prev(after);
                if (best == byTime.end() || t - before->first < best->first - t) best = before;
            }
            if (best != byTime.end() && std::abs(best->first - t) <= maxGap)
                poses[frame.first] = best->second;
        }
    }
    return poses;
}

} // namespace essential_samples

#endif
