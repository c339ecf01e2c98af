#!/usr/bin/python3
"""ISO 6336-1:2006 clause 9 (Method B) mesh stiffness of the thesis gear pair, by hand.

Run:  /usr/bin/python3 reference/scripts/ch07_iso6336.py   -> iso6336_c_gamma_alpha_MN_per_m
z1 = z2 = 50, x1 = x2 = 0, alpha_n = 20 deg, h_fP / m_n = 3.75 / 3 = 1.25, b = 20 mm,
eps_alpha = AE / pb of the thesis gear, line load 4000 N / 20 mm = 200 N/mm (>= 100:
no load correction). q' = C1 + C2/z1 + C3/z2, c'_th = 1/q', C_M = 0.8, C_R = 1,
C_B = [1 + 0.5 (1.2 - h_fP/m_n)] [1 - 0.02 (20 - alpha_n)], c' = c'_th C_M C_R C_B,
c_gamma_alpha = c' (0.75 eps_alpha + 0.25) [N/(mm um)], times b [mm] -> N/um = MN/m.
"""
import math

m, z, alpha = 3e-3, 50, math.radians(20.0)
r, ra = m * z / 2, m * z / 2 + 3e-3
rb = r * math.cos(alpha)
eps = 2 * (math.sqrt(ra ** 2 - rb ** 2) - rb * math.tan(alpha)) / (math.pi * m * math.cos(alpha))
q = 0.04723 + 0.15551 / z + 0.25791 / z
C_B = (1 + 0.5 * (1.2 - 1.25)) * (1 - 0.02 * (20 - 20))
c_single = (1 / q) * 0.8 * 1.0 * C_B
print("iso6336_c_gamma_alpha_MN_per_m %.12g" % (c_single * (0.75 * eps + 0.25) * 20))
