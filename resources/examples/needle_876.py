#!/usr/bin/env python3
"""Writes the 876-class eight-link needle mechanism (seed 001) at alpha = 0 and 35 degrees.

The derivation is in README.md ("The 876-class needle mechanism"). Every coordinate is computed
in 50-digit decimal arithmetic from the paper's dimensions and y_C = 175 mm, and stored as the
correctly rounded double, as generate.py does for the other examples. The sketch is the
needle's lowest position (the paper's phi_1 = phi_0): crank and coupler collinear and stretched,
the rocker EF horizontal.

Run from anywhere:  python3 resources/examples/needle_876.py
"""

from decimal import Decimal, getcontext

from generate import linkage_file, plain, write

getcontext().prec = 50
D = Decimal

# The paper's dimensions (mm) and our y_C (README.md says why 175).
OA, AB, BC, CD, DE, EF, EG = D(15), D(175), D(25), D(17), D(30), D(25), D(30)
X_OF, B_SLOT = D(18), D(20)
XC, YC = X_OF, D(175)
ALPHAS = (0, 35)


def pi():
    """pi to the working precision (Machin's formula)."""

    def arctan_inv(n):
        x, n2, total, k, sign = D(1) / n, n * n, D(0), 1, 1
        while True:
            term = x / k
            if term == 0 or abs(term) < D(10) ** -(getcontext().prec + 2):
                return total
            total += sign * term
            x /= n2
            k += 2
            sign = -sign

    return 4 * (4 * arctan_inv(D(5)) - arctan_inv(D(239)))


def sin_cos(x):
    """Taylor series; |x| < 1 here."""
    s, c, term, k = D(0), D(0), D(1), 0
    while True:
        if k % 2 == 0:
            c += term if k % 4 == 0 else -term
        else:
            s += term if k % 4 == 1 else -term
        k += 1
        term = term * x / k
        if abs(term) < D(10) ** -(getcontext().prec + 2):
            return s, c


def sketch():
    """The lowest position: returns the points and the derived numbers."""
    C = (XC, YC)
    OC = (XC * XC + YC * YC).sqrt()
    # Crank and coupler stretched (|OB| = OA + AB = 190): B on the circle of radius 190 about O
    # and of radius BC about C, on the side where the crank angle is near 90 degrees (x_B < 0).
    R = OA + AB
    m = (R * R - BC * BC + OC * OC) / (2 * OC)  # foot of B on O->C
    h = (R * R - m * m).sqrt()
    u = (XC / OC, YC / OC)
    B = (m * u[0] - h * u[1], m * u[1] + h * u[0])  # to the left of O->C
    A = (B[0] * OA / R, B[1] * OA / R)
    # The lever is straight: D on the far side of C from B (README.md: only then CF = 37.945).
    Dp = (C[0] - CD * (B[0] - C[0]) / BC, C[1] - CD * (B[1] - C[1]) / BC)
    # The rocker EF horizontal with E to the right of F, F straight below C (x_F = x_C):
    # E = (x_C + EF, y_F) at distance DE from D, below D.
    xE = XC + EF
    yE = Dp[1] - (DE * DE - (xE - Dp[0]) ** 2).sqrt()
    E = (xE, yE)
    F0 = (XC, yE)
    # The needle bar on the vertical x = x_C + b, below E (formula 13).
    xG = XC + B_SLOT
    G = (xG, yE - (EG * EG - (xG - xE) ** 2).sqrt())
    return {"A": A, "B": B, "C": C, "D": Dp, "E": E, "F0": F0, "G": G, "CF": YC - yE}


def pivot_F(s, alpha_deg):
    """Formula (8): F on the arc of radius EF about E at the lowest position."""
    if alpha_deg == 0:
        return s["F0"]
    sn, cs = sin_cos(D(alpha_deg) * pi() / 180)
    return (s["E"][0] - EF * cs, s["F0"][1] + EF * sn)


def mechanism(s, alpha_deg):
    r = {k: tuple(plain(float(v)) for v in p) for k, p in s.items() if k not in ("CF",)}
    F = tuple(plain(float(v)) for v in pivot_F(s, alpha_deg))
    H = (plain(float(XC + B_SLOT)), 0)
    pts = lambda **kw: {k: list(v) for k, v in kw.items()}  # noqa: E731
    return linkage_file(
        f"876-class needle mechanism (eight links), alpha = {alpha_deg} degrees",
        [
            {"name": "ground", "ground": True, "number": 1,
             "points": pts(O=(0, 0), C=r["C"], F=F),
             "slots": {"guide": [list(H), [H[0], 150]]}},
            {"name": "crank", "number": 2, "points": pts(O=(0, 0), A=r["A"])},
            {"name": "coupler", "number": 3, "points": pts(A=r["A"], B=r["B"])},
            {"name": "lever", "number": 4, "points": pts(B=r["B"], C=r["C"], D=r["D"])},
            {"name": "link", "number": 5, "points": pts(D=r["D"], E=r["E"])},
            {"name": "rocker", "number": 6, "points": pts(E=r["E"], F=F)},
            {"name": "rod", "number": 7, "points": pts(E=r["E"], G=r["G"])},
            {"name": "needlebar", "number": 8, "points": pts(G=r["G"])},
        ],
        [
            {"type": "pin", "a": "ground.O", "b": "crank.O"},
            {"type": "pin", "a": "crank.A", "b": "coupler.A"},
            {"type": "pin", "a": "coupler.B", "b": "lever.B"},
            {"type": "pin", "a": "lever.C", "b": "ground.C"},
            {"type": "pin", "a": "lever.D", "b": "link.D"},
            {"type": "pin", "a": "link.E", "b": "rocker.E"},
            {"type": "pin", "a": "rocker.F", "b": "ground.F"},
            {"type": "pin", "a": "rocker.E", "b": "rod.E"},
            {"type": "pin", "a": "rod.G", "b": "needlebar.G"},
            {"type": "slider", "a": "needlebar.G", "slot": "ground.guide"},
        ],
        {"joint": 0, "rpm": 1000, "direction": "ccw"},
        ["needlebar.G"])


def main():
    s = sketch()
    A = s["A"]
    # phi_0 from atan2 in floats: only printed, never stored.
    import math
    phi0 = math.degrees(math.atan2(float(A[1]), float(A[0])))
    print(f"needle-876: phi_0 = {phi0:.6f} deg, CF = {s['CF']:.12f} mm (paper: 90.6, 37.945)")
    for k in ("A", "B", "D", "E", "G"):
        print(f"  {k} = ({float(s[k][0])!r}, {float(s[k][1])!r})")
    for alpha in ALPHAS:
        F = pivot_F(s, alpha)
        write(f"needle-876-alpha-{alpha}.linkage.json", mechanism(s, alpha))
        print(f"needle-876-alpha-{alpha}: F = ({float(F[0])!r}, {float(F[1])!r})")


if __name__ == "__main__":
    main()
