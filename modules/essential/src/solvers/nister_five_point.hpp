// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// "nister": the five-point algorithm as implemented by Rosten et al. (Algorithm 4, section "Our
// implementation of the 5-point algorithm"): Gauss-Jordan null space, generated code for the
// 10 x 20 constraint matrix, Sturm-sequence bracketing with the paper's early abandonment, and a
// hybrid Newton-Raphson / bisection polish of at most 10 iterations. One addition to the paper:
// the sample is solved in one of three fixed rotated coordinate frames, chosen per sample, because
// the Gauss-Jordan basis cannot represent forward motion in camera coordinates and is
// ill-conditioned for some samples in any single frame (see NisterSettings::frames).

#ifndef OPENCV_ESSENTIAL_SOLVERS_NISTER_FIVE_POINT_HPP
#define OPENCV_ESSENTIAL_SOLVERS_NISTER_FIVE_POINT_HPP

#include "opencv2/essential/solver.hpp"

namespace cv {
namespace essential {
namespace solvers {

/** Bounds and tolerances of the five-point solver. The defaults were measured on 4000 noise-free
minimal problems of the paper's protocol (seeds 1000..4999 of test/synthetic_scene.hpp; "found"
means the true E is among the solutions to 1e-6 up to scale and sign); test_nister.cpp checks the
rates on other seeds. */
struct NisterSettings
{
    /** Roots of d(z) outside [-maxAbsRoot, maxAbsRoot] are abandoned (the paper's 100): bracketing
    starts on this interval and never looks outside it. Measured: found 99.78% with 100, 99.95%
    with no bound (the frames below already avoid most roots beyond it). */
    double maxAbsRoot = 100.0;
    /** A bracket still holding two or more roots is abandoned once it is narrower than this (the
    paper abandons near-repeated roots "quickly": at most log2(200 / 1e-4) = 21 splits). Measured on
    4000 problems: 1e-4 abandons 2 roots and loses no true E; 1e-3 loses 0.1% and 1e-2 1.4%. */
    double minBracketWidth = 1e-4;
    /** Once a bracket holds a single root it is narrowed on the sign of d alone (one Horner
    evaluation, cheaper than the Sturm sequence) until its width is at most this times
    max(1, |z|); the polish starts there. With 1e-2 the polish takes 3.5 iterations on average
    (about 6 narrowing steps before it); with 0.1, 4.5 (3 before), with 0.5, 5.5 and the cap of 10
    is hit more often. */
    double polishBracketWidth = 1e-2;
    /** Polishing iterations of the hybrid Newton-Raphson / bisection (the paper's 10). */
    int maxPolishIterations = 10;
    /** Polishing stops after a step smaller than this times max(1, |z|). A Newton step that small
    leaves an error of the order of its square; asking for 1e-13 instead made the polish fall back
    to bisection at the rounding floor of d and lose 5% of the roots to the iteration cap. */
    double polishTolerance = 1e-8;
    /** A polished root is kept only if |d(z)| is at most this times sum_i |d_i| |z|^i (the scale of
    the rounding error of evaluating d at z): otherwise d is "too far from zero" (the paper's
    discard). About 1 root in 4000 is discarded. */
    double maxRelativeResidual = 1e-9;
    /** A solution is returned only if ||2 E E^T E - trace(E E^T) E||_F <= this for ||E||_F =
    sqrt(2): E is (near) an essential matrix. Genuine roots measure below 3e-3 even when d(z) is
    ill-conditioned (OpenCV's solutions likewise); spurious roots of a badly conditioned sample 0.1
    and more. */
    double maxEssentialResidual = 1e-2;
    /** Coordinate frames to try, 0 to kMaxFrames (0: camera coordinates, as in the paper). This is
    not in the paper: the solver works in rotated coordinates q1' = R1 q1, q2' = R2 q2 (and returns
    E = R2^T E' R1) for two reasons.

    The Gauss-Jordan basis fixes E'(2,2) = -1, so a true E with E'(2,2) = 0 cannot be represented
    and one with a small E'(2,2) has |z| = |E'(2,1) / E'(2,2)| beyond maxAbsRoot. In camera
    coordinates that is the common case: E = [t]x R has a zero third row for forward motion and a
    near-zero diagonal for small rotations (measured: the true E is found for 0% of forward motions
    and 84.5% of the paper's general ones). In every frame here E'(2,2) = t . (R v x u) with
    v x u = (1, +-1, +-1) / sqrt(3), which is 0.58 |t| for a translation along any camera axis.

    And, in any one frame, the basis [A^T | -I] (max |A_ij| large: a nearly singular pivot block)
    or the leading 10 x 10 block of M (max |B_ij| of the reduced rows large) is ill-conditioned for
    some samples, which costs digits in d(z): one frame finds 96.7%. Frames are tried in turn until
    one has max |A_ij| max |B_ij| <= acceptableCondition and no real root beyond maxAbsRoot, else
    the best one tried is used (well conditioned first, then fewest roots abandoned). */
    int frames = 3;
    /** See `frames`. The trade is frames prepared per call against roots lost to an ill-conditioned
    frame, measured on 4000 noise-free problems of the paper's protocol (seeds 1000..4999; true E
    within 1e-6 / 1e-4 of a solution; share of solutions with an essential residual above 1e-6):
    200: 1.66 frames, 99.78% / 99.82%, 0.15%; 1000: 1.35, 99.80% / 99.88%, 0.26%; 3000: 1.22,
    99.75% / 99.90%, 0.33%; 10 000: 1.15, 99.70% / 99.92%, 0.52%; no bound: 1.03, 97.30% /
    98.85%. A frame is two thirds of a call's work, and inside a search a root within 1e-4 (a tenth
    of a pixel at a focal length of 1000) is as good as an exact one: local optimisation and the
    final refinement fit the model to all its inliers. 3000 keeps the 1e-6 rate at the declared
    successRate and the inexact share well inside test_nister's bound. Selecting on max |B_ij|
    alone does worse at every cost. */
    double acceptableCondition = 3000.0;
    /** Probability that one call on an outlier-free sample returns the true E: measured 0.9975 on
    the paper's protocol (test_nister at acceptableCondition 3000: 99.95% general and sideways,
    99.70% forward, of 2000 problems each; it asserts that this is not above the rate it measures).
    The engine divides its sample count by this. */
    double successRate = 0.997;
};

/** Rosten et al.'s five-point solver ("nister"): 0 to 10 essential matrices per five
correspondences, each scaled to Frobenius norm sqrt(2). All storage is fixed-size members and stack
arrays: solve() does not allocate. */
class NisterFivePointSolver : public EssentialSolver
{
public:
    /** Most coordinate frames NisterSettings::frames may ask for. */
    static constexpr int kMaxFrames = 3;

