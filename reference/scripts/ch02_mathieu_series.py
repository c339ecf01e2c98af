"""Independent values for reference/ch02_methods.json: the edges b1(q), a1(q) of the
first instability tongue of Mathieu's equation y'' + (a - 2q cos 2t) y = 0 at q = 0.1,
from the small-q series of Abramowitz & Stegun, Handbook of Mathematical Functions,
20.2.25 (terms to q^5; the first omitted term, 49 q^6/589824, is 8e-11 at q = 0.1).
Run: python3 reference/scripts/ch02_mathieu_series.py
"""
from fractions import Fraction as F

q = F(1, 10)
b1 = 1 - q - q**2 / 8 + q**3 / 64 - q**4 / 1536 - 11 * q**5 / 36864
a1 = 1 + q - q**2 / 8 - q**3 / 64 - q**4 / 1536 + 11 * q**5 / 36864
print("mathieu_b1_q0.1 = %.15f" % float(b1))
print("mathieu_a1_q0.1 = %.15f" % float(a1))
