// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// Real scenes with ground-truth cameras, as scripts/fetch_real_pairs.sh lays them out (Strecha et
// al.'s fountain, Herz-Jesu, entry and castle sets; Middlebury's templeRing and dinoSparseRing):
// ROOT/<scene>/images/<file> and ROOT/<scene>/cameras.txt, whose lines after the '#' comments are
//   name width height fx fy cx cy r11 r12 r13 r21 r22 r23 r31 r32 r33 t1 t2 t3
// with x_cam = R X_world + t (world to camera) and pixel = (fx x/z + cx, fy y/z + cy), no skew, no
// distortion. Reading it, listing the scenes of a root, the relative pose of two views and the
// pairs a pose benchmark takes from a scene. Header-only, OpenCV only; a malformed file throws
// std::runtime_error naming the file, the line and what is wrong (essential_samples::runCli
// prints it).

#ifndef OPENCV_ESSENTIAL_BENCH_REAL_DATASET_HPP
#define OPENCV_ESSENTIAL_BENCH_REAL_DATASET_HPP

#include <opencv2/core.hpp>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace essential_bench {

/** One image of a real scene and its ground-truth camera: x_cam = R X_world + t, pixel = K x_cam
(after division by z). */
struct RealView
{
    std::string name;  //!< the file name without its extension, e.g. "0003"
    std::string image; //!< the image's path: <scene dir>/images/<file>
    int width = 0, height = 0;
    cv::Matx33d K, R;
    cv::Vec3d t;
};

/** A scene: its folder's name and its views in the order of cameras.txt. */
struct RealScene
{
    std::string name;
    std::vector<RealView> views;
};

namespace real_detail {

[[noreturn]] inline void fail(const std::string& where, const std::string& what)
{
    throw std::runtime_error("real scene: " + where + ": " + what);
}

/** The whole of `token` as a finite number, else fail. */
inline double number(const std::string& token, const std::string& where)
{
    errno = 0;
    char* end = nullptr;
    const double v = std::strtod(token.c_str(), &end);
    if (token.empty() || *end != '\0' || errno == ERANGE || !std::isfinite(v))
        fail(where, "'" + token + "' is not a finite number");
    return v;
}

} // namespace real_detail

/** Reads dir/cameras.txt (see the top of this file). Throws std::runtime_error on a missing or
malformed file: a line without exactly 19 fields, a field that is not a number, a size that is not a
positive whole number, fx or fy not positive, R not a rotation (|R^T R - I| > 1e-6 or det R < 0), a
name given twice, an image missing from dir/images, or fewer than two views. */
inline RealScene loadRealScene(const std::string& dir)
{
    namespace fs = std::filesystem;
    const std::string path = (fs::path(dir) / "cameras.txt").string();
    std::ifstream in(path);
    if (!in)
        real_detail::fail(path, "cannot be opened (lay the scene out with "
                                "scripts/fetch_real_pairs.sh)");
    RealScene scene;
    scene.name = fs::path(dir).lexically_normal().filename().string();
    if (scene.name.empty())
        scene.name = fs::path(dir).lexically_normal().parent_path().filename().string();
    std::set<std::string> seen;
    std::string line;
    for (int lineNo = 1; std::getline(in, line); ++lineNo) {
        const std::string where = path + ":" + std::to_string(lineNo);
        std::istringstream fields(line);
        std::vector<std::string> f;
        for (std::string token; fields >> token;)
            f.push_back(token);
        if (f.empty() || f[0][0] == '#') continue;
        if (f.size() != 19)
            real_detail::fail(where, std::to_string(f.size()) + " fields, expected 19 (name width "
                                                                "height fx fy cx cy R t)");
        double v[18];
        for (int i = 0; i < 18; ++i)
            v[i] = real_detail::number(f[i + 1], where);
        RealView view;
        if (v[0] < 1 || v[1] < 1 || v[0] != std::floor(v[0]) || v[1] != std::floor(v[1]) ||
            v[0] > 1e6 || v[1] > 1e6)
            real_detail::fail(where, "width and height must be positive whole numbers");
        view.width = static_cast<int>(v[0]);
        view.height = static_cast<int>(v[1]);
        if (v[2] <= 0 || v[3] <= 0) real_detail::fail(where, "fx and fy must be positive");
        view.K = cv::Matx33d(v[2], 0, v[4], 0, v[3], v[5], 0, 0, 1);
        for (int i = 0; i < 9; ++i)
            view.R.val[i] = v[6 + i];
        view.t = cv::Vec3d(v[15], v[16], v[17]);
        if (cv::norm(view.R.t() * view.R - cv::Matx33d::eye(), cv::NORM_INF) > 1e-6 ||
            cv::determinant(view.R) < 0)
            real_detail::fail(where, "R is not a rotation");
        if (!seen.insert(f[0]).second) real_detail::fail(where, "'" + f[0] + "' is listed twice");
        const fs::path image = fs::path(dir) / "images" / f[0];
        std::error_code error;
        if (!fs::is_regular_file(image, error))
            real_detail::fail(where, "no image " + image.string());
        view.name = fs::path(f[0]).stem().string();
        view.image = image.string();
        scene.views.push_back(view);
    }
    if (scene.views.size() < 2) real_detail::fail(path, "fewer than two views");
    return scene;
}

