#!/usr/bin/env python3
"""Writes the example mechanism files of this directory (see README.md).

Sketch coordinates are solved to full double precision: each geometry is first solved with Newton
in Python floats (as the Wanzer homework script does), then polished with a few Newton steps in
50-digit decimal arithmetic and rounded once, so every stored number is the correctly rounded
double of the exact sketch. All the equations are polynomial or need only square roots, which the
decimal module has, so no trigonometry is needed at high precision.

Run from anywhere:  python3 resources/examples/generate.py
"""

import json
import os
from decimal import Decimal, getcontext

getcontext().prec = 50
HERE = os.path.dirname(os.path.abspath(__file__))


def sqrt(x):
    return x.sqrt() if isinstance(x, Decimal) else x ** 0.5


def plain(x):
    """Whole numbers as integers, so that 10.0 is written 10 as the program writes it."""
    return int(x) if float(x).is_integer() else x


def solve3(J, r):
    """Solves J x = r (3x3) by Cramer's rule, in the number type of the arguments."""

    def det(M):
        return (M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1])
                - M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0])
                + M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0]))

    d = det(J)
    out = []
    for k in range(3):
        M = [[r[i] if j == k else J[i][j] for j in range(3)] for i in range(3)]
        out.append(det(M) / d)
    return out


def newton(residual_jacobian, q, max_iter=60):
    """Newton to convergence: stops when the step vanishes, or has stopped shrinking once it is at
    rounding level (it then only dithers in the last digits).

    Returns the solution and the number of iterations taken."""
    tiny = Decimal(10) ** (10 - getcontext().prec) if isinstance(q[0], Decimal) else 1e-12
    prev = None
    for it in range(1, max_iter + 1):
        r, J = residual_jacobian(q)
        dq = solve3(J, r)
        q = [qi - di for qi, di in zip(q, dq)]
        step = sum(abs(d) for d in dq)
        if step == 0 or (prev is not None and step >= prev and step < tiny * sum(abs(x) for x in q)):
            return q, it
        prev = step
    raise RuntimeError("Newton did not converge")


def linkage_file(name, bodies, joints, driver, outputs, timing=None):
    """A mechanism file's contents, its keys in the order of the format spec (the optional
    "timing", a machine's cycle as docs/timing.md has it, last)."""
    data = {"format": "linkage", "version": 1, "name": name, "units": {"length": "mm"},
            "bodies": bodies, "joints": joints, "driver": driver, "outputs": {"points": outputs}}
    if timing:
        data["timing"] = timing
    return data


# ----------------------------------------------------------------------------------------------
# Wanzer needle bar (ME 481 H05): triangle EF 16, FG 56, EG 62; slot B is x = 10, slot C is y = 10
# on the disk (disk frame = global frame in the sketch); needle slot D is x = 0.
EF, FG, EG = 16, 56, 62
XB, YC, XG = 10, 10, 0


def wanzer_points(inv, q):
    """Global E, F, G from the three unknowns of the homework script."""
    if inv == 2:  # q = (yE, xF, yG): E in slot B, F in slot C
        E, F = (XB, q[0]), (q[1], YC)
    else:  # q = (xE, yF, yG): E in slot C, F in slot B
        E, F = (q[0], YC), (XB, q[1])
    return E, F, (XG, q[2])


def wanzer_equations(inv):
    def rj(q):
        num = type(q[0])
        E, F, G = wanzer_points(inv, q)
        E = tuple(num(v) for v in E)
        F = tuple(num(v) for v in F)
        G = tuple(num(v) for v in G)
        ef = (E[0] - F[0], E[1] - F[1])
        fg = (F[0] - G[0], F[1] - G[1])
        eg = (E[0] - G[0], E[1] - G[1])
        r = [ef[0] ** 2 + ef[1] ** 2 - EF ** 2,
             fg[0] ** 2 + fg[1] ** 2 - FG ** 2,
             eg[0] ** 2 + eg[1] ** 2 - EG ** 2]
        if inv == 2:  # the homework's Jacobian
            J = [[2 * ef[1], -2 * ef[0], 0 * ef[0]],
                 [0 * ef[0], 2 * fg[0], -2 * fg[1]],
                 [2 * eg[1], 0 * ef[0], -2 * eg[1]]]
        else:
            J = [[2 * ef[0], -2 * ef[1], 0 * ef[0]],
                 [0 * ef[0], 2 * fg[1], -2 * fg[1]],
                 [2 * eg[0], 0 * ef[0], -2 * eg[1]]]
        return r, J

    return rj


