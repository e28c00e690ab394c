#!/usr/bin/env python3
# This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
# See the LICENSE file at the top of the source tree.
"""Writes nister_coefficients.inc: straight-line C++ that fills the 10 x 20 matrix M of the
five-point solver "nister" (Rosten et al., "Our implementation of the 5-point algorithm").

The null space of the 5 x 9 epipolar constraint matrix is taken from its Gauss-Jordan form
[I | A] (A is 5 x 4): E = x X + y Y + z Z + W with the basis rows of [A^T | -I], so, with E
stored row-major,

    E[i] = A[i][0] x + A[i][1] y + A[i][2] z + A[i][3]    (i = 0..4)
    E[5] = -x,  E[6] = -y,  E[7] = -z,  E[8] = -1.

The ten cubic constraints det(E) = 0 and 2 E E^T E - trace(E E^T) E = 0 are polynomials in x, y, z
whose coefficients are polynomials in the twenty entries of A. This script expands them exactly
(integer arithmetic, no third-party module: python3 alone regenerates the file) and emits code for
them, using the structure of the basis: the last four entries of E are single monomials with
coefficient -1, so most products vanish or reduce to a sign.

The cost is kept low in two stages, both computed symbolically here:
  1. the coefficients of S = 2 E E^T - trace(E E^T) I (quadratic in the entries of A) become named
     temporaries, shared between rows;
  2. each entry of M is then a sum of products of two factors (entry of A or temporary), since the
     trace constraint is S E and the determinant is expanded along the first row of E.
The column order of M is the paper's monomial order
  [x^3, y^3, x^2y, xy^2, x^2z, x^2, y^2z, y^2, xyz, xy, xz^2, xz, x, yz^2, yz, y, z^3, z^2, z, 1];
row 0 is det(E) and rows 1..9 are the entries (0,0), (0,1), ..., (2,2) of S E.

Usage: generate_nister_coefficients.py [--output FILE]   (default: standard output)
The ctest entry nister_generated_code_is_current regenerates the file and compares it byte for
byte with the committed copy.
"""

import argparse
import math
import sys
from collections import defaultdict

# The paper's monomial order, as exponents (x, y, z).
MONOMIALS = [
    (3, 0, 0), (0, 3, 0), (2, 1, 0), (1, 2, 0), (2, 0, 1), (2, 0, 0), (0, 2, 1), (0, 2, 0),
    (1, 1, 1), (1, 1, 0), (1, 0, 2), (1, 0, 1), (1, 0, 0), (0, 1, 2), (0, 1, 1), (0, 1, 0),
    (0, 0, 3), (0, 0, 2), (0, 0, 1), (0, 0, 0),
]
MONOMIAL_NAMES = [
    "x^3", "y^3", "x^2y", "xy^2", "x^2z", "x^2", "y^2z", "y^2", "xyz", "xy", "xz^2", "xz", "x",
    "yz^2", "yz", "y", "z^3", "z^2", "z", "1",
]
VARIABLE_EXPONENTS = [(1, 0, 0), (0, 1, 0), (0, 0, 1), (0, 0, 0)]  # x, y, z, 1


# --- Coefficient expressions: polynomials in named atoms with integer coefficients. ------------
# An expression is a dict {tuple of atom names (sorted, with repetition): int}.


def expr_atom(name, coefficient=1):
    return {(name,): coefficient}


def expr_const(value):
    return {(): value} if value else {}


def expr_add(*exprs):
    out = defaultdict(int)
    for e in exprs:
        for term, c in e.items():
            out[term] += c
    return {t: c for t, c in out.items() if c}


def expr_scale(s, e):
    return {t: s * c for t, c in e.items() if s * c}