/** The folders directly in `root` that hold a cameras.txt, as full paths, sorted by name; empty
when root does not exist. */
inline std::vector<std::string> listRealScenes(const std::string& root)
{
    namespace fs = std::filesystem;
    std::vector<std::string> scenes;
    std::error_code error;
    for (fs::directory_iterator it(root, error), end; !error && it != end; it.increment(error)) {
        const fs::path dir = it->path();
        if (dir.filename().string().rfind('.', 0) == 0) continue; // .<scene>.partial
        if (fs::is_regular_file(dir / "cameras.txt", error)) scenes.push_back(dir.string());
    }
    std::sort(scenes.begin(), scenes.end());
    return scenes;
}

/** The root fetch_real_pairs.sh lays out by default: $XDG_CACHE_HOME/opencv_essential/real, or
$HOME/.cache/opencv_essential/real; "" when neither variable is set. */
inline std::string defaultRealRoot()
{
    const char* xdg = std::getenv("XDG_CACHE_HOME");
    if (xdg && *xdg) return std::string(xdg) + "/opencv_essential/real";
    const char* home = std::getenv("HOME");
    if (home && *home) return std::string(home) + "/.cache/opencv_essential/real";
    return "";
}

/** The centre of a view's camera in world coordinates, -R^T t. */
inline cv::Vec3d cameraCentre(const RealView& v)
{
    return -(v.R.t() * v.t);
}

/** The direction of a view's optical axis in world coordinates, R^T (0, 0, 1). */
inline cv::Vec3d opticalAxis(const RealView& v)
{
    return cv::Vec3d(v.R(2, 0), v.R(2, 1), v.R(2, 2));
}

/** The pose of b relative to a: x_b = R x_a + t for camera coordinates x_a, x_b, with t of unit
length (the scale is lost in an essential matrix); t is zero when the two centres coincide. */
inline void relativePose(const RealView& a, const RealView& b, cv::Matx33d& R, cv::Vec3d& t)
{
    R = b.R * a.R.t();
    t = b.t - R * a.t;
    const double n = cv::norm(t);
    t = n > 0 ? t * (1.0 / n) : cv::Vec3d();
}

/** The angle of a rotation, in degrees. */
inline double rotationAngleDeg(const cv::Matx33d& R)
{
    const double c = std::max(-1.0, std::min(1.0, (cv::trace(R) - 1.0) / 2.0));
    return std::acos(c) * 180.0 / CV_PI;
}

/** The pairs (i, j), i < j, of views of a scene that a pose benchmark takes, in order. "Overlap"
here is a proxy computed from the cameras alone (cameras.txt has no scene geometry): the optical
axes (opticalAxis) differ by at most maxAngleDeg. The baseline must not be negligible: the
distance between the centres is at least minBaselineRatio times the scene's typical step, the
median over its views of the distance to the nearest other centre, so that a view taken twice or a
rotation about a fixed centre (no translation direction to estimate) is left out whatever the
scene's units. The proxy sees neither occlusion nor cameras that face the same way at different
parts of a large scene: a caller should still skip a pair with too few matches. With the defaults,
the relative rotations of the laid-out scenes' pairs range from about 1 to about 60 degrees
(templeRing, where a quarter of the images are upside down, also has pairs near 180). */
inline std::vector<std::pair<int, int>>
overlappingPairs(const RealScene& scene, double maxAngleDeg = 60.0, double minBaselineRatio = 0.1)
{
    const int n = static_cast<int>(scene.views.size());
    std::vector<cv::Vec3d> centre(n), axis(n);
    for (int i = 0; i < n; ++i) {
        centre[i] = cameraCentre(scene.views[i]);
        axis[i] = opticalAxis(scene.views[i]);
    }
    std::vector<double> nearest;
    for (int i = 0; i < n; ++i) {
        double d = HUGE_VAL;
        for (int j = 0; j < n; ++j)
            if (j != i) d = std::min(d, cv::norm(centre[i] - centre[j]));
        nearest.push_back(d);
    }
    std::vector<std::pair<int, int>> pairs;
    if (n < 2) return pairs;
    std::nth_element(nearest.begin(), nearest.begin() + n / 2, nearest.end());
    const double step = nearest[n / 2];
    const double cosMax = std::cos(maxAngleDeg * CV_PI / 180.0);
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j)
            if (axis[i].dot(axis[j]) >= cosMax &&
                cv::norm(centre[j] - centre[i]) >= minBaselineRatio * step)
                pairs.emplace_back(i, j);
    return pairs;
}

} // namespace essential_bench

#endif // OPENCV_ESSENTIAL_BENCH_REAL_DATASET_HPP