def wanzer_sketch(inv, start):
    rj = wanzer_equations(inv)
    qf, iters = newton(rj, [float(v) for v in start])
    qd, _ = newton(rj, [Decimal(repr(v)) for v in qf])
    q = [plain(float(v)) for v in qd]
    E, F, G = wanzer_points(inv, q)
    # Same triangle orientation in both inversions: E, G, F counter-clockwise.
    cross = (F[0] - E[0]) * (G[1] - E[1]) - (F[1] - E[1]) * (G[0] - E[0])
    assert cross < 0, "Newton start led to the mirrored triangle"
    ulps = [abs(a - b) / (abs(b) * 2.0 ** -52) for a, b in zip(qf, q)]
    return E, F, G, iters, ulps


def wanzer_file(inv, E, F, G):
    # The slot that carries each slider is what distinguishes the inversions.
    slot4, slot5 = ("disk.B", "disk.C") if inv == 2 else ("disk.C", "disk.B")
    return linkage_file(
        f"Wanzer needle bar, inversion {inv}",
        [
            {"name": "ground", "ground": True, "number": 1,
             "points": {"A": [0, 0]},
             "slots": {"D": [[0, 0], [0, -100]]}},
            {"name": "disk", "number": 2,
             "points": {"A": [0, 0]},
             "slots": {"B": [[10, -31], [10, 31]], "C": [[-31, 10], [31, 10]]}},
            {"name": "triangle", "number": 3,
             "points": {"E": list(E), "F": list(F), "G": list(G)}},
            {"name": "slider4", "number": 4, "points": {"E": list(E)}},
            {"name": "slider5", "number": 5, "points": {"F": list(F)}},
            {"name": "needlebar", "number": 6, "points": {"G": list(G)}},
        ],
        [
            {"type": "pin", "a": "ground.A", "b": "disk.A"},
            {"type": "pin", "a": "triangle.E", "b": "slider4.E"},
            {"type": "slider", "a": "slider4.E", "slot": slot4},
            {"type": "pin", "a": "triangle.F", "b": "slider5.F"},
            {"type": "slider", "a": "slider5.F", "slot": slot5},
            {"type": "pin", "a": "triangle.G", "b": "needlebar.G"},
            {"type": "slider", "a": "needlebar.G", "slot": "ground.D"},
        ],
        {"joint": 0, "rpm": 240, "direction": "cw"},
        ["needlebar.G"])


# ----------------------------------------------------------------------------------------------
# Central slider-crank of the 22-A needle bar (Karabegovic et al.): r = 15, l = r / lambda, drawn at
# the outer dead centre. Exact integers, nothing to solve.
def slider_crank_file(lam_text, l):
    r = 15
    return linkage_file(
        f"Central slider-crank needle bar (22-A), lambda = {lam_text}",
        [
            {"name": "ground", "ground": True, "number": 1,
             "points": {"O": [0, 0]},
             "slots": {"guide": [[0, 0], [0, 120]]}},
            {"name": "crank", "number": 2, "points": {"O": [0, 0], "A": [0, r]}},
            {"name": "rod", "number": 3, "points": {"A": [0, r], "B": [0, r + l]}},
            {"name": "needlebar", "number": 4, "points": {"B": [0, r + l]}},
        ],
        [
            {"type": "pin", "a": "ground.O", "b": "crank.O"},
            {"type": "pin", "a": "crank.A", "b": "rod.A"},
            {"type": "pin", "a": "rod.B", "b": "needlebar.B"},
            {"type": "slider", "a": "needlebar.B", "slot": "ground.guide"},
        ],
        {"joint": 0, "rpm": 1000, "direction": "ccw"},
        ["needlebar.B"])


# ----------------------------------------------------------------------------------------------
# Grashof crank-rocker: O2 (0, 0), O4 (60, 0), crank 20 at 60 degrees, coupler 70, rocker 50, open
# circuit (B left of A->O4, here above the ground line), coupler point 35 along and 25 normal to AB.
def four_bar_sketch(num):
    r2, r3, r4 = num(20), num(70), num(50)
    O4 = (num(60), num(0))
    A = (r2 / 2, r2 * sqrt(num(3)) / 2)  # 60 degrees, exactly in terms of sqrt(3)
    D = (O4[0] - A[0], O4[1] - A[1])
    d2 = D[0] ** 2 + D[1] ** 2
    d = sqrt(d2)
    m = (r3 ** 2 - r4 ** 2 + d2) / (2 * d)
    h = sqrt(r3 ** 2 - m ** 2)
    B = (A[0] + (m * D[0] - h * D[1]) / d, A[1] + (m * D[1] + h * D[0]) / d)
    u = ((B[0] - A[0]) / r3, (B[1] - A[1]) / r3)
    n = (-u[1], u[0])
    P = (A[0] + 35 * u[0] + 25 * n[0], A[1] + 35 * u[1] + 25 * n[1])
    return A, B, P


