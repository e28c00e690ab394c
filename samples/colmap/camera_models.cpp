// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "colmap/camera_models.hpp"

#include "colmap/sqlite_connection.hpp"

#include <cmath>

namespace essential_colmap {

namespace {

struct ModelDefinition
{
    const char* name;
    int paramCount;
};

// COLMAP 3.8's model ids (its documentation's camera model list, in id order).
const ModelDefinition kModels[] = {
    {"SIMPLE_PINHOLE", 3},
    {"PINHOLE", 4},
    {"SIMPLE_RADIAL", 4},
    {"RADIAL", 5},
    {"OPENCV", 8},
    {"OPENCV_FISHEYE", 8},
    {"FULL_OPENCV", 12},
    {"FOV", 5},
    {"SIMPLE_RADIAL_FISHEYE", 4},
    {"RADIAL_FISHEYE", 5},
    {"THIN_PRISM_FISHEYE", 12},
};
const int kModelCount = static_cast<int>(sizeof(kModels) / sizeof(kModels[0]));

/** The distorted normalised point of `n` and the Jacobian of the distortion at `n`. */
cv::Point2d distort(const CameraIntrinsics& c, const cv::Point2d& n, cv::Matx22d* jacobian)
{
    const double u = n.x, v = n.y;
    const double uu = u * u, vv = v * v, uv = u * v, r2 = uu + vv;
    const double radial = 1.0 + c.k1 * r2 + c.k2 * r2 * r2;
    const cv::Point2d d(u * radial + 2.0 * c.p1 * uv + c.p2 * (r2 + 2.0 * uu),
                        v * radial + 2.0 * c.p2 * uv + c.p1 * (r2 + 2.0 * vv));
    if (jacobian) {
        // d radial / d r2, times d r2 / du = 2u (and 2v).
        const double dRadial = c.k1 + 2.0 * c.k2 * r2;
        const double radialU = 2.0 * u * dRadial, radialV = 2.0 * v * dRadial;
        *jacobian = cv::Matx22d(radial + u * radialU + 2.0 * c.p1 * v + 6.0 * c.p2 * u,
                                u * radialV + 2.0 * c.p1 * u + 2.0 * c.p2 * v,
                                v * radialU + 2.0 * c.p2 * v + 2.0 * c.p1 * u,
                                radial + v * radialV + 2.0 * c.p2 * u + 6.0 * c.p1 * v);
    }
    return d;
}

} // namespace

std::string cameraModelName(int modelId)
{
    if (modelId >= 0 && modelId < kModelCount) return kModels[modelId].name;
    return "unknown model id " + std::to_string(modelId);
}

int cameraModelParamCount(int modelId)
{
    return modelId >= 0 && modelId < kModelCount ? kModels[modelId].paramCount : -1;
}

CameraIntrinsics cameraIntrinsics(const ColmapCamera& camera)
{
    const std::string which =
        "camera " + std::to_string(camera.id) + " (" + cameraModelName(camera.modelId) + ")";
    if (camera.modelId < 0 || camera.modelId > 4)
        throw DatabaseError(which + ": model not supported (supported: SIMPLE_PINHOLE, PINHOLE, "
                                    "SIMPLE_RADIAL, RADIAL, OPENCV)");
    const std::vector<double>& p = camera.params;
    if (static_cast<int>(p.size()) != cameraModelParamCount(camera.modelId))
        throw DatabaseError(which + ": " + std::to_string(p.size()) +
                            " parameters, the model has " +
                            std::to_string(cameraModelParamCount(camera.modelId)));
    for (double value : p)
        if (!std::isfinite(value)) throw DatabaseError(which + ": a parameter is not finite");
    CameraIntrinsics c;
    switch (camera.modelId) {
    case 0: // f, cx, cy
        c.fx = c.fy = p[0], c.cx = p[1], c.cy = p[2];
        break;
    case 1: // fx, fy, cx, cy
        c.fx = p[0], c.fy = p[1], c.cx = p[2], c.cy = p[3];
        break;
    case 2: // f, cx, cy, k
        c.fx = c.fy = p[0], c.cx = p[1], c.cy = p[2], c.k1 = p[3];
        break;
    case 3: // f, cx, cy, k1, k2
        c.fx = c.fy = p[0], c.cx = p[1], c.cy = p[2], c.k1 = p[3], c.k2 = p[4];
        break;
    default: // 4, OPENCV: fx, fy, cx, cy, k1, k2, p1, p2
        c.fx = p[0], c.fy = p[1], c.cx = p[2], c.cy = p[3];
        c.k1 = p[4], c.k2 = p[5], c.p1 = p[6], c.p2 = p[7];
    }
    // The module refuses a camera matrix whose determinant is not a normal double (it calls it
    // singular): fx fy must neither underflow nor overflow, for these cameras and for the virtual
    // camera of a pair (verify_pairs.cpp: the mean of two cameras' focal lengths). 1e-100 to 1e100
    // pixels keeps every product of two far inside; no camera is anywhere near either end.
    const double minFocal = 1e-100, maxFocal = 1e100;
    for (double f : {c.fx, c.fy})
        if (!(f >= minFocal && f <= maxFocal))
            throw DatabaseError(which + ": focal length " + std::to_string(f) +
                                " is not in [1e-100, 1e100] pixels");
    return c;
}

cv::Point2d projectNormalised(const CameraIntrinsics& camera, const cv::Point2d& normalised)
{
    const cv::Point2d d = camera.distorted() ? distort(camera, normalised, nullptr) : normalised;
    return cv::Point2d(camera.fx * d.x + camera.cx, camera.fy * d.y + camera.cy);
}

bool undistortPixel(const CameraIntrinsics& camera, const cv::Point2d& pixel,
                    cv::Point2d& normalised)
{
    const cv::Point2d target((pixel.x - camera.cx) / camera.fx, (pixel.y - camera.cy) / camera.fy);
    normalised = target;
    if (!camera.distorted()) return std::isfinite(target.x) && std::isfinite(target.y);
    // Newton's method on distort(n) = target. The tolerance is 1e-12 normalised units (1e-9 px at a
    // focal length of 1000). Newton converged within 5 iterations at every pixel of a 16-pixel grid
    // over a 640 x 480 image, corners included, for the test cameras (SIMPLE_RADIAL k = -0.15,
    // RADIAL k1 = 0.3 k2 = -0.05, OPENCV k1 = -0.28 k2 = 0.07 p = +-0.01 at f = 500:
    // test_colmap_camera_models.cpp); the cap of 20 leaves room for stronger distortions.
    const int kMaxIterations = 20;
    const double kTolerance = 1e-12;
    for (int i = 0; i < kMaxIterations; ++i) {
        cv::Matx22d J;
        const cv::Point2d d = distort(camera, normalised, &J);
        const cv::Vec2d residual(d.x - target.x, d.y - target.y);
        const double det = J(0, 0) * J(1, 1) - J(0, 1) * J(1, 0);
        if (!(std::abs(det) > 1e-12)) return false;
        const cv::Vec2d step = J.inv() * residual;
        normalised.x -= step[0];
        normalised.y -= step[1];
        if (!std::isfinite(normalised.x) || !std::isfinite(normalised.y)) return false;
        if (std::abs(step[0]) < kTolerance && std::abs(step[1]) < kTolerance) {
            // Converged to a point whose Jacobian is not positive: a solution beyond the fold of
            // the distortion, not the one the camera images there.
            return det > 0;
        }
    }
    return false;
}

} // namespace essential_colmap
