#!/usr/bin/env python3
"""The ring-sun mesh phase gamma_rs of a planet, from its teeth, by construction in the plane
(an independent check of lib/gearhb/tools/planetary_stiffness.hpp ring_sun_phase_from_teeth).

    planetary_ring_sun_phase.py Z_SUN Z_PLANET Z_RING MODULE PRESSURE_ANGLE_DEG [ADDENDUM]

prints gamma_rs in mesh cycles (the ring-planet mesh's stiffness wave lags the sun-planet mesh's
by gamma_rs; both waves start, theta = 0, when a new tooth pair enters the path of contact).

Construction, in the carrier frame (no formula of the library): the sun's centre O = (0, 0),
the planet's C = (0, a), a = (z_s + z_p) m / 2; the sun turns counter-clockwise, the planet
clockwise. The sun-planet line of action passes the pitch point (0, r_s) along the force on the
planet (-cos a, sin a); the ring-planet line the pitch point (0, r_r) along (-cos a, -sin a).
Its entry points: A_s where the sun-planet line cuts the planet's tip circle beyond the pitch
point (the driven planet's tip meets the sun's root), A_r where the ring-planet line cuts the
ring's tip circle between the planet's tangent point and the pitch point (the driving planet's
root meets the ring's tip); both by bisection on |P - centre| = tip radius. The planet's tooth j
has its centre line at the angle phi0 + 2 pi j / z_p (clockwise from the direction to the sun's
centre); the flank facing backwards (the sun pushes it) lies at phi_j - theta_b + inv(a(r)), the
forward flank (it pushes the ring) at phi_j + theta_b - inv(a(r)), theta_b = pi / (2 z_p) +
inv(alpha) (unshifted teeth), a(r) = acos(r_bp / r). A pair enters a mesh when such a flank
passes its entry point: phi0 from the entry point's polar angle about C, for each mesh; gamma_rs is
their difference in tooth pitches, mod 1.
"""
import math
import sys


def inv(a):
    return math.tan(a) - a


def bisect(f, lo, hi):
    flo = f(lo)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if (f(mid) > 0) == (flo > 0):
            lo, flo = mid, f(mid)
        else:
            hi = mid
    return 0.5 * (lo + hi)


def ring_sun_phase(zs, zp, zr, m, alpha_deg, ha=1.0):
    al = math.radians(alpha_deg)
    rs, rp, rr = zs * m / 2, zp * m / 2, zr * m / 2
    a = rs + rp
    rbp = rp * math.cos(al)
    rap, rar = rp + ha * m, rr - ha * m
    C = (0.0, a)
    # sun-planet line: P(d) = pitch - d u, u the force on the planet; d > 0 runs from the pitch
    # point away from the planet's tangent point (towards the planet's tip circle on this side)
    us = (-math.cos(al), math.sin(al))
    ps = (0.0, rs)
    Ps = lambda d: (ps[0] - d * us[0], ps[1] - d * us[1])
    d_s = bisect(lambda d: math.dist(Ps(d), C) - rap, 0.0, 3 * m)
    As = Ps(d_s)
    # ring-planet line: P(d) = pitch + d u, towards the planet's tangent point; the ring's tip circle
    ur = (-math.cos(al), -math.sin(al))
    pr = (0.0, rr)
    Pr = lambda d: (pr[0] + d * ur[0], pr[1] + d * ur[1])
    d_r = bisect(lambda d: math.hypot(*Pr(d)) - rar, 0.0, rp * math.sin(al))
    Ar = Pr(d_r)

    def polar(Q):   # radius and angle clockwise from the direction to the sun's centre (0, -1)
        x, y = Q[0] - C[0], Q[1] - C[1]
        return math.hypot(x, y), math.atan2(-x, -y)

    theta_b = math.pi / (2 * zp) + inv(al)
    r, phi = polar(As)
    phi0_s = phi + theta_b - inv(math.acos(rbp / r))
    r, phi = polar(Ar)
    phi0_r = phi - theta_b + inv(math.acos(rbp / r))
    g = (phi0_r - phi0_s) / (2 * math.pi / zp)
    return g - math.floor(g)


if __name__ == "__main__":
    args = [float(v) for v in sys.argv[1:]]
    if len(args) < 5:
        sys.exit(__doc__)
    print(f"{ring_sun_phase(int(args[0]), int(args[1]), int(args[2]), args[3], args[4], *(args[5:6])):.12f}")
