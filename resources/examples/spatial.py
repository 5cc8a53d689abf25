#!/usr/bin/env python3
"""The spatial examples (docs/spatial.md), written as the program saves them: run
`python3 resources/examples/spatial.py` (no dependencies). Numbers are Python floats, whose repr
reads back to the same double."""
import math

from generate import linkage_file, plain, write


def rssr_file():
    """An RSSR crank-rocker: a crank of 7.5 mm on a shaft along z (the drawing plane), a rocker of
    28.5 mm turning about an axis along x through H (0, 0, 80), its plane inclined rho = 23
    degrees (the overedge machine's crank and rocker lengths and angle, seed 004; the rest ours),
    joined by a ball rod from the crank pin A (5 mm out along the shaft) to the rocker's C."""
    rho = math.radians(23)
    x_axis = [0, math.cos(rho), math.sin(rho)]
    y_axis = [0, -math.sin(rho), math.cos(rho)]
    a, c = math.radians(30), math.radians(160)
    data = linkage_file(
        "RSSR crank-rocker (a crank and a rocker on crossed shafts, a ball rod between)",
        [{"name": "ground", "ground": True, "number": 1, "points": {"O": [0, 0], "H": [0, 0, 80]}},
         {"name": "crank", "number": 2,
          "points": {"O": [0, 0], "A": [7.5 * math.cos(a), 7.5 * math.sin(a), 5]}},
         {"name": "rocker", "plane": "rocker", "number": 3,
          "points": {"H": [0, 0], "C": [28.5 * math.cos(c), 28.5 * math.sin(c)]}}],
        [{"type": "pin", "a": "ground.O", "b": "crank.O"},
         {"type": "pin", "a": "ground.H", "b": "rocker.H"},
         {"type": "ball-rod", "a": "crank.A", "b": "rocker.C"}],
        {"joint": 0, "rpm": 600, "direction": "ccw"},
        ["rocker.C"])
    planes = {"rocker": {"origin": [0, 0, 80], "x_axis": x_axis, "y_axis": y_axis}}
    # "planes" after "units", as the program writes it.
    keys = list(data)
    data = {k: data[k] for k in keys[:keys.index("bodies")]} | {"planes": planes} | \
        {k: data[k] for k in keys[keys.index("bodies"):]}
    return data


# ----------------------------------------------------------------------------------------------
# Seed 004's overedge machine (Przytulski, Zajaczkowski, GN1-1) as its paper draws it: world x
# along the main shaft, y up, z across; the paper's numbers in mm (it gives metres). README.md
# "The overedge machine in space" says which numbers are the paper's and which are ours.
RHO = math.radians(23)
OV_A, OV_H = (138, 73, 79), (111, 134.5, 53.5)  # the main shaft's crank R1 centre, the rockers' H
OV_R1, OV_L1, OV_W1, OV_W2, OV_L2, OV_XG = 7.5, 67, 28.5, 41.5, 16, 70
OV_NEEDLE = 15  # the needle point beyond the needle arm's pin G along u (ours)
# The plane of the main shaft: normal -x, so that the paper's phi1 (the crank pin at A + R1 (0,
# -cos phi1, sin phi1), eq. 1a) is the crank's angle counter-clockwise; its x along world z,
# y along world y (seen from the machine's left end, y up). Points at depth d lie at x = 138 - d.
MAIN = {"origin": list(OV_A), "x_axis": [0, 0, 1], "y_axis": [0, 1, 0]}
# The rockers' plane (eqs. 1a and 2a): x along the main shaft's x, y = u, the needle arm's
# direction (0, -cos rho, sin rho); its normal (0, -sin rho, -cos rho) is the rockers' axis.
ROCKER = {"origin": list(OV_H), "x_axis": [1, 0, 0],
          "y_axis": [0, -math.cos(RHO), math.sin(RHO)]}
