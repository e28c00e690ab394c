// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.
// The signs of a correspondence's two depths under a pose and under its twisted pair, without
// triangulating: what every cheirality test needs (the sample check of
// solvers/sample_cheirality.hpp, the in-front score of scoring/in_front_score.hpp and the votes of
// pose/pose_recovery.cpp), each with its own parallax below which the signs are noise's.
#ifndef OPENCV_ESSENTIAL_GEOMETRY_DEPTH_SIGNS_HPP
#define OPENCV_ESSENTIAL_GEOMETRY_DEPTH_SIGNS_HPP

namespace cv {
namespace essential {
namespace geometry {

/** Five dot products of a correspondence under X2 = R X1 + t (t a unit vector): a = R q1 is the
ray of view 1 rotated into view 2, q2 the ray of view 2 (any scale; q1 and q2 usually (x, y, 1)).

The depths (lambda1, lambda2) of lambda2 q2 = lambda1 a + t, by least squares (exact for a
correspondence on the epipolar geometry), have the normal equations
    [ a.a  -a.q2 ] [lambda1]   [ -a.t ]
    [ -a.q2 q2.q2 ] [lambda2] = [ q2.t ]
whose determinant |a|^2 |q2|^2 - (a.q2)^2 = |q2 x a|^2 >= 0, so the depths have the signs of the
numerators of Cramer's rule, depth1() and depth2(). Negating t negates both numerators exactly
(floating-point negation and round-to-nearest are symmetric), so one evaluation decides (R, t)
and (R, -t). The twisted pair R' = (2 t t^T - I) R maps q1 to a' = 2 (a.t) t - a, with |a'| = |a|,
a'.t = a.t and a'.q2 = 2 (a.t)(q2.t) - a.q2 (twisted()): the same five numbers decide all four poses
of E = [t]x R. Everything is scalar and branch-free, so that loops over points vectorise. */
struct DepthProducts
{
    double aa; //!< a.a
    double qq; //!< q2.q2
    double qa; //!< q2.a
    double ta; //!< t.a
    double tq; //!< t.q2

    /** lambda1 times |q2 x a|^2 */
    double depth1() const { return qa * tq - qq * ta; }
    /** lambda2 times |q2 x a|^2 */
    double depth2() const { return aa * tq - qa * ta; }
    /** |q2 x a|^2 */
    double crossSquared() const { return qq * aa - qa * qa; }
    /** Whether the sine of the angle between the rays exceeds sqrt(minParallax2): below, a point
    that far away (or that near the epipole) has depth signs that image noise decides. */
    bool decided(double minParallax2) const { return crossSquared() > minParallax2 * aa * qq; }
    /** Whether the rays are not parallel (the depths exist). */
    bool solvable() const { return crossSquared() > 0.0; }
    /** The same products for the twisted pair's ray a' = 2 (t.a) t - a. */
    DepthProducts twisted() const { return {aa, qq, 2.0 * ta * tq - qa, ta, tq}; }
};

/** The products of the correspondence ((x1, y1, 1), (x2, y2, 1)) under the row-major rotation r and
the unit translation t. */
inline DepthProducts depthProducts(const double* r, const double* t, double x1, double y1,
                                   double x2, double y2)
{
    const double a0 = r[0] * x1 + r[1] * y1 + r[2];
    const double a1 = r[3] * x1 + r[4] * y1 + r[5];
    const double a2 = r[6] * x1 + r[7] * y1 + r[8];
    DepthProducts p;
    p.aa = a0 * a0 + a1 * a1 + a2 * a2;
    p.qq = x2 * x2 + y2 * y2 + 1.0;
    p.qa = x2 * a0 + y2 * a1 + a2;
    p.ta = t[0] * a0 + t[1] * a1 + t[2] * a2;
    p.tq = t[0] * x2 + t[1] * y2 + t[2];
    return p;
}

} // namespace geometry
} // namespace essential
} // namespace cv

#endif
