// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// Real roots of a polynomial of degree <= 10 counted on an interval: Horner's rule and the Sturm
// sequence, for the five-point solver's d(z) (nister_five_point.cpp).

#ifndef OPENCV_ESSENTIAL_SOLVERS_STURM_SEQUENCE_HPP
#define OPENCV_ESSENTIAL_SOLVERS_STURM_SEQUENCE_HPP

#include "simd_dispatch.hpp"

#include <algorithm>
#include <cmath>

namespace cv {
namespace essential {
namespace solvers {

/** c[0] + c[1] t + ... + c[n] t^n by Horner's rule. The five-point solver's d(z) is of degree 10
but for degenerate samples, so that degree takes the loop-free path (the same operations). T is
double, or a vector of doubles whose lanes are evaluated side by side (the solver's root lanes),
each lane by exactly the operations of the scalar evaluation; the coefficients C are of the same
type, or scalars shared by every lane (the Sturm members at split points in lanes). The leading one
enters as c[n] - 0, which is c[n] exactly (-0 included) and a broadcast for scalar coefficients. */
template <class C, class T> ESSENTIAL_INLINE_INTO_CLONES T polynomialValue(const C* c, int n, T t)
{
    T v = c[n] - T{};
    if (n == 10) {
#pragma GCC unroll 10
        for (int i = 9; i >= 0; --i)
            v = v * t + c[i];
        return v;
    }
#pragma GCC unroll 10
    for (int i = n - 1; i >= 0; --i)
        v = v * t + c[i];
    return v;
}

/** d(t) and d'(t) together by Horner's rule; T as for polynomialValue. */
template <class T>
ESSENTIAL_INLINE_INTO_CLONES void polynomialValueAndDerivative(const T* c, int n, T t, T& f, T& df)
{
    f = c[n];
    df = T{};
    if (n == 10) {
#pragma GCC unroll 10
        for (int i = 9; i >= 0; --i) {
            df = df * t + f;
            f = f * t + c[i];
        }
        return;
    }
#pragma GCC unroll 10
    for (int i = n - 1; i >= 0; --i) {
        df = df * t + f;
        f = f * t + c[i];
    }
}

/** The Sturm sequence of a polynomial of degree <= 10: p0 = d, p1 = d', p(k+1) = -(p(k-1) mod
p(k)), each scaled to max |coefficient| = 1 (a positive factor keeps the signs). The sequence
stops early at a remainder that is zero to rounding (the last member is then gcd(d, d'), and the
count of sign changes still counts the distinct roots).

The members are evaluated by the recurrence the division leaves, p(k-1) = q(k) p(k) - s(k+1)
p(k+1) with the quotient q(k) (linear unless the degree drops by more than one) and s(k+1) the
scale of the remainder, from the last two members up: a few operations per member instead of a
Horner evaluation of each. Its signs agree with those of the members evaluated one by one on the
polynomials of the solver (test_sturm_sequence:
RecurrenceCountsLikeDirectEvaluationOnTheSolversPolynomials). */
class SturmSequence
{
public:
    /** Builds the sequence of d (degree n >= 1, d[n] != 0). Inlined into the five-point solver's
    frame preparation, so that it runs in that function's SIMD clone (simd_dispatch.hpp). */
    ESSENTIAL_INLINE_INTO_CLONES void build(const double* d, int n)
    {
        for (int i = 0; i <= n; ++i)
            p_[0][i] = d[i];
        degree_[0] = n;
        largest_[0] = maxAbs(p_[0], n);
        for (int i = 1; i <= n; ++i)
            p_[1][i - 1] = i * d[i];
        degree_[1] = n - 1;
        normalise(1, maxAbs(p_[1], n - 1));
        size_ = 2;
        while (degree_[size_ - 1] > 0) {
            const int k = size_ - 1;
            double r[11];
            const int m = degree_[k - 1], nk = degree_[k];
            const double zero = 1e-14 * largest_[k - 1];
            // The usual step (a remainder one degree below its divisor) by code of fixed length.
            const bool linear = m == nk + 1 && nk <= 9; // nk >= 1: the loop's condition
            if (linear && linearStepOfDegree<9>(nk, k, zero, r)) {
                ++size_;
                continue;
            }
            if (!linear) {
                for (int i = 0; i <= m; ++i)
                    r[i] = p_[k - 1][i];
                const double lead = p_[k][nk];
                for (int i = m; i >= nk; --i) {
                    const double f = r[i] / lead;
                    q_[k][i - nk] = f;
                    for (int j = 0; j < nk; ++j)
                        r[i - nk + j] -= f * p_[k][j];
                    r[i] = 0.0;
                }
                qDegree_[k] = m - nk;
            }
            int rd = nk - 1;
            while (rd >= 0 && std::abs(r[rd]) <= zero)
                --rd;
            if (rd < 0) break; // p(k) divides p(k-1): repeated roots
            for (int i = 0; i <= rd; ++i)
                p_[size_][i] = -r[i];
            degree_[size_] = rd;
            // p(k+1) = -r / s(k+1), so r = -s(k+1) p(k+1)
            s_[size_] = maxAbs(r, rd);
            normalise(size_, s_[size_]);
            ++size_;
        }
        allLinear_ = true;
        for (int k = 1; k + 1 < size_; ++k)
            allLinear_ = allLinear_ && qDegree_[k] == 1;
    }