# The grippers' plane: the upper gripper's rocker W3 and W4 turn about an axis along z through F
# (eq. 3a), the lower gripper W4 - L4 - W5 is flat in it (eq. 4a), 10 mm deeper (z 69). Its
# coordinates are the world's x and y (origin on the z axis): it is parallel to the drawing plane.
OV_F = (40, 38, 79)
GRIPPER = {"origin": [0, 0, OV_F[2]], "x_axis": [1, 0, 0], "y_axis": [0, 1, 0]}
OV_R2, OV_L3, OV_W3, OV_W4, OV_L4, OV_W5, OV_P = 10, 40, 24, 20, 42, 22, 52
OV_K = (78, 51)  # the lower gripper's pivot, world x, y (z 69)
OV_LOW = -10  # the lower gripper's depth in the grippers' plane
OV_D = (6, -8)  # the crank R2 in the main shaft's plane (36.87 degrees ahead of R1), at x = 0
OV_W4_TURN = math.atan2(-40, 9)  # W4 from W3 (77.32 degrees behind it)
OV_V = (30, 67, -14)  # the upper gripper's point on its rocker, from F (ours)
# The transport (eqs. 5a to 8), flat in planes across the main shaft (its plane's class), ours:
# R3 3 and R4 2 on the main shaft, the rockers W6 - W7 about B and W8 - W9 about C, links L5,
# L6, L8, the toothed bar L7 + LT; main-plane coordinates, 60 mm deep (x 78).
TR_B, TR_C = (48, -23), (40, 10)
TR_R3, TR_L5, TR_W6, TR_W7, TR_L6, TR_W8, TR_W9 = 3, 53, 12, 12, 30, 14, 10
TR_L7, TR_LT, TR_R4, TR_L8 = 40, 12, 2, 17.5
TR_W7_TURN = math.atan2(-9, 8) - math.pi  # W7 from W6
TR_DEPTH, TR_TOOTH_DEPTH = 60, 68  # the bar's tooth under the needle (x 70)


def v_add(*vs):
    return tuple(sum(c) for c in zip(*vs))


def v_mul(s, v):
    return tuple(s * c for c in v)


def v_sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def v_dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def in_plane(plane, p):
    """A plane's (x, y[, d]) in the world."""
    x, y, n = plane["x_axis"], plane["y_axis"], cross(plane["x_axis"], plane["y_axis"])
    d = p[2] if len(p) > 2 else 0
    return v_add(plane["origin"], v_mul(p[0], x), v_mul(p[1], y), v_mul(d, n))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def rocker_angle(P, plane, centre, r, length, near):
    """The angle (in its plane, from its x axis) of a rocker of radius r about `centre` (plane
    coordinates, depth 0) whose end is `length` from the world point P: a cos t + b sin t = c, the
    root nearest `near`."""
    d = v_sub(P, in_plane(plane, centre))
    a, b = 2 * r * v_dot(d, plane["x_axis"]), 2 * r * v_dot(d, plane["y_axis"])
    c = v_dot(d, d) + r * r - length * length
    base, half = math.atan2(b, a), math.acos(c / math.hypot(a, b))
    return min((base + half, base - half), key=lambda t: abs(math.remainder(t - near, 2 * math.pi)))


def circles2(c0, r0, c1, r1, near):
    """The intersection of two circles nearest `near` (2D, floats)."""
    e = (c1[0] - c0[0], c1[1] - c0[1])
    d = math.hypot(*e)
    m = (r0 * r0 - r1 * r1 + d * d) / (2 * d)
    h = math.sqrt(r0 * r0 - m * m)
    u = (e[0] / d, e[1] / d)
    two = [(c0[0] + m * u[0] - s * h * u[1], c0[1] + m * u[1] + s * h * u[0]) for s in (1, -1)]
    return min(two, key=lambda p: math.dist(p, near))


def turned2(c, p, angle, scale=1):
    v = (p[0] - c[0], p[1] - c[1])
    co, si = math.cos(angle), math.sin(angle)
    return (c[0] + scale * (co * v[0] - si * v[1]), c[1] + scale * (si * v[0] + co * v[1]))


