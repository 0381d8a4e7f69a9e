#!/usr/bin/env python3
"""How far the asymptotic Weyl-van der Pol form of a point source over an impedance plane is from
the exact form (docs/physics/absorbing-roads.md), independently of rollnoise: the exact field by
scipy's adaptive quadrature of the complex image line, the asymptotic one with scipy's Faddeeva
function. Time dependence e^{+i omega t}, admittance beta = rho0 c0 / Z_s. Prints, per kR2, the
largest level difference |20 lg |G_WvdP| / |G_exact|| over the admittances and geometries below.

    /usr/bin/python3 tools/diagnostics/weyl_van_der_pol_check.py
"""
import numpy as np
from scipy.integrate import quad
from scipy.special import wofz


def exact(k, r, z, zs, beta):
    height = z + zs
    r1, r2 = np.hypot(r, z - zs), np.hypot(r, height)

    def line(t, part):
        s = t / k
        radius = np.sqrt(complex(r * r + height * height - s * s, -2 * height * s))
        value = np.exp(-beta * t - 1j * k * radius) / (k * radius)
        return value.real if part == 0 else value.imag

    kr2 = k * r2
    breaks = sorted({b for b in (kr2, 1 / abs(beta), 10 / abs(beta), kr2 + k * height, max(kr2 - k * height, 0.0))
                     if 0 < b < kr2 + 60})
    integral = sum(quad(line, 0, kr2 + 60, args=(part,), points=breaks, limit=2000, epsabs=1e-13)[0] * unit
                   for part, unit in ((0, 1), (1, 1j)))
    return (np.exp(-1j * k * r1) / (4 * np.pi * r1) + np.exp(-1j * k * r2) / (4 * np.pi * r2)
            - k * beta / (2 * np.pi) * integral)


def weyl_van_der_pol(k, r, z, zs, beta):
    # The textbook form is written for e^{-i omega t}: evaluate it there (beta conjugated) and
    # conjugate back. Q = R_p + (1 - R_p) F(w), F(w) = 1 + i sqrt(pi) w W(w), W the Faddeeva function.
    b = np.conj(beta)
    height = z + zs
    r1, r2 = np.hypot(r, z - zs), np.hypot(r, height)
    cos_theta = height / r2
    rp = (cos_theta - b) / (cos_theta + b)
    w = np.sqrt(1j * k * r2 / 2) * (cos_theta + b)
    q = rp + (1 - rp) * (1 + 1j * np.sqrt(np.pi) * w * wofz(w))
    return np.conj(np.exp(1j * k * r1) / (4 * np.pi * r1) + q * np.exp(1j * k * r2) / (4 * np.pi * r2))


admittances = [0.3 + 0.4j, 0.5 - 0.2j, 0.05 - 0.8j, 2 + 1.5j, 0.0146 - 0.0059j, 0.002 + 0.0226j, 0.1 + 0.1j]
geometries = [(0.2, 0.1, 0.002), (7.5, 1.2, 0.05), (0.5, 0.01, 0.002), (1.0, 0.3, 0.2), (0.05, 0.01, 0.002),
              (3.0, 0.5, 0.5)]  # (r, z, z_s), m
print("kR2  largest |dL| (dB) over", len(admittances) * len(geometries), "cases")
for kr2 in (0.3, 1, 3, 10, 30, 100, 300, 1000, 3000):
    worst = 0.0
    for beta in admittances:
        for r, z, zs in geometries:
            k = kr2 / np.hypot(r, z + zs)
            worst = max(worst, abs(20 * np.log10(abs(weyl_van_der_pol(k, r, z, zs, beta)) / abs(exact(k, r, z, zs, beta)))))
    print(f"{kr2:6g}  {worst:.3f}")