    /** Sign changes of the sequence at t (zeros skipped). */
    ESSENTIAL_INLINE_INTO_CLONES int signChanges(double t) const
    {
        // The changes are counted from the last member up, as the recurrence produces them (the
        // count of a sequence read backwards is the same).
        const int last = size_ - 1;
        double above = polynomialValue(p_[last], degree_[last], t);
        double v = polynomialValue(p_[last - 1], degree_[last - 1], t);
        int changes = 0, previous = signOf(above);
        countSign(v, changes, previous);
        for (int k = last - 1; k >= 1; --k) {
            const double q =
                qDegree_[k] == 1 ? q_[k][0] + q_[k][1] * t : polynomialValue(q_[k], qDegree_[k], t);
            const double below = q * v - s_[k + 1] * above;
            countSign(below, changes, previous);
            above = v;
            v = below;
        }
        return changes;
    }

    /** signChanges at the lanes of t, side by side: Lanes is a vector of doubles (GCC's vector
    extension) and Mask the integer vector of its comparisons; counts[l] receives the count at t[l]
    for l < kLanes. Each lane takes exactly the operations of signChanges(t[l]) (IEEE operations
    lane by lane, the sign count by selects), so the counts are the same. Only for a sequence whose
    quotients are all linear (allLinear()), as the solver's nearly always are. */
    template <class Lanes, class Mask, int kLanes>
    ESSENTIAL_INLINE_INTO_CLONES void signChangesInLanes(Lanes t, int* counts) const
    {
        const int last = size_ - 1;
        Lanes above = polynomialValue(p_[last], degree_[last], t);
        Lanes v = polynomialValue(p_[last - 1], degree_[last - 1], t);
        const Mask zero{}, one = zero + 1, minusOne = zero - 1;
        // signOf lane by lane: 0 for a zero, -1 below it, +1 otherwise (a NaN too).
        auto signs = [&](Lanes x) {
            const Mask nonzero = x != 0.0;
            const Mask negative = x < 0.0;
            return negative ? minusOne : (nonzero ? one : zero);
        };
        Mask changes = zero, previous = signs(above);
        auto count = [&](Lanes x) {
            const Mask sign = signs(x);
            changes -= (sign != zero) & (previous != zero) & (sign != previous);
            previous = sign != zero ? sign : previous;
        };
        count(v);
        for (int k = last - 1; k >= 1; --k) {
            const Lanes below = (q_[k][0] + q_[k][1] * t) * v - s_[k + 1] * above;
            count(below);
            above = v;
            v = below;
        }
        for (int l = 0; l < kLanes; ++l)
            counts[l] = static_cast<int>(changes[l]);
    }

    /** Every quotient signChanges uses is linear. */
    bool allLinear() const { return allLinear_; }

    /** The same by evaluating every member on its own (for tests of the recurrence). */
    int signChangesDirect(double t) const
    {
        double v[11];
        for (int k = 0; k < size_; ++k)
            v[k] = polynomialValue(p_[k], degree_[k], t);
        return countSignChanges(v, size_);
    }