def overedge_machine_sketch(phi=0.0, near=None):
    """Every moving point at crank angle phi (radians; 0 is the drawing), in its body's plane's
    coordinates; `near`, the previous sketch, picks the branches (the drawing's by default)."""
    near = near or {"a1": 0.0, "a3": math.pi, "M": (80, 58), "G6": (40, -32), "G8": (54, 10),
                    "J": (3, 17)}
    s = {}
    c, si = math.cos(phi), math.sin(phi)
    A1 = (OV_R1 * si, -OV_R1 * c)  # eq. 1a's crank pin, main-plane coordinates
    a1 = rocker_angle(in_plane(MAIN, A1), ROCKER, (0, 0), OV_W1, OV_L1, near["a1"])
    B = (OV_W1 * math.cos(a1), OV_W1 * math.sin(a1))
    C = (-OV_W2 * math.cos(a1), -OV_W2 * math.sin(a1))  # W2 opposite W1: phase pi
    x = OV_H[0] - OV_XG  # eq. 2a: the needle arm's line, X_H - X_G from H
    sin_b2 = (x - OV_W2 * math.cos(a1)) / OV_L2
    U = OV_L2 * math.sqrt(1 - sin_b2 * sin_b2) - OV_W2 * math.sin(a1)
    G = (-x, U)
    s.update(A1=A1, B=B, C=C, G=G, N=(-x, U + OV_NEEDLE), a1=a1)
    # The upper gripper (eq. 3a): the crank R2 at x = 0, a ball rod L3 to W3 about F (axis z).
    D = turned2((0, 0), OV_D, phi)
    F = OV_F[:2]
    a3 = rocker_angle(in_plane(MAIN, (D[0], D[1], OV_A[0])), GRIPPER, F, OV_W3, OV_L3,
                      near["a3"])
    E = v_add(F, (OV_W3 * math.cos(a3), OV_W3 * math.sin(a3)))
    Q = v_add(F, (OV_W4 * math.cos(a3 + OV_W4_TURN), OV_W4 * math.sin(a3 + OV_W4_TURN)))
    V = turned2(F, v_add(F, OV_V[:2]), a3 - near_a3_drawn())
    K = OV_K
    M = circles2(Q, OV_L4, K, OV_W5, near["M"])
    P = v_add(K, v_mul(OV_P / OV_W5, v_sub(M, K)))
    s.update(D=D, E=E, Q=Q, V=V, K=K, M=M, P=P, a3=a3)
    # The transport (eqs. 5a to 8).
    P3 = turned2((0, 0), (0, TR_R3), phi)
    P4 = turned2((0, 0), (-TR_R4, 0), phi)  # 90 degrees ahead of R3
    G6 = circles2(P3, TR_L5, TR_B, TR_W6, near["G6"])
    G7 = turned2(TR_B, G6, TR_W7_TURN, TR_W7 / TR_W6)
    G8 = circles2(G7, TR_L6, TR_C, TR_W8, near["G8"])
    S = turned2(TR_C, G8, math.pi / 2, TR_W9 / TR_W8)
    J = circles2(S, TR_L7, P4, TR_L8, near["J"])
    T = v_add(S, v_mul((TR_L7 + TR_LT) / TR_L7, v_sub(J, S)))
    s.update(P3=P3, P4=P4, G6=G6, G7=G7, G8=G8, S=S, J=J, T=T)
    return s


_A3_DRAWN = []


def near_a3_drawn():
    """W3's angle in the drawing (V is placed at OV_V there)."""
    if not _A3_DRAWN:
        D = OV_D
        _A3_DRAWN.append(rocker_angle(in_plane(MAIN, (D[0], D[1], OV_A[0])), GRIPPER, OV_F[:2],
                                      OV_W3, OV_L3, math.pi))
    return _A3_DRAWN[0]


def xyd(p, d):
    return [plain(p[0]), plain(p[1])] + ([plain(d)] if d else [])


