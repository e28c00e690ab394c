// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "frontend/sequence_io.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace essential_samples {

bool readSequence(const std::string& dir, cv::Matx33d& K, std::vector<Pose>& poses,
                  bool acceptShortCamera)
{
    std::ifstream kf(dir + "/camera.txt"), pf(dir + "/poses.txt");
    if (!kf || !pf) return false;
    for (int i = 0; i < 9; ++i)
        kf >> K.val[i];
    std::string line;
    while (std::getline(pf, line)) {
        std::istringstream ls(line);
        int k;
        Pose p;
        if (!(ls >> k)) continue;
        for (int i = 0; i < 9; ++i)
            ls >> p.R.val[i];
        for (int i = 0; i < 3; ++i)
            ls >> p.C[i];
        poses.push_back(p);
    }
    return acceptShortCamera ? kf.good() || kf.eof() : static_cast<bool>(kf);
}

std::string framePath(const std::string& dir, int k)
{
    char name[32];
    std::snprintf(name, sizeof(name), "/%03d.jpg", k);
    return dir + name;
}

cv::Matx33d relativeRotation(const Pose& a, const Pose& b)
{
    return b.R * a.R.t();
}

cv::Vec3d relativeTranslation(const Pose& a, const Pose& b)
{
    return -(b.R * (b.C - a.C));
}

cv::Matx33d crossMatrix(const cv::Vec3d& t)
{
    return cv::Matx33d(0, -t[2], t[1], t[2], 0, -t[0], -t[1], t[0], 0);
}

cv::Matx33d trueEssential(const Pose& a, const Pose& b)
{
    return crossMatrix(relativeTranslation(a, b)) * relativeRotation(a, b);
}

cv::Matx33d trueFundamental(const cv::Matx33d& K, const Pose& a, const Pose& b)
{
    const cv::Matx33d Kinv = K.inv();
    return Kinv.t() * trueEssential(a, b) * Kinv;
}

double sampsonPx(const cv::Matx33d& F, const cv::Point2f& p1, const cv::Point2f& p2)
{
    const cv::Vec3d x1(p1.x, p1.y, 1.0), x2(p2.x, p2.y, 1.0);
    const cv::Vec3d Fx1 = F * x1, Ftx2 = F.t() * x2;
    const double d = Fx1[0] * Fx1[0] + Fx1[1] * Fx1[1] + Ftx2[0] * Ftx2[0] + Ftx2[1] * Ftx2[1];
    return d > 0 ? std::abs(x2.dot(Fx1)) / std::sqrt(d) : HUGE_VAL;
}

} // namespace essential_samples
