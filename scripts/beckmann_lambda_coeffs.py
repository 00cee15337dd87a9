#!/usr/bin/env python3
"""Prints the piecewise polynomials of baker/models/beckmann_lambda.cpp (python3-mpmath).

psi(x) = 1/sqrt(pi) - x erfcx(x) on [0, 6] in 24 pieces of width 1/4; on piece i the polynomial
in z = 8 x - (2 i + 1), z in [-1, 1], of degree 11 interpolating psi at the 12 Chebyshev nodes
(50 significant digits, then rounded to double). Prints the worst relative error of the double
evaluation (as BeckmannPsi's) at 20,000 random points and the piece ends on stderr."""
import random
import sys

import mpmath as mp

mp.mp.dps = 50
WIDTH, PIECES, TERMS = 0.25, 24, 12


def psi(x):
    x = mp.mpf(x)
    return 1 / mp.sqrt(mp.pi) - x * mp.exp(x * x) * mp.erfc(x)


def piece(i):
    c, h = (i + mp.mpf(1) / 2) * WIDTH, mp.mpf(WIDTH) / 2
    nodes = [mp.cos(mp.pi * (k + mp.mpf(1) / 2) / TERMS) for k in range(TERMS)]
    a = mp.matrix([[z**j for j in range(TERMS)] for z in nodes])
    coef = mp.lu_solve(a, mp.matrix([psi(c + h * z) for z in nodes]))
    return [float(coef[j]) for j in range(TERMS)]


def evaluate(pieces, x):
    """As BeckmannPsi evaluates it (Estrin's scheme, the same operations in the same order)."""
    i = min(int(x * 4), PIECES - 1)
    z, c = 8 * x - (2 * i + 1), pieces[i]
    z2 = z * z
    z4 = z2 * z2
    p = [c[k] + c[k + 1] * z for k in range(0, TERMS, 2)]
    q0, q1, q2 = p[0] + p[1] * z2, p[2] + p[3] * z2, p[4] + p[5] * z2
    return q0 + (q1 + q2 * z4) * z4


def main():
    pieces = [piece(i) for i in range(PIECES)]
    random.seed(1)
    xs = [random.uniform(0, PIECES * WIDTH) for _ in range(20000)]
    xs += [i * WIDTH for i in range(PIECES + 1)]
    worst = max(float(abs(evaluate(pieces, x) / psi(x) - 1)) for x in xs)
    print(f"worst relative error {worst:.3g}", file=sys.stderr)
    for p in pieces:
        print("    {" + ", ".join(repr(v) for v in p) + "},")


if __name__ == "__main__":
    main()