def overedge_machine_file():
    s = overedge_machine_sketch()
    low, tr, tooth = OV_LOW, TR_DEPTH, TR_TOOTH_DEPTH
    x = OV_H[0] - OV_XG
    u_slot = [[plain(c) for c in in_plane(ROCKER, (-x, u))] for u in (0, 40)]

    def body(name, number, plane, points, slots=None):
        b = {"name": name}
        if plane:
            b["plane"] = plane
        b["number"] = number
        b["points"] = points
        if slots:
            b["slots"] = slots
        return b

    bodies = [
        {"name": "ground", "ground": True, "number": 1,
         "points": {"A": list(OV_A), "H": list(OV_H), "F": list(OV_F), "K": [OV_K[0], OV_K[1], 69],
                    "B": list(in_plane(MAIN, (TR_B[0], TR_B[1], tr))),
                    "C": list(in_plane(MAIN, (TR_C[0], TR_C[1], tr)))},
         "slots": {"u": u_slot}},
        body("main", 2, "main", {"O": [0, 0], "A1": xyd(s["A1"], 0), "D": xyd(s["D"], OV_A[0]),
                                 "R3": xyd(s["P3"], tr), "R4": xyd(s["P4"], tr)}),
        body("needlerock", 3, "rocker", {"H": [0, 0], "B": xyd(s["B"], 0), "C": xyd(s["C"], 0)}),
        body("needlelink", 4, "rocker", {"C": xyd(s["C"], 0), "G": xyd(s["G"], 0)}),
        body("needlearm", 5, "rocker", {"G": xyd(s["G"], 0), "N": xyd(s["N"], 0)}),
        body("upper", 6, "gripper", {"F": xyd(OV_F, 0), "E": xyd(s["E"], 0), "Q": xyd(s["Q"], low),
                                     "V": xyd(s["V"], OV_V[2])}),
        body("lowerlink", 7, "gripper", {"Q": xyd(s["Q"], low), "M": xyd(s["M"], low)}),
        body("lower", 8, "gripper", {"K": xyd(s["K"], low), "M": xyd(s["M"], low),
                                     "P": xyd(s["P"], low)}),
        body("feedrod", 9, "main", {"R3": xyd(s["P3"], tr), "G6": xyd(s["G6"], tr)}),
        body("feedrock1", 10, "main", {"B": xyd(TR_B, tr), "G6": xyd(s["G6"], tr),
                                       "G7": xyd(s["G7"], tr)}),
        body("feedlink", 11, "main", {"G7": xyd(s["G7"], tr), "G8": xyd(s["G8"], tr)}),
        body("feedrock2", 12, "main", {"C": xyd(TR_C, tr), "G8": xyd(s["G8"], tr),
                                       "S": xyd(s["S"], tr)}),
        body("liftrod", 13, "main", {"R4": xyd(s["P4"], tr), "J": xyd(s["J"], tr)}),
        body("feedbar", 14, "main", {"S": xyd(s["S"], tr), "J": xyd(s["J"], tr),
                                     "T": xyd(s["T"], tooth)}),
    ]
    joints = [
        {"type": "pin", "a": "ground.A", "b": "main.O"},
        {"type": "pin", "a": "ground.H", "b": "needlerock.H"},
        {"type": "ball-rod", "a": "main.A1", "b": "needlerock.B"},
        {"type": "pin", "a": "needlerock.C", "b": "needlelink.C"},
        {"type": "pin", "a": "needlelink.G", "b": "needlearm.G"},
        {"type": "slider", "a": "needlearm.G", "slot": "ground.u"},
        {"type": "pin", "a": "ground.F", "b": "upper.F"},
        {"type": "ball-rod", "a": "main.D", "b": "upper.E"},
        {"type": "pin", "a": "upper.Q", "b": "lowerlink.Q"},
        {"type": "pin", "a": "lowerlink.M", "b": "lower.M"},
        {"type": "pin", "a": "lower.K", "b": "ground.K"},
        {"type": "pin", "a": "main.R3", "b": "feedrod.R3"},
        {"type": "pin", "a": "feedrod.G6", "b": "feedrock1.G6"},
        {"type": "pin", "a": "feedrock1.B", "b": "ground.B"},
        {"type": "pin", "a": "feedrock1.G7", "b": "feedlink.G7"},
        {"type": "pin", "a": "feedlink.G8", "b": "feedrock2.G8"},
        {"type": "pin", "a": "feedrock2.C", "b": "ground.C"},
        {"type": "pin", "a": "feedrock2.S", "b": "feedbar.S"},
        {"type": "pin", "a": "main.R4", "b": "liftrod.R4"},
        {"type": "pin", "a": "liftrod.J", "b": "feedbar.J"},
    ]
    data = linkage_file(
        "Overedge machine GN1-1 in space (seed 004): needle arm, grippers and transport on one "
        "main shaft",
        bodies, joints, {"joint": 0, "rpm": 6000, "direction": "ccw"},
        ["needlearm.N", "upper.V", "lower.P", "feedbar.T"])
    return with_planes(data, {"main": MAIN, "rocker": ROCKER, "gripper": GRIPPER})