    /** Sign changes at +infinity (`positive`) or -infinity: the signs of the leading terms. */
    int signChangesAtInfinity(bool positive) const
    {
        int changes = 0;
        for (int k = 1; k < size_; ++k) {
            const bool a = (p_[k - 1][degree_[k - 1]] < 0.0) != (!positive && degree_[k - 1] % 2);
            const bool b = (p_[k][degree_[k]] < 0.0) != (!positive && degree_[k] % 2);
            changes += a != b;
        }
        return changes;
    }

private:
    /** One step of build() where p(k-1) has degree NK + 1 and p(k) degree NK (the quotient is
    linear), every loop of a length known at compile time: the same operations in the same order as
    the general step, so the same bits. r receives the remainder. Returns false, p(k + 1) not
    written, when the remainder's leading coefficient is zero to rounding (`zero`): the general step
    then seeks its degree. */
    template <int NK> ESSENTIAL_INLINE_INTO_CLONES bool linearStep(int k, double zero, double* r)
    {
        const double* divisor = p_[k];
        for (int i = 0; i <= NK + 1; ++i)
            r[i] = p_[k - 1][i];
        const double lead = divisor[NK];
        for (int i = NK + 1; i >= NK; --i) {
            const double f = r[i] / lead;
            q_[k][i - NK] = f;
            for (int j = 0; j < NK; ++j)
                r[i - NK + j] -= f * divisor[j];
            r[i] = 0.0;
        }
        qDegree_[k] = 1;
        if (!(std::abs(r[NK - 1]) > zero)) return false;
        double* next = p_[k + 1];
        double m = 0.0;
        for (int i = 0; i < NK; ++i) {
            next[i] = -r[i];
            m = std::max(m, std::abs(r[i]));
        }
        degree_[k + 1] = NK - 1;
        s_[k + 1] = m;
        largest_[k + 1] = m;
        if (m > 0.0) {
            const double scale = 1.0 / m;
            for (int i = 0; i < NK; ++i)
                next[i] *= scale;
            largest_[k + 1] = std::max(0.0, m * scale);
        }
        return true;
    }

    /** linearStep for a divisor of degree nk, 1 to NK (NK = 9: d has degree 10 at most). */
    template <int NK>
    ESSENTIAL_INLINE_INTO_CLONES bool linearStepOfDegree(int nk, int k, double zero, double* r)
    {
        if (nk == NK) return linearStep<NK>(k, zero, r);
        if constexpr (NK > 1)
            return linearStepOfDegree<NK - 1>(nk, k, zero, r);
        else
            return false;
    }

    /** Sign changes along v[0..n), zeros skipped (Sturm's theorem counts them so). */
    static int countSignChanges(const double* v, int n)
    {
        int changes = 0, previous = 0;
        for (int k = 0; k < n; ++k)
            countSign(v[k], changes, previous);
        return changes;
    }

    /** -1, 0 or +1; a NaN counts as positive, as x < 0 is false. */
    ESSENTIAL_INLINE_INTO_CLONES static int signOf(double x)
    {
        return x == 0.0 ? 0 : (x < 0.0 ? -1 : 1);
    }

    /** One member of a count of sign changes, branch-free (the signs along a sequence follow no
    pattern the branch predictor could learn): `previous` is the sign of the last nonzero member,
    0 before the first; a zero member leaves it unchanged. */
    ESSENTIAL_INLINE_INTO_CLONES static void countSign(double x, int& changes, int& previous)
    {
        const int sign = signOf(x);
        changes += sign * previous < 0;
        previous = sign != 0 ? sign : previous;
    }

    static double maxAbs(const double* c, int n)
    {
        double m = 0.0;
        for (int i = 0; i <= n; ++i)
            m = std::max(m, std::abs(c[i]));
        return m;
    }
    /** Scales member k by 1 / m, m = max |coefficient|, and records its new largest magnitude:
    m * (1 / m), the product the largest coefficient becomes (rounding is monotonic, so no other
    exceeds it); max(0, .) gives 0 where maxAbs would, should m be infinite. */
    ESSENTIAL_INLINE_INTO_CLONES void normalise(int k, double m)
    {
        largest_[k] = m;
        if (m > 0.0) {
            const double s = 1.0 / m;
            for (int i = 0; i <= degree_[k]; ++i)
                p_[k][i] *= s;
            largest_[k] = std::max(0.0, m * s);
        }
    }

    double p_[11][11];
    double q_[11][11];   //!< q_[k]: the quotient of p(k-1) by p(k)
    double s_[11];       //!< s_[k]: the scale of the remainder that became p(k), k >= 2
    double largest_[11]; //!< max |coefficient| of p(k), kept so that a division need not seek it
    int degree_[11];
    int qDegree_[11];
    int size_ = 0;
    bool allLinear_ = false; //!< every quotient is linear: signChangesInLanes' condition
};

} // namespace solvers
} // namespace essential
} // namespace cv

#endif
