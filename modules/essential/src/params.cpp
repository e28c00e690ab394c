// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// The constructors of the settings and report structs, with the defaults that params.hpp documents
// field by field. They are out of line, not member initialisers, because OpenCV's Python generator
// (modules/python/src2/hdr_parser.py in OpenCV 4.6) reads `CV_PROP_RW int x = 5;` as a field named
// "x = 5", and makes cv2.essential.EssentialParams() only from a declared CV_WRAP constructor.

#include "opencv2/essential/params.hpp"

namespace cv {
namespace essential {

EssentialParams::EssentialParams()
    : solver("gn+nister"), method(RANSAC), engine(ENGINE_ADAPTIVE), timeBudgetMs(0),
      preemptiveHypotheses(0), preemptiveBlockSize(100), confidence(0.999), threshold(1.0),
      distance(DISTANCE_SAMPSON), maxIters(1000), sampleBudget(BUDGET_OPENCV_TIME),
      budgetLocalSamples(true), planeParallax(true), loIterations(5), loSampleSize(0),
      sampler(SAMPLING_UNIFORM), sprt(true), seed(0x6573736e7469616cULL), refine(true),
      recoverPose(true)
{
}

EssentialReport::EssentialReport()
    : success(false), E(Matx33d::zeros()), R(Matx33d::eye()), t(Vec3d(0, 0, 0)),
      poseRecovered(false), pointsInFront(0), rotationOnlyFraction(0), homographyFraction(0),
      degenerate(false), numPoints(0), inliers(0), iterations(0), hypothesesGenerated(0),
      hypothesesConverged(0), hypothesesScored(0), refineIterations(0), pointsScored(0),
      localOptimisations(0), localOptimisationsKept(0), sprtRejections(0), planeParallaxKept(false),
      timeSetupMs(0), timeSearchMs(0), timeRefineMs(0), timePoseMs(0), timeTotalMs(0)
{
}

} // namespace essential
} // namespace cv