def with_planes(data, planes):
    # "planes" after "units", as the program writes it.
    keys = list(data)
    return {k: data[k] for k in keys[:keys.index("bodies")]} | {"planes": planes} | \
        {k: data[k] for k in keys[keys.index("bodies"):]}


def overedge_machine_numbers():
    """Printed for README.md and docs/seed004.md: ranges over a turn, every 0.1 degree."""
    near, rows = None, []
    for k in range(3601):
        s = overedge_machine_sketch(math.radians(k / 10), near)
        near = {"a1": s["a1"], "a3": s["a3"], "M": s["M"], "G6": s["G6"], "G8": s["G8"],
                "J": s["J"]}
        rows.append((k / 10, s))
    def rng(f):
        v = [f(s) for _, s in rows]
        return f"{min(v):.3f} to {max(v):.3f}"
    print("  alpha1 (deg):", rng(lambda s: math.degrees(s["a1"])))
    print("  U (mm):", rng(lambda s: s["G"][1]))
    low = max(rows, key=lambda r: r[1]["N"][1])
    print(f"  needle point lowest at crank {low[0]} deg, world {tuple(round(c, 3) for c in in_plane(ROCKER, low[1]['N']))}")
    print("  alpha3 (deg):", rng(lambda s: math.degrees(s["a3"])))
    print("  lower P world x:", rng(lambda s: s["P"][0]), "y:", rng(lambda s: s["P"][1]))
    print("  feed T world z:", rng(lambda s: s["T"][0] + OV_A[2]), "y:", rng(lambda s: s["T"][1] + OV_A[1]))
    H1 = (111, 149.5, 88.5)
    d, n = v_sub(H1, OV_H), (0, math.sin(RHO), math.cos(RHO))
    print(f"  H1 off the rho axis: {math.sqrt(v_dot(d, d) - v_dot(d, n) ** 2):.4f} mm; "
          f"its angle {math.degrees(math.atan2(15, 35)):.4f} deg")


# ----------------------------------------------------------------------------------------------
# A lockstitch machine whose hook shaft is driven through a vertical shaft and two bevel pairs
# (dimensions ours): the arm shaft along x through the origin, the needle bar's central
# slider-crank in the plane across it at its end (x = 0), as lockstitch-machine's (crank 16
# drawn straight up, rod 45, the needle point 131 below the rod's pin: from y -160 to -192); the
# vertical shaft along y at x = 20, z = 0 (it meets both other shafts), geared 1:1 to the arm
# shaft; the hook shaft along z at (20, -200), geared 2:1 to the vertical shaft, so that the hook
# turns twice a stitch in the plane z = 0, at right angles to the needle's (x = 0). The hook
# point is 25 from its axis and crosses the needle's line at the top of the plate's level,
# (0, -185, 0), at crank 206.57 degrees (26.57 after the needle's lowest), as in
# lockstitch-machine.
LB_R, LB_L, LB_NEEDLE, LB_BLADE = 16, 45, 131, 35
LB_VX, LB_HOOK_Y, LB_HOOK_R = 20, -200, 25
LB_MEET = math.pi + (math.pi / 2 - math.atan2(9, 12)) / 2  # lockstitch-machine's meeting angle
# Each angle is about its own plane's normal (the file format's rule): the arm shaft's +x, the
# vertical shaft's +y, the hook's +z (the hook is in the drawing plane, z = 0).
LB_NEEDLE_PLANE = {"origin": [0, 0, 0], "x_axis": [0, 0, -1], "y_axis": [0, 1, 0]}
LB_VERTICAL = {"origin": [LB_VX, 0, 0], "x_axis": [1, 0, 0], "y_axis": [0, 0, -1]}
LB_RATIO1, LB_RATIO2 = 1, 2


