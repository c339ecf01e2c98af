#!/usr/bin/env python3
"""The ring-sun mesh phase gamma_rs of a planet, from its teeth, by construction in the plane
(an independent check of lib/gearhb/tools/planetary_stiffness.hpp ring_sun_phase_from_teeth).

    planetary_ring_sun_phase.py Z_SUN Z_PLANET Z_RING MODULE PRESSURE_ANGLE_DEG [ADDENDUM]

prints gamma_rs in mesh cycles (the ring-planet mesh's stiffness wave lags the sun-planet mesh's
by gamma_rs; both waves start, theta = 0, when a new tooth pair enters the path of contact), and
the ring-planet mesh's back-flank mirror phase psi / (2 pi) (ring_back_mirror below; the
library's ring_back_mirror_phase).

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


def ring_back_mirror(zs, zp, zr, m, alpha_deg, ha=1.0):
    """The ring-planet mesh's back-flank mirror phase psi / (2 pi) [cycles], by construction: the
    back line is the drive line mirrored about the line of centres (x = 0), its planet tangent
    point T' = C + r_bp (sin a, cos a). At the instant a drive pair enters at A_r (phi0 as in
    ring_sun_phase), the planet's backward-facing flank of a tooth is intersected with the back
    line (points of the involute by their polar angle, the crossing found by bisection on the
    signed distance to the line), d_b its distance from T'. A back pair at d_b from T' is the
    mirror of a drive pair at d_b from T, which the drive flanks reach psi - 0 later:
    psi p_b / (2 pi) = d_b - T1A (mod p_b), T1A = |A_r - T|."""
    al = math.radians(alpha_deg)
    rs, rp, rr = zs * m / 2, zp * m / 2, zr * m / 2
    a = rs + rp
    rbp = rp * math.cos(al)
    rap, rar = rp + ha * m, rr - ha * m
    pb = math.pi * m * math.cos(al)
    C = (0.0, a)
    ur = (-math.cos(al), -math.sin(al))
    pr = (0.0, rr)
    Pr = lambda d: (pr[0] + d * ur[0], pr[1] + d * ur[1])
    d_r = bisect(lambda d: math.hypot(*Pr(d)) - rar, 0.0, rp * math.sin(al))
    Ar = Pr(d_r)
    T = (C[0] - rbp * math.sin(al), C[1] + rbp * math.cos(al))
    T1A = math.dist(Ar, T)
    x, y = Ar[0] - C[0], Ar[1] - C[1]
    theta_b = math.pi / (2 * zp) + inv(al)
    phi0 = math.atan2(-x, -y) - theta_b + inv(math.acos(rbp / math.hypot(x, y)))
    # the drive path runs from T along -ur (towards the pitch point); the back path from T'
    # along its mirror v = (-cos a, sin a); n the back line's normal
    Tb = (C[0] + rbp * math.sin(al), C[1] + rbp * math.cos(al))
    v = (-math.cos(al), math.sin(al))
    n = (-v[1], v[0])

    def flank(j, r):   # the backward-facing flank of tooth j at radius r
        ang = phi0 + 2 * math.pi * j / zp - theta_b + inv(math.acos(rbp / r))
        return (C[0] - r * math.sin(ang), C[1] - r * math.cos(ang))

    for j in range(zp):
        f = lambda r: (flank(j, r)[0] - Tb[0]) * n[0] + (flank(j, r)[1] - Tb[1]) * n[1]
        lo, hi = rbp * (1 + 1e-12), rap
        if f(lo) * f(hi) < 0:
            P = flank(j, bisect(f, lo, hi))
            d_b = (P[0] - Tb[0]) * v[0] + (P[1] - Tb[1]) * v[1]
            if d_b > 0:   # on the side of the back path
                g = (d_b - T1A) / pb
                return g - math.floor(g)
    raise RuntimeError("no flank crosses the back line")


if __name__ == "__main__":
    args = [float(v) for v in sys.argv[1:]]
    if len(args) < 5:
        sys.exit(__doc__)
    z = (int(args[0]), int(args[1]), int(args[2]))
    print(f"gamma_rs {ring_sun_phase(*z, args[3], args[4], *(args[5:6])):.12f}")
    print(f"ring back mirror phase {ring_back_mirror(*z, args[3], args[4], *(args[5:6])):.12f} cycles")
