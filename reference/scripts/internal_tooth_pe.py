#!/usr/bin/env python3
"""The potential-energy compliances of one internal (ring) gear tooth, integrated over the radius by
composite Simpson (an independent implementation of lib/gearhb/gears/tooth/potential_energy.hpp
pe_internal_tooth_compliance, which integrates by Gauss-Legendre in the pressure angle).

    internal_tooth_pe.py        prints bending, shear, axial [m/N] and the load angle [rad] of the
                                ring of programs/gearhb_planetary/examples/gtf_star_five_planets_teeth.json
                                (z 98, m 4.5 mm, 25 deg, ha* 1, hf* 1.25, b 120 mm, E 206 GPa, nu 0.3,
                                plane strain) at three contact radii: the tip, the pitch circle, the
                                root side 1.1 m beyond the pitch circle.

The tooth (material outside the space, which is an external tooth's shape): half angle at radius r
psi(r) = pi / (2 z) - inv(alpha0) + inv(a), a = acos(rb / r); centre-line coordinate xi = r cos(psi),
half thickness y = r sin(psi), dxi/dr = cos(psi) - r sin(psi) tan(a) / r. Loaded at r_c along the
line of action, at alpha_m = a_c + psi_c to the normal of the centre line, towards the root.
From the contact to the root circle (xi_c .. xi_f):
  1/k_b = int [cos(alpha_m) (xi - xi_c) - sin(alpha_m) y_c]^2 / (E' (2y)^3 b / 12) dxi
  1/k_s = int 1.2 cos^2(alpha_m) / (G 2 y b) dxi,   1/k_a = int sin^2(alpha_m) / (E' 2 y b) dxi.
"""
import math


def inv(a):
    return math.tan(a) - a


def compliance(z, m, alpha0, ha, hf, b, E, nu, r_c, n=20000):
    r0 = z * m / 2
    rb, rf = r0 * math.cos(alpha0), r0 + hf * m
    Ep, G = E / (1 - nu * nu), E / (2 * (1 + nu))

    def psi(r):
        return math.pi / (2 * z) - inv(alpha0) + inv(math.acos(rb / r))

    a_c = math.acos(rb / r_c)
    p_c = psi(r_c)
    xi_c, y_c, am = r_c * math.cos(p_c), r_c * math.sin(p_c), a_c + p_c
    c, s = math.cos(am), math.sin(am)

    def parts(r):
        p, a = psi(r), math.acos(rb / r)
        xi, y = r * math.cos(p), r * math.sin(p)
        dxi = math.cos(p) - math.sin(p) * math.tan(a)
        M = c * (xi - xi_c) - s * y_c
        return (M * M / (Ep * (2 * y) ** 3 * b / 12) * dxi, 1.2 * c * c / (G * 2 * y * b) * dxi,
                s * s / (Ep * 2 * y * b) * dxi)

    h = (rf - r_c) / n
    tot = [0.0, 0.0, 0.0]
    for i in range(n + 1):
        w = 1 if i in (0, n) else (4 if i % 2 else 2)
        for k, v in enumerate(parts(r_c + i * h)):
            tot[k] += w * v
    return [t * h / 3 for t in tot] + [am]


if __name__ == "__main__":
    z, m, al = 98, 0.0045, math.radians(25)
    r0 = z * m / 2
    for r in (r0 - m, r0, r0 + 1.1 * m):
        kb, ks, ka, am = compliance(z, m, al, 1.0, 1.25, 0.12, 206e9, 0.3, r)
        print(f"r_c = {r:.6f} m: bending {kb:.10e}, shear {ks:.10e}, axial {ka:.10e} m/N, load angle {am:.12f} rad")
