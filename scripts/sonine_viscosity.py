#!/usr/bin/env python3
"""The dilute shear viscosity of hard disks in successive Sonine approximations (docs/kinetic-theory.md,
"Shear viscosity"): the bracket integrals of the 2D linearised Boltzmann collision operator, computed by
quadrature, and eta^(K) / eta^(1) = A_00 (A^-1)_00 for the trial functions
psi_p(C) = C_x C_y L_p^(2)(C^2 / 2), p < K (units m = kT = sigma = n = 1).

Why it is exact up to the quadrature: the Maxwellian pair weight is exp(-G^2 - g^2 / 4) with the centre
of mass velocity G and the relative velocity g; a hard-disk collision reflects g about the contact normal
n, at angle phi from g with impact parameter b = sin(phi) (db = cos(phi) dphi). The integrand is a
polynomial in G (Gauss-Hermite is exact), an even polynomial in |g| times g^2 (Gauss-Hermite on the full
line), a trigonometric polynomial in g's direction (the trapezoidal rule is exact) and a smooth function
of phi (Gauss-Legendre). Check: A_00 = 2 sqrt(pi) in these units, which gives the first approximation
eta^(1) = kT b_0^2 / A_00 = (1 / (2 sigma)) sqrt(m kT / pi) (b_0 = n kT / m).

Usage: sonine_viscosity.py [--check KINETIC_THEORY_HPP]: prints the ratios; with --check, also verifies
the second approximation is 1.0200 (exactly 51/50 up to the quadrature) and that the constant
kViscositySonineFactor in the header is the converged ratio to its four decimals (exit 1 otherwise).
Needs numpy (Debian's python3-numpy)."""
import re
import sys

import numpy as np
from numpy.polynomial.hermite import hermgauss
from numpy.polynomial.legendre import leggauss
from math import comb, factorial


def laguerre2(p, x):
    """The generalised Laguerre polynomial L_p^(2)(x) = sum_i (-1)^i C(p + 2, p - i) x^i / i!."""
    return sum((-1) ** i * comb(p + 2, p - i) * x**i / factorial(i) for i in range(p + 1))


def brackets(k, n_g=14, n_s=16, n_theta=40, n_phi=40):
    """The k x k matrix of bracket integrals [psi_p, psi_q]."""
    xg, wg = hermgauss(n_g)
    xs, ws = hermgauss(n_s)
    radius, w_radius = 2 * xs, 0.5 * ws * 8 * xs**2  # integral of r^2 e^(-r^2/4) dr, half the full line
    theta = np.arange(n_theta) * 2 * np.pi / n_theta
    xp, wp = leggauss(n_phi)
    phi = xp * np.pi / 2
    w_phi = wp * np.pi / 2 * np.cos(phi)
    r, th, ph = np.meshgrid(radius, theta, phi, indexing="ij")
    weight = w_radius[:, None, None] * (2 * np.pi / n_theta) * w_phi[None, None, :]
    gx, gy = r * np.cos(th), r * np.sin(th)
    nx, ny = np.cos(th + ph), np.sin(th + ph)
    gn = gx * nx + gy * ny
    hx, hy = gx - 2 * gn * nx, gy - 2 * gn * ny  # g after the collision

    def psi(cx, cy, p):
        return cx * cy * laguerre2(p, (cx * cx + cy * cy) / 2)

    a = np.zeros((k, k))
    for x, wx in zip(xg, wg):
        for y, wy in zip(xg, wg):
            d = [psi(x + hx / 2, y + hy / 2, p) + psi(x - hx / 2, y - hy / 2, p)
                 - psi(x + gx / 2, y + gy / 2, p) - psi(x - gx / 2, y - gy / 2, p) for p in range(k)]
            for p in range(k):
                for q in range(p, k):
                    v = wx * wy * np.sum(weight * d[p] * d[q])
                    a[p, q] += v
                    if q != p:
                        a[q, p] += v
    return a / 4 / (4 * np.pi**2)  # [A, B] = (1/4) integral f0 f0 g dA dB; f0 f0 = e^(...) / (2 pi)^2


def main(argv):
    a = brackets(6)
    ratios = [a[0, 0] * np.linalg.inv(a[:k, :k])[0, 0] for k in range(1, 7)]
    print("A_00 = %.12f (2 sqrt(pi) = %.12f)" % (a[0, 0], 2 * np.sqrt(np.pi)))
    for k, r in enumerate(ratios, 1):
        print("approximation %d: eta / eta^(1) = %.7f" % (k, r))
    if len(argv) == 3 and argv[1] == "--check":
        constant = float(re.search(r"kViscositySonineFactor = ([0-9.]+);", open(argv[2]).read()).group(1))
        ok = abs(a[0, 0] - 2 * np.sqrt(np.pi)) < 1e-10 and abs(ratios[1] - 1.02) < 1e-10
        ok = ok and abs(ratios[-1] - constant) < 5e-5 and ratios[-1] - ratios[-2] < 2e-5
        print("kViscositySonineFactor = %.4f: %s" % (constant, "agrees" if ok else "DISAGREES"))
        return 0 if ok else 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
