#!/usr/bin/env python3
"""Expected CCD polynomial coefficients, expanded symbolically from their DEFINITIONS.

Independent of the C++ builders: every polynomial is written here as the geometric quantity
it stands for (spec section 4) and expanded by sympy in exact rational arithmetic; only the
reference's t^3 quintic coefficient is evaluated from the spec's a..q formula, since that one
is defined by its formula.

Inputs are dyadic rationals (k / 2^m), so they are exact doubles and the C++ side sees the very
same numbers. Output, one record per pair, all numbers as round-trip decimal doubles:
  PP x1 d1 r1 x2 d2 r2            then 2 'poly' lines: position, approach
  PE x1 d1 rv x2 d2 x3 d3 re      then 4 'poly' lines: quartic, alpha>0, alpha<1, exact
                                  quintic, and 'reft3 <value>' (the reference's t^3 coefficient)
  PH x1 d1 r p m                  then 2 'poly' lines: distance, approach
(vectors are two numbers). A poly line is 'poly <n> c_{n-1} ... c_0', highest power first,
leading coefficients below 1e-12 in magnitude dropped, as the reference does.

usage: ccd_symbolic.py OUTPUT_FILE
"""
import random
import sys
from fractions import Fraction

import sympy as sp

t = sp.symbols('t')
SEED = 20240611


def dyadic(rng, lo, hi, bits):
    return sp.Rational(rng.randint(lo, hi), 2 ** bits)


def vec(rng, lo, hi, bits):
    return sp.Matrix([dyadic(rng, lo, hi, bits), dyadic(rng, lo, hi, bits)])


def num(x):
    """Exact rational -> correctly rounded double -> round-trip decimal string."""
    x = sp.Rational(x)
    return repr(float(Fraction(int(x.p), int(x.q))))


# The reference drops leading coefficients below 1e-12 in magnitude (not only exact zeros;
# see kNegligibleLeadingCoefficient in ccd.h for the evidence).
NEGLIGIBLE_LEADING = sp.Rational(1, 10 ** 12)


def coeffs(expr):
    """Coefficients highest first, negligible leading ones dropped (empty for 0)."""
    expr = sp.expand(expr)
    if expr == 0:
        return []
    c = sp.Poly(expr, t).all_coeffs()
    while c and abs(c[0]) < NEGLIGIBLE_LEADING:
        c.pop(0)
    return c


def poly_line(expr):
    c = coeffs(expr)
    return 'poly %d %s' % (len(c), ' '.join(num(v) for v in c))


def at(x, d):
    return x + t * d


def pp_case(x1, d1, r1, x2, d2, r2):
    x21 = at(x2, d2) - at(x1, d1)
    dist2 = x21.dot(x21)
    position = (r1 + r2) ** 2 - dist2
    approach = -sp.diff(dist2, t) / 2  # > 0 while the distance decreases
    head = 'PP ' + ' '.join(num(v) for v in (*x1, *d1, r1, *x2, *d2, r2))
    return [head, poly_line(position), poly_line(approach)]


def pe_case(x1, d1, rv, x2, d2, x3, d3, re):
    X1, X2, X3 = at(x1, d1), at(x2, d2), at(x3, d3)
    w = X1 - X2
    e = X3 - X2
    G = e.dot(e)
    A = w.dot(e)
    quartic = G * (rv + re) ** 2 - G * w.dot(w) + A ** 2
    above = A
    below = (X1 - X3).dot(X2 - X3)
    V = G * (d1 - d2) - A * (d3 - d2)
    N = G * (X2 - X1) + A * e
    quintic = V.dot(N)
    # The reference's t^3 coefficient, from the spec's notation (all at t = 0).
    e0, de, w0, dw = x3 - x2, d3 - d2, x1 - x2, d1 - d2
    a, b, c = e0.dot(e0), e0.dot(de), de.dot(de)
    d = (d2 - d1).dot(d2 - d1)
    ee = (d2 - d1).dot(x2 - x1)
    f, g, h = w0.dot(e0), w0.dot(de) + dw.dot(e0), dw.dot(de)
    i = de.dot(x2 - x1) + (d2 - d1).dot(e0)
    j = de.dot(d2 - d1)
    m = a * h + 2 * b * g + c * f
    n = c * g + 2 * b * h
    p, q = de.dot(e0), de.dot(de)
    reft3 = (-2 * g * h * p - 2 * f * g * q - g * g * q - 2 * a * c * d - 4 * b * b * d
             - 4 * b * c * ee - n * i - 2 * m * j)
    head = 'PE ' + ' '.join(num(v) for v in (*x1, *d1, rv, *x2, *d2, *x3, *d3, re))
    return [head, poly_line(quartic), poly_line(above), poly_line(below), poly_line(quintic),
            'reft3 ' + num(reft3)]


def ph_case(x1, d1, r, p, m):
    s = (p - at(x1, d1)).dot(m)
    distance = r ** 2 * m.dot(m) - s ** 2
    approach = -sp.diff(s ** 2, t) / 2
    head = 'PH ' + ' '.join(num(v) for v in (*x1, *d1, r, *p, *m))
    return [head, poly_line(distance), poly_line(approach)]


def main():
    rng = random.Random(SEED)
    pos = lambda: vec(rng, -512, 512, 7)   # coordinates in [-4, 4]
    disp = lambda: vec(rng, -256, 256, 8)  # displacements in [-1, 1]
    rad = lambda: dyadic(rng, 1, 64, 8)    # radii in (0, 0.25]
    zero = sp.Matrix([0, 0])
    lines = []
    for k in range(60):
        # Every tenth case has a static or rigidly co-moving pair: shorter lists.
        d1 = disp()
        d2 = d1 if k % 10 == 0 else disp()
        lines += pp_case(pos(), d1, rad(), pos(), d2, rad())
    for k in range(60):
        d1, d2, d3 = disp(), disp(), disp()
        if k % 10 == 0:
            d1 = d2 = d3 = zero
        elif k % 10 == 1:
            d2 = d3 = zero
        elif k % 10 == 2:
            d2 = d3 = d1
        lines += pe_case(pos(), d1, rad(), pos(), d2, pos(), d3, rad())
    for k in range(60):
        m = vec(rng, -512, 512, 8)
        d1 = zero if k % 10 == 0 else disp()
        lines += ph_case(pos(), d1, rad(), pos(), m)
    with open(sys.argv[1], 'w') as out:
        out.write('\n'.join(lines) + '\n')


if __name__ == '__main__':
    main()