def expr_scale_down(e, d):
    return {t: c // d for t, c in e.items()}


def expr_mul(a, b):
    out = defaultdict(int)
    for ta, ca in a.items():
        for tb, cb in b.items():
            out[tuple(sorted(ta + tb))] += ca * cb
    return {t: c for t, c in out.items() if c}


# --- Polynomials in x, y, z whose coefficients are expressions. -------------------------------
# A polynomial is a dict {(ex, ey, ez): expression}.


def poly_add(*polys):
    out = {}
    for p in polys:
        for m, e in p.items():
            out[m] = expr_add(out.get(m, {}), e)
    return {m: e for m, e in out.items() if e}


def poly_scale(s, p):
    return {m: expr_scale(s, e) for m, e in p.items() if s}


def poly_mul(p, q):
    out = {}
    for mp, ep in p.items():
        for mq, eq in q.items():
            m = (mp[0] + mq[0], mp[1] + mq[1], mp[2] + mq[2])
            out[m] = expr_add(out.get(m, {}), expr_mul(ep, eq))
    return {m: e for m, e in out.items() if e}


def essential_entries():
    """E (row-major, 9 polynomials of degree 1) in the Gauss-Jordan null-space basis."""
    entries = []
    for i in range(5):
        entries.append({VARIABLE_EXPONENTS[k]: expr_atom("a%d%d" % (i, k)) for k in range(4)})
    for k in range(4):
        entries.append({VARIABLE_EXPONENTS[k]: expr_const(-1)})
    return [entries[3 * r:3 * r + 3] for r in range(3)]


# --- Code emission. -----------------------------------------------------------------------------


class Emitter:
    """Turns expressions into C++ statements, naming shared temporaries."""

    def __init__(self):
        self.lines = []
        self.temporaries = {}  # canonical expression -> name
        self.multiplications = 0
        self.additions = 0

    @staticmethod
    def key(e):
        return tuple(sorted(e.items()))

    def term_code(self, term, c, first):
        factors = list(term)
        magnitude = abs(c)
        if magnitude != 1 or not factors:
            factors = ["%d.0" % magnitude] + factors
        self.multiplications += len(factors) - 1
        body = " * ".join(factors)
        if first:
            return ("-" if c < 0 else "") + body
        self.additions += 1
        return (" - " if c < 0 else " + ") + body

    def expression_code(self, e):
        if not e:
            return "0.0"
        common = 0
        for c in e.values():
            common = math.gcd(common, c)
        if common > 1 and len(e) > 1:
            self.multiplications += 1
            return "%d.0 * (%s)" % (common, self.expression_code(expr_scale_down(e, common)))
        terms = sorted(e.items(), key=lambda tc: (len(tc[0]), tc[0]))
        # Start with a positive term where there is one (saves a negation).
        positive = [i for i, (_, c) in enumerate(terms) if c > 0]
        if positive:
            terms.insert(0, terms.pop(positive[0]))
        return "".join(self.term_code(t, c, i == 0) for i, (t, c) in enumerate(terms))

    def materialise(self, e):
        """Returns an expression equivalent to e that is one atom times +-1 (or a constant)."""
        if not e:
            return e
        if len(e) == 1:
            (term, c), = e.items()
            if not term or (len(term) == 1 and abs(c) == 1):
                return e
        k = self.key(e)
        if k in self.temporaries:
            return expr_atom(self.temporaries[k])
        negated = self.key(expr_scale(-1, e))
        if negated in self.temporaries:
            return expr_atom(self.temporaries[negated], -1)
        name = "t%d" % len(self.temporaries)
        self.temporaries[k] = name
        self.emit("const double %s = %s;" % (name, self.expression_code(e)))
        return expr_atom(name)

    def emit(self, statement):
        self.lines.extend(wrap(statement))


def wrap(statement, width=100, indent="    "):
    """Breaks a long statement before ' + ' / ' - ' so that every line fits in `width` columns."""
    lines = []
    current = indent + statement
    while len(current) > width:
        cut = max(current.rfind(" + ", 0, width), current.rfind(" - ", 0, width))
        if cut <= len(indent) + 8:
            break
        lines.append(current[:cut])
        current = indent + "    " + current[cut + 1:]
    lines.append(current)
    return lines


def generate():
    E = essential_entries()
    em = Emitter()
    for i in range(5):
        em.emit("const double %s;" % ", ".join("a%d%d = A[%d][%d]" % (i, k, i, k)
                                               for k in range(4)))

    # Stage 1: S = 2 E E^T - trace(E E^T) I, each coefficient a named temporary.
    P = [[None] * 3 for _ in range(3)]
    for i in range(3):
        for j in range(i, 3):
            P[i][j] = poly_add(*[poly_mul(E[i][k], E[j][k]) for k in range(3)])
            P[j][i] = P[i][j]
    trace = poly_add(P[0][0], P[1][1], P[2][2])
    S = [[None] * 3 for _ in range(3)]
    for i in range(3):
        for j in range(i, 3):
            s = poly_scale(2, P[i][j])
            if i == j:
                s = poly_add(s, poly_scale(-1, trace))
            s = {m: em.materialise(e) for m, e in sorted(s.items(), reverse=True)}
            S[i][j] = S[j][i] = s

    # Stage 2: the rows of M.
    rows = []
    cof0 = poly_add(poly_mul(E[1][1], E[2][2]), poly_scale(-1, poly_mul(E[1][2], E[2][1])))
    cof1 = poly_add(poly_mul(E[1][2], E[2][0]), poly_scale(-1, poly_mul(E[1][0], E[2][2])))
    cof2 = poly_add(poly_mul(E[1][0], E[2][1]), poly_scale(-1, poly_mul(E[1][1], E[2][0])))
    rows.append(poly_add(poly_mul(E[0][0], cof0), poly_mul(E[0][1], cof1),
                         poly_mul(E[0][2], cof2)))
    for i in range(3):
        for j in range(3):
            rows.append(poly_add(*[poly_mul(S[i][k], E[k][j]) for k in range(3)]))

    for r, row in enumerate(rows):
        assert all(sum(m) == 3 or m in MONOMIALS for m in row)
        for c, m in enumerate(MONOMIALS):
            code = em.expression_code(row.get(m, {}))
            em.emit("M[%d][%d] = %s; // %s" % (r, c, code, MONOMIAL_NAMES[c]))
    return em


HEADER = """\
// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

// GENERATED by generate_nister_coefficients.py (python3, no other module); do not edit by hand.
// Regenerate from the repository root with
//   python3 modules/essential/src/solvers/generate_nister_coefficients.py
//       --output modules/essential/src/solvers/nister_coefficients.inc
// (the ctest entry nister_generated_code_is_current fails when this file is out of date).
//
// nisterConstraintMatrix(A, M): the 10 x 20 matrix M of the ten cubic constraints det(E) = 0 and
// 2 E E^T E - trace(E E^T) E = 0 on E = x X + y Y + z Z + W, where the null-space basis X, Y, Z, W
// of the five epipolar constraints is the rows of [A^T | -I] (A: 5 x 4, from the Gauss-Jordan form
// [I | A] of the 5 x 9 constraint matrix). Columns: the monomials
//   x^3 y^3 x^2y xy^2 x^2z x^2 y^2z y^2 xyz xy xz^2 xz x yz^2 yz y z^3 z^2 z 1;
// rows: det(E), then the entries (0,0), (0,1), ..., (2,2) of the trace constraint.
// Cost: %(temps)d shared temporaries; %(mul)d multiplications and %(add)d additions in all.
// Inlined into the AVX2 clone of its caller (ESSENTIAL_INLINE_INTO_CLONES, simd_dispatch.hpp).

// clang-format off
ESSENTIAL_INLINE_INTO_CLONES void nisterConstraintMatrix(const double A[5][4], double M[10][20])
{
"""

FOOTER = """\
}
// clang-format on
"""


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--output", help="file to write (default: standard output)")
    args = parser.parse_args()
    em = generate()
    text = (HEADER % {"temps": len(em.temporaries), "mul": em.multiplications,
                      "add": em.additions}
            + "\n".join(em.lines) + "\n" + FOOTER)
    if args.output:
        with open(args.output, "w", encoding="utf-8", newline="\n") as f:
            f.write(text)
    else:
        sys.stdout.write(text)


if __name__ == "__main__":
    main()
