// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.
//
// Consumer of the installed package: builds against <prefix>/include/opencv4 (opencv5 with OpenCV
// 5) and links libopencv_essential through find_package(opencv_essential CONFIG REQUIRED).

#include <opencv2/essential.hpp>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

int main()
{
    // A few points in front of two cameras related by a small rotation and a sideways step.
    const cv::Matx33d K(500, 0, 320, 0, 500, 240, 0, 0, 1);
    cv::Matx33d R;
    cv::Rodrigues(cv::Vec3d(0.02, -0.05, 0.01), R);
    const cv::Vec3d t(1.0, 0.1, 0.05);

    cv::RNG rng(12345);
    std::vector<cv::Point2d> p1, p2;
    for (int i = 0; i < 30; ++i) {
        const cv::Vec3d X(rng.uniform(-2.0, 2.0), rng.uniform(-1.5, 1.5), rng.uniform(4.0, 10.0));
        const cv::Vec3d X2 = R * X + t;
        const cv::Vec3d x1 = K * X, x2 = K * X2;
        p1.emplace_back(x1[0] / x1[2], x1[1] / x1[2]);
        p2.emplace_back(x2[0] / x2[2], x2[1] / x2[2]);
    }

    cv::essential::EssentialParams params;
    cv::essential::EssentialReport report;
    cv::Mat mask;
    const cv::Mat E = cv::essential::findEssentialMatIter(p1, p2, K, params, mask, &report);
    if (E.rows != 3 || E.cols != 3) {
        std::fprintf(stderr, "essential_consumer: E is %d x %d, expected 3 x 3\n", E.rows, E.cols);
        return 1;
    }

    const std::vector<std::string> solvers = cv::essential::listSolvers();
    if (std::find(solvers.begin(), solvers.end(), "gn") == solvers.end()) {
        std::fprintf(stderr, "essential_consumer: listSolvers() lacks \"gn\"\n");
        return 1;
    }

    std::printf("essential_consumer: E is 3 x 3, %d of %d inliers, %zu solvers\n",
                cv::countNonZero(mask), static_cast<int>(p1.size()), solvers.size());
    return 0;
}