    explicit NisterFivePointSolver(const NisterSettings& settings = NisterSettings());
    int sampleSize() const override { return 5; }
    int maxSolutions() const override { return 10; }
    double successRate() const override { return settings_.successRate; }
    int solve(const Point2d* x1, const Point2d* x2, RNG& rng, Matx33d* solutions) override;

    /** What the last call of solve() did (for measurements and tests). */
    struct Diagnostics
    {
        int framesTried = 0;          //!< coordinate frames prepared (null space to Sturm sequence)
        int frame = -1;               //!< the frame used
        double condition = 0.0;       //!< max |A_ij| * max |B_ij| in that frame
        int rootsOutside = 0;         //!< real roots beyond maxAbsRoot in that frame (abandoned)
        int realRootsInRange = 0;     //!< distinct real roots of d(z) in [-maxAbsRoot, maxAbsRoot]
        int abandonedRepeated = 0;    //!< roots abandoned in brackets narrower than minBracketWidth
        int rejectedNotEssential = 0; //!< solutions discarded by maxEssentialResidual
        int rejectedResidual = 0;     //!< polished roots discarded for |d(z)| too far from zero
        int noSignChange = 0; //!< single-root brackets without a sign change of d (Sturm count off)
        int polishIterations = 0;    //!< polishing iterations summed over the roots
        int bracketEvaluations = 0;  //!< evaluations of d narrowing single-root brackets
        int sturmEvaluations = 0;    //!< evaluations of the whole Sturm sequence
        double polynomial[11] = {0}; //!< d(z), lowest power first, scaled to max |d_i| = 1
    };
    const Diagnostics& lastDiagnostics() const { return diagnostics_; }

    /** The rotations of coordinate frame f (q1' = R1 q1, q2' = R2 q2), for tests. */
    void frameRotations(int f, Matx33d& R1, Matx33d& R2) const
    {
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) {
                R1(i, j) = frames_[f][0][i][j];
                R2(i, j) = frames_[f][1][i][j];
            }
    }

private:
    NisterSettings settings_;
    int numFrames_ = 1;
    double frames_[kMaxFrames][2][3][3]; //!< per frame: R1 (view 1) and R2 (view 2)
    Diagnostics diagnostics_;
};

} // namespace solvers
} // namespace essential
} // namespace cv

#endif