def four_bar_file():
    A, B, P = (tuple(plain(float(v)) for v in pt) for pt in four_bar_sketch(Decimal))
    Af, Bf, Pf = four_bar_sketch(float)
    for exact, fl in ((A, Af), (B, Bf), (P, Pf)):  # the float closed form agrees to rounding
        assert all(abs(x - y) <= 1e-13 * max(1.0, abs(x)) for x, y in zip(exact, fl))
    assert B[1] > 0
    data = linkage_file(
        "Four-bar crank-rocker with coupler point",
        [
            {"name": "ground", "ground": True, "number": 1,
             "points": {"O2": [0, 0], "O4": [60, 0]}},
            {"name": "crank", "number": 2, "points": {"O2": [0, 0], "A": list(A)}},
            {"name": "coupler", "number": 3, "points": {"A": list(A), "B": list(B), "P": list(P)}},
            {"name": "rocker", "number": 4, "points": {"B": list(B), "O4": [60, 0]}},
        ],
        [
            {"type": "pin", "a": "ground.O2", "b": "crank.O2"},
            {"type": "pin", "a": "crank.A", "b": "coupler.A"},
            {"type": "pin", "a": "coupler.B", "b": "rocker.B"},
            {"type": "pin", "a": "rocker.O4", "b": "ground.O4"},
        ],
        {"joint": 0, "rpm": 60, "direction": "ccw"},
        ["coupler.P"])
    return data, (A, B, P)


def scalar(v):
    """A number, string or boolean as the program writes it (Python's float repr, like the
    program's, is the shortest text that reads back to the same double)."""
    return json.dumps(v, ensure_ascii=False)


def inline(v):
    """An array of scalars, or of arrays of scalars, on one line when that line is at most 80
    characters long ([x, y], [[x0, y0], [x1, y1]], a list of output names); None otherwise."""
    parts = []
    for e in v:
        if isinstance(e, dict):
            return None
        if isinstance(e, list):
            if any(isinstance(x, (list, dict)) for x in e):
                return None
            parts.append("[" + ", ".join(scalar(x) for x in e) + "]")
        else:
            parts.append(scalar(e))
    text = "[" + ", ".join(parts) + "]"
    return text if len(text) <= 80 else None


def emit(v, indent=0):
    """The program's layout of a mechanism file (solver/io/model_file_write.cpp): two spaces of
    indentation, short arrays on one line."""
    pad = " " * (indent + 2)
    if isinstance(v, dict):
        if not v:
            return "{}"
        items = [pad + scalar(k) + ": " + emit(x, indent + 2) for k, x in v.items()]
        return "{\n" + ",\n".join(items) + "\n" + " " * indent + "}"
    if isinstance(v, list):
        if not v:
            return "[]"
        one_line = inline(v)
        if one_line is not None:
            return one_line
        return "[\n" + ",\n".join(pad + emit(x, indent + 2) for x in v) + "\n" + " " * indent + "]"
    return scalar(v)


def write(name, data):
    # Floats are written as their repr, which reads back to the same double, and laid out as the
    # program saves them, so that opening and saving an example changes nothing.
    text = emit(data)
    assert json.loads(text) == data
    with open(os.path.join(HERE, name), "w", encoding="utf-8") as f:
        f.write(text + "\n")


def main():
    for inv, start in ((2, (20, 20, -40)), (1, (-4.5132, 3.2644, -51.8355))):
        E, F, G, iters, ulps = wanzer_sketch(inv, start)
        write(f"wanzer-inversion-{inv}.linkage.json", wanzer_file(inv, E, F, G))
        print(f"wanzer-inversion-{inv}: E = {E}, F = {F}, G = {G} "
              f"(float Newton: {iters} iterations, within {max(ulps):.1f} ulp of the rounded exact)")
    for lam_text, l in (("0.5", 30), ("0.3", 50)):
        write(f"slider-crank-22a-lambda-{lam_text}.linkage.json", slider_crank_file(lam_text, l))
        print(f"slider-crank-22a-lambda-{lam_text}: r = 15, l = {l}")
    data, (A, B, P) = four_bar_file()
    write("four-bar-crank-rocker.linkage.json", data)
    print(f"four-bar-crank-rocker: A = {A}, B = {B}, P = {P}")


if __name__ == "__main__":
    main()