def lockstitch_bevel_file():
    A, B = (0, LB_R), (0, LB_R - LB_L)
    N, T = (0, B[1] - LB_NEEDLE), (0, B[1] - LB_NEEDLE + LB_BLADE)
    # The hook point meets the needle's line at (-20, 15) from its axis (3, 4, 5 times 5) when
    # the crank is at LB_MEET, 2 LB_MEET = 2 pi + pi / 2 - atan(3 / 4) of the hook's turn
    # earlier: it is drawn straight up from its axis, at (0, 25).
    k0 = math.atan2(15, -LB_VX) - LB_RATIO1 * LB_RATIO2 * LB_MEET
    assert abs(math.remainder(k0 - math.pi / 2, 2 * math.pi)) < 1e-12
    K = (0, LB_HOOK_R)
    V0 = (12, 0)  # a mark on the vertical shaft, 12 from its axis
    data = linkage_file(
        "Lockstitch machine with bevel pairs: arm shaft, vertical shaft, hook shaft 2:1, the "
        "hook at right angles to the needle",
        [{"name": "ground", "ground": True, "number": 1,
          "points": {"O": [0, 0], "V": [LB_VX, -100, 0], "L": [LB_VX, LB_HOOK_Y, -30]},
          "slots": {"needle": [[0, -20, 0], [0, -170, 0]]}},
         {"name": "armshaft", "plane": "needle", "number": 2, "points": {"O": [0, 0], "A": list(A)}},
         {"name": "rod", "plane": "needle", "number": 3, "points": {"A": list(A), "B": list(B)}},
         {"name": "needlebar", "plane": "needle", "number": 4,
          "points": {"B": list(B), "N": list(N), "T": list(T)}},
         {"name": "vshaft", "plane": "vertical", "number": 5,
          "points": {"V": [0, 0], "M": [V0[0], V0[1], 100]}},
         {"name": "hook", "number": 6,
          "points": {"L": [LB_VX, LB_HOOK_Y], "K": [LB_VX + K[0], LB_HOOK_Y + K[1]]}}],
        [{"type": "pin", "a": "ground.O", "b": "armshaft.O"},
         {"type": "pin", "a": "armshaft.A", "b": "rod.A"},
         {"type": "pin", "a": "rod.B", "b": "needlebar.B"},
         {"type": "slider", "a": "needlebar.B", "slot": "ground.needle"},
         {"type": "pin", "a": "ground.V", "b": "vshaft.V"},
         {"type": "gear", "a": "armshaft.O", "b": "vshaft.V", "ratio": LB_RATIO1},
         {"type": "pin", "a": "ground.L", "b": "hook.L"},
         {"type": "gear", "a": "vshaft.V", "b": "hook.L", "ratio": LB_RATIO2}],
        {"joint": 0, "rpm": 1200, "direction": "ccw"},
        ["needlebar.N", "needlebar.T", "hook.K"])
    return with_planes(data, {"needle": LB_NEEDLE_PLANE, "vertical": LB_VERTICAL})


def main():
    write("rssr-crank-rocker.linkage.json", rssr_file())
    print("rssr-crank-rocker: crank 7.5 at 30 degrees, rocker 28.5 at 160 degrees, rho 23")
    write("overedge-machine.linkage.json", overedge_machine_file())
    print("overedge-machine:")
    overedge_machine_numbers()
    write("lockstitch-bevel.linkage.json", lockstitch_bevel_file())
    print(f"lockstitch-bevel: hook point meets the needle's line at crank "
          f"{math.degrees(LB_MEET):.4f} deg")


if __name__ == "__main__":
    main()
