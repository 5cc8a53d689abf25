#!/usr/bin/env python3
"""Writes the examples of gear and belt couplings and of arc slots (see README.md):

  lockstitch-arm-shaft   a lockstitch machine's arm shaft: needle bar, take-up lever and a hook
                         shaft belted 2:1 (dimensions representative, ours)
  gear-four-bar          a pinion and gear (ratio -1/2) cranking the four-bar-crank-rocker example
  planet-epicycloid      a planet of radius 10 on an arm around a fixed sun of radius 20
  curved-guide           a slider-crank whose block runs in an arc slot of the ground
  lockstitch-machine     the lockstitch arm shaft with a drop feed on a lower shaft belted 1:1
                         and a throat plate (issue 18)
  overedge-needle-arm    seed 004's overedge needle arm drive in its plane (the paper's R1, L1,
                         W1, W2, L2), with a lower gripper on a second crank (ours) (issue 18)

The machines (the two lockstitch files and the overedge needle arm) keep the windows of their
cycle in their "timing" (issue 26), each threshold taken from the file's own geometry: the
needle point below the throat plate, the hook or gripper point past the needle's line, the feed
dog above the plate; and the conflict a designer checks (the feed dog moves the fabric only
while the needle is out of it). The lockstitch files also watch the hook point's clearance to
the needle, the segment from its point up to the needle bar's pin (where the two meet).

Every coordinate is computed in 50-digit decimal arithmetic (only square roots are needed) and
stored as the correctly rounded double, as generate.py does for the other examples; each file is
drawn at crank angle 0, exactly closed.

Run from anywhere:  python3 resources/examples/machines.py
"""

import math
from decimal import Decimal, getcontext

from generate import four_bar_sketch, linkage_file, plain, write

getcontext().prec = 50
D = Decimal


def rounded(p):
    """A point as stored: each coordinate the correctly rounded double (whole numbers as ints)."""
    return [plain(float(v)) for v in p]


def circles(c0, r0, c1, r1, left):
    """An intersection of the circles (c0, r0) and (c1, r1): the one to the left of c0 -> c1 when
    `left`, else the one to its right."""
    e = (c1[0] - c0[0], c1[1] - c0[1])
    d = (e[0] * e[0] + e[1] * e[1]).sqrt()
    m = (r0 * r0 - r1 * r1 + d * d) / (2 * d)
    h = (r0 * r0 - m * m).sqrt()
    if not left:
        h = -h
    u = (e[0] / d, e[1] / d)
    return (c0[0] + m * u[0] - h * u[1], c0[1] + m * u[1] + h * u[0])


def along(p, q, length, t, n=D(0)):
    """The point t along p -> q (|pq| = length) and n to its left."""
    u = ((q[0] - p[0]) / length, (q[1] - p[1]) / length)
    return (p[0] + t * u[0] - n * u[1], p[1] + t * u[1] + n * u[0])


def bodies(*specs):
    """Bodies from (name, number, points, slots): the ground first."""
    out = []
    for name, number, points, slots in specs:
        b = {"name": name}
        if number == 1:
            b["ground"] = True
        b["number"] = number
        b["points"] = {k: rounded(v) for k, v in points.items()}
        if slots:
            b["slots"] = {k: [rounded(p) for p in v] for k, v in slots.items()}
        out.append(b)
    return out


def pin(a, b):
    return {"type": "pin", "a": a, "b": b}


# ----------------------------------------------------------------------------------------------
# Lockstitch arm shaft (representative dimensions, ours). Arm shaft O at the origin, 1200 rpm ccw.
# Needle bar: a central slider-crank hanging below the shaft, crank 16, rod 45 (stroke 32), the
# needle point 131 mm below the rod's pin on the needle bar; drawn at its top dead centre.
# Take-up lever: a crank-rocker on a second crank pin T of the arm shaft (radius 16, 36.87 degrees
# from the x axis: 16 (4/5, 3/5)), lever T-R 45, link R-Q 55 to the pivot Q = (-20, 48) on the
# ground (|OQ| = 52; 16 + 55 < 45 + 52: Grashof, the crank shortest), the eye 80 along T -> R.
# Hook shaft L 200 mm below the arm shaft, belted to it 2:1 (gear, ratio +2); hook point 15 from
# its axis, drawn at (12, 9) from L: it passes over the needle's line 26.57 degrees of crank after
# the needle's bottom dead centre, when the needle has risen 2.3 mm (the loop-taking position).
NR, NL, NEEDLE = D(16), D(45), D(131)
TR, TL, TQ, TEYE = D(16), D(45), D(55), D(80)
Q, L = (D(-20), D(48)), (D(0), D(-200))
HOOK = (D(12), D(9))
# The needle's line: the guide slot's x. The throat plate lies where the hook point's circle
# reaches highest, L.y + |LK| = -200 + 15 = -185: the hook point passes just under the plate.
NEEDLE_X = D(0)
PLATE_Y = L[1] + (HOOK[0] * HOOK[0] + HOOK[1] * HOOK[1]).sqrt()
assert PLATE_Y == -185


def lockstitch_sketch():
    A = (D(0), NR)
    B = (D(0), NR - NL)
    N = (D(0), B[1] - NEEDLE)
    T = (TR * 4 / 5, TR * 3 / 5)
    R = circles(T, TL, Q, TQ, left=False)
    E = along(T, R, TL, TEYE)
    K = (L[0] + HOOK[0], L[1] + HOOK[1])
    return {"A": A, "B": B, "N": N, "T": T, "R": R, "E": E, "K": K}


def lockstitch_file(s):
    O = (0, 0)
    return linkage_file(
        "Lockstitch arm shaft: needle bar, take-up lever, hook shaft belted 2:1",
        bodies(
            ("ground", 1, {"O": O, "Q": Q, "L": L},
             {"needle": [(NEEDLE_X, -20), (NEEDLE_X, -170)]}),
            ("armshaft", 2, {"O": O, "A": s["A"], "T": s["T"]}, None),
            ("rod", 3, {"A": s["A"], "B": s["B"]}, None),
            ("needlebar", 4, {"B": s["B"], "N": s["N"]}, None),
            ("takeup", 5, {"T": s["T"], "R": s["R"], "E": s["E"]}, None),
            ("link", 6, {"R": s["R"], "Q": Q}, None),
            ("hook", 7, {"L": L, "K": s["K"]}, None),
        ),
        [
            pin("ground.O", "armshaft.O"),
            pin("armshaft.A", "rod.A"),
            pin("rod.B", "needlebar.B"),
            {"type": "slider", "a": "needlebar.B", "slot": "ground.needle"},
            pin("armshaft.T", "takeup.T"),
            pin("takeup.R", "link.R"),
            pin("link.Q", "ground.Q"),
            pin("ground.L", "hook.L"),
            {"type": "gear", "a": "armshaft.O", "b": "hook.L", "ratio": 2},
        ],
        {"joint": 0, "rpm": 1200, "direction": "ccw"},
        ["needlebar.N", "takeup.E", "hook.K"],
        {"windows": lockstitch_windows(), "clearances": lockstitch_clearances()})


def lockstitch_windows():
    """The arm shaft's windows: the needle point below the plate's level, and the hook point past
    the needle's line. The hook turns counter-clockwise (the belt keeps the arm shaft's sense),
    so at the top of its circle, where it meets the needle, it moves towards -x: past the line
    is x < 0."""
    return [f"needle=needlebar.N:y<{plain(float(PLATE_Y))}",
            f"hook=hook.K:x<{plain(float(NEEDLE_X))}"]


def lockstitch_clearances():
    """The hook point's clearance to the needle, as the segment from the needle's point N up to
    the needle bar's pin B (body.P-Q): the hook point meets it 4.74 mm above N at crank 206.57
    degrees, where it crosses the needle's line (to the point N alone the closest is 4.41 mm, at
    210.25: not the question a designer asks)."""
    return [{"between": ["hook.K", "needlebar.N-B"]}]


def lockstitch_timing():
    """Printed for README.md: where the hook point meets the needle's line after the needle's
    bottom dead centre (crank 180 degrees), and the take-up eye's highest position."""
    r, l, n = float(NR), float(NL), float(NEEDLE)

    def needle_y(t):  # crank pin at (-r sin t, r cos t)
        return r * math.cos(t) - math.sqrt(l * l - (r * math.sin(t)) ** 2) - n

    hook0 = math.atan2(float(HOOK[1]), float(HOOK[0]))
    meet = math.pi + (math.pi / 2 - hook0) / 2  # the hook turns twice as fast
    rise = needle_y(meet) - needle_y(math.pi)
    below = float(L[1]) + 15 - needle_y(meet)
    print(f"  hook point over the needle at crank {math.degrees(meet):.2f} deg: the needle point "
          f"{rise:.2f} mm above its lowest ({needle_y(math.pi):g}), {below:.2f} mm below the hook "
          f"point")
    best = max(range(3600), key=lambda k: takeup_eye(k / 10)[1])
    print(f"  take-up eye highest at crank {best / 10:.1f} deg: {takeup_eye(best / 10)}")


def takeup_eye(deg):
    t = math.radians(deg) + math.atan2(3, 4)
    T = (float(TR) * math.cos(t), float(TR) * math.sin(t))
    R = circles(tuple(D(v) for v in T), TL, Q, TQ, left=False)
    E = along(tuple(D(v) for v in T), R, TL, TEYE)
    return tuple(round(float(v), 2) for v in E)


# ----------------------------------------------------------------------------------------------
# A pinion I = (-45, 0), driven at 120 rpm clockwise, meshing with a gear on O2 = (0, 0) at ratio
# -1/2 (pitch radii 15 and 30); the gear is the crank of the four-bar-crank-rocker example (crank
# 20 at 60 degrees, coupler 70, rocker 50, O4 = (60, 0), coupler point 35 along and 25 left of
# A -> B), which so turns counter-clockwise at 60 rpm as that example does.
def gear_four_bar_file():
    A, B, P = (rounded(pt) for pt in four_bar_sketch(Decimal))
    I, O2, O4 = (-45, 0), (0, 0), (60, 0)
    return linkage_file(
        "Gear pair cranking a four-bar",
        bodies(
            ("ground", 1, {"I": I, "O2": O2, "O4": O4}, None),
            ("pinion", 2, {"I": I}, None),
            ("gear", 3, {"O2": O2, "A": A}, None),
            ("coupler", 4, {"A": A, "B": B, "P": P}, None),
            ("rocker", 5, {"B": B, "O4": O4}, None),
        ),
        [
            pin("ground.I", "pinion.I"),
            pin("ground.O2", "gear.O2"),
            {"type": "gear", "a": "pinion.I", "b": "gear.O2", "ratio": -0.5},
            pin("gear.A", "coupler.A"),
            pin("coupler.B", "rocker.B"),
            pin("rocker.O4", "ground.O4"),
        ],
        {"joint": 0, "rpm": 120, "direction": "cw"},
        ["coupler.P"])


# ----------------------------------------------------------------------------------------------
# A planet of pitch radius 10 on an arm (the driven crank, 60 rpm ccw) around a fixed sun of pitch
# radius 20 at the origin: gear ratio -2 with the arm as carrier. The planet turns 3 times per turn
# of the arm; its rim point P, drawn at (40, 0), traces the epicycloid 30 e^{it} + 10 e^{3it}.
def planet_file():
    S, Bc, P = (0, 0), (30, 0), (40, 0)
    return linkage_file(
        "Planet gear on a fixed sun: epicycloid",
        bodies(
            ("ground", 1, {"S": S}, None),
            ("arm", 2, {"S": S, "B": Bc}, None),
            ("planet", 3, {"B": Bc, "P": P}, None),
        ),
        [
            pin("ground.S", "arm.S"),
            pin("arm.B", "planet.B"),
            {"type": "gear", "a": "ground.S", "b": "planet.B", "ratio": -2, "carrier": "arm"},
        ],
        {"joint": 0, "rpm": 60, "direction": "ccw"},
        ["planet.P"])


# ----------------------------------------------------------------------------------------------
# A slider-crank, crank 15 (drawn straight up) and rod 45, whose block runs in an arc slot of the
# ground: radius 100 about C = (-100, 45), from (-4, 17) through (0, 45) to (-4, 73) (all three on
# the circle: 96^2 + 28^2 = 100^2). The block turns about C, a rocker of 100: a four-bar 15, 45,
# 100 on |OC| = 109.66 (15 + 109.66 < 45 + 100: the crank turns fully). 1000 rpm ccw.
CG_R, CG_L, ARC_R = D(15), D(45), D(100)
ARC_C = (D(-100), D(45))


def curved_guide_sketch():
    A = (D(0), CG_R)
    B = circles(A, CG_L, ARC_C, ARC_R, left=False)  # the upper intersection
    assert B[1] > A[1]
    return A, B


def curved_guide_file():
    A, B = curved_guide_sketch()
    O = (0, 0)
    return linkage_file(
        "Slider-crank in a curved guide",
        bodies(
            ("ground", 1, {"O": O}, {"guide": [(-4, 17), (0, 45), (-4, 73)]}),
            ("crank", 2, {"O": O, "A": A}, None),
            ("rod", 3, {"A": A, "B": B}, None),
            ("block", 4, {"B": B}, None),
        ),
        [
            pin("ground.O", "crank.O"),
            pin("crank.A", "rod.A"),
            pin("rod.B", "block.B"),
            {"type": "slider", "a": "block.B", "slot": "ground.guide"},
        ],
        {"joint": 0, "rpm": 1000, "direction": "ccw"},
        ["block.B"])


# ----------------------------------------------------------------------------------------------
# The lockstitch arm shaft with its feed (dimensions representative, ours): a lower "feedshaft"
# at S = (-60, -225) belted 1:1 to the arm shaft (gear, ratio +1) carries the lift eccentric E1
# (radius 2) and the advance eccentric E2 (radius 2.5), both drawn straight up (crank 0: the
# needle at its top, the feed dog at its highest, advancing fastest). The advance: rod E2-R of 50
# to the top R of a rocker of 20 about G = (-110, -245) (a crank-rocker: 2.5 + 53.9 < 50 + 20).
# The feed bar hangs from R and rides on E1 in its fork, a slot along x through E1: E1 lifts it,
# the rocker carries it back and forth; its tooth T = (-5, -182) reaches 3 mm above the throat
# plate at y = -185 (a ground slot "plate" from (-40, -185) to (20, -185)).
FS, FE1, FE2 = (D(-60), D(-225)), D(2), D(D(5) / 2)
FG, FROD, FROCK = (D(-110), D(-245)), D(50), D(20)
FTOOTH = (D(-5), D(-182))


def feed_sketch():
    E1 = (FS[0], FS[1] + FE1)
    E2 = (FS[0], FS[1] + FE2)
    R = circles(E2, FROD, FG, FROCK, left=False)  # the rocker leaning back, up from G
    assert R[1] > FG[1] and R[0] < E2[0]
    return {"E1": E1, "E2": E2, "R": R}


def lockstitch_machine_file(s, f):
    base = lockstitch_file(s)
    base["name"] = "Lockstitch machine: arm shaft, hook shaft 2:1, drop feed on a lower shaft 1:1"
    base["bodies"][0]["points"].update({"S": rounded(FS), "G": rounded(FG)})
    base["bodies"][0]["slots"]["plate"] = [[-40, plain(float(PLATE_Y))], [20, plain(float(PLATE_Y))]]
    E1, E2, R = f["E1"], f["E2"], f["R"]
    fork = [rounded((E1[0] - 6, E1[1])), rounded((E1[0] + 6, E1[1]))]
    base["bodies"] += bodies(
        ("feedshaft", 8, {"S": FS, "E1": E1, "E2": E2}, None),
        ("advancerod", 9, {"E2": E2, "R": R}, None),
        ("feedrock", 10, {"R": R, "G": FG}, None),
        ("feedbar", 11, {"R": R, "T": FTOOTH}, None))
    base["bodies"][-1]["slots"] = {"fork": fork}
    base["joints"] += [
        pin("ground.S", "feedshaft.S"),
        {"type": "gear", "a": "armshaft.O", "b": "feedshaft.S", "ratio": 1},
        pin("feedshaft.E2", "advancerod.E2"),
        pin("advancerod.R", "feedrock.R"),
        pin("feedrock.G", "ground.G"),
        pin("feedrock.R", "feedbar.R"),
        {"type": "pin-in-slot", "a": "feedshaft.E1", "slot": "feedbar.fork"},
    ]
    base["outputs"]["points"] = ["needlebar.N", "takeup.E", "hook.K", "feedbar.T"]
    # The feed dog's tooth above the plate; the feed must not move the fabric while the needle
    # is in it: the two windows must not overlap.
    base["timing"] = {
        "windows": lockstitch_windows() + [f"feed=feedbar.T:y>{plain(float(PLATE_Y))}"],
        "conflicts": [["needle", "feed"]],
        "clearances": lockstitch_clearances()}
    return base


# ----------------------------------------------------------------------------------------------
# Seed 004's overedge machine (Przytulski, Zajaczkowski), the planar part of its needle arm drive
# with the paper's numbers, and a lower gripper (looper) whose dimensions are ours (the paper
# gives none). Main shaft O at the origin, 6000 rpm ccw; crank R1 7.5 drawn straight up.
# - The spatial crank-rocker R1 - L1 - W1 (ball-jointed link, rocker axis H inclined at rho = 23
#   degrees) becomes a planar four-bar: crank 7.5, coupler 67, rocker 28.5, frame |OH| = 71.8,
#   the paper's distance from A = (138, 73, 79) to H = (111, 134.5, 53.5). Grashof:
#   7.5 + 71.8 = 79.3 < 67 + 28.5 = 95.5 with the crank shortest: a crank-rocker; W1 swings 30.5
#   degrees.
# - W2 41.5, rigid with W1, at 16.26 degrees ahead of it ((24/25, 7/25): exact in decimals);
#   eq. 2a is an RRP dyad: link L2 16 to the needle arm, a block in a ground slot along u, the
#   line x = X_H - X_G = 41 from H, u pointing down: U = L2 cos b2 - W2 sin a2 with a2 the angle
#   of W2 from x (counter-clockwise) and sin b2 = (41 - W2 cos a2) / L2. W2 swings from -20.1 to
#   10.4 degrees, where |41 - 41.5 cos a2| <= 2.1 < 16: it always assembles. The needle point N
#   is 55 below the block's pin G; it travels from 8.30 above y = 0 to 13.34 below (stroke 21.64).
# - The lower gripper: a second crank pin D = (-6, 8) on the main shaft (R2 10, 36.87 degrees ahead
#   of R1), link L3 55 to the rocker W3 24 about F = (-10, -55) (Grashof: 10 + 55.90 < 55 + 24, a
#   crank-rocker; W3 swings 49.9 degrees); W4 20 on the same body, 77.32 degrees behind W3 ((9/41,
#   -40/41)); link L4 42 to W5 22 about K = (30, -60), the gripper's rocker, its point P 52 from K
#   on the line K -> M. W4 - L4 - W5 on |FK| = 40.31 (eq. 4a) is Grashof with W4 shortest
#   (20 + 42 < 22 + 40.31), so W5 follows W4's 49.9 degree swing without a dead point
#   (transmission angle 57 to 101 degrees); W5 swings 45.7 degrees. P crosses the needle's line
#   x = 41 going right at crank 183 degrees, 26 degrees after the needle's lowest position.
OV_R1, OV_L1, OV_W1, OV_W2, OV_L2 = D("7.5"), D(67), D("28.5"), D("41.5"), D(16)
OV_H, OV_XS, OV_NEEDLE = (D(0), D("71.8")), D(41), D(55)
OV_PLATE = D(0)  # the plate's level (the paper gives none)
OV_PHASE2 = (D(24) / 25, D(7) / 25)  # W2 from W1
OV_D, OV_F, OV_K = (D(-6), D(8)), (D(-10), D(-55)), (D(30), D(-60))
OV_L3, OV_W3, OV_W4, OV_L4, OV_W5, OV_P = D(55), D(24), D(20), D(42), D(22), D(52)
OV_PHASE4 = (D(9) / 41, D(-40) / 41)  # W4 from W3


def turned(c, p, rot, scale):
    """c + scale * (p - c) turned by rot = (cos, sin)."""
    v = (p[0] - c[0], p[1] - c[1])
    return (c[0] + scale * (rot[0] * v[0] - rot[1] * v[1]),
            c[1] + scale * (rot[1] * v[0] + rot[0] * v[1]))


def overedge_sketch():
    A = (D(0), OV_R1)
    B = circles(A, OV_L1, OV_H, OV_W1, left=False)  # W1 to the right of H, pointing down
    C = turned(OV_H, B, OV_PHASE2, OV_W2 / OV_W1)
    dx = OV_XS - C[0]
    G = (OV_XS, C[1] - (OV_L2 * OV_L2 - dx * dx).sqrt())  # the needle arm below W2's end
    N = (OV_XS, G[1] - OV_NEEDLE)
    E = circles(OV_D, OV_L3, OV_F, OV_W3, left=False)
    Q = turned(OV_F, E, OV_PHASE4, OV_W4 / OV_W3)
    M = circles(Q, OV_L4, OV_K, OV_W5, left=True)  # W5 up from K
    P = along(OV_K, M, OV_W5, OV_P)
    return {"A": A, "B": B, "C": C, "G": G, "N": N, "E": E, "Q": Q, "M": M, "P": P}


def overedge_file(s):
    O, H, F, K = (0, 0), OV_H, OV_F, OV_K
    return linkage_file(
        "Overedge needle arm (seed 004, planar part) and lower gripper on a second crank",
        bodies(
            ("ground", 1, {"O": O, "H": H, "F": F, "K": K}, {"u": [(41, 75), (41, 30)]}),
            ("main", 2, {"O": O, "A": s["A"], "D": OV_D}, None),
            ("needlerod", 3, {"A": s["A"], "B": s["B"]}, None),
            ("needlerock", 4, {"H": H, "B": s["B"], "C": s["C"]}, None),
            ("needlelink", 5, {"C": s["C"], "G": s["G"]}, None),
            ("needlearm", 6, {"G": s["G"], "N": s["N"]}, None),
            ("gripperrod", 7, {"D": OV_D, "E": s["E"]}, None),
            ("gripperrock", 8, {"F": F, "E": s["E"], "Q": s["Q"]}, None),
            ("gripperlink", 9, {"Q": s["Q"], "M": s["M"]}, None),
            ("gripper", 10, {"K": K, "M": s["M"], "P": s["P"]}, None),
        ),
        [
            pin("ground.O", "main.O"),
            pin("main.A", "needlerod.A"),
            pin("needlerod.B", "needlerock.B"),
            pin("needlerock.H", "ground.H"),
            pin("needlerock.C", "needlelink.C"),
            pin("needlelink.G", "needlearm.G"),
            {"type": "slider", "a": "needlearm.G", "slot": "ground.u"},
            pin("main.D", "gripperrod.D"),
            pin("gripperrod.E", "gripperrock.E"),
            pin("gripperrock.F", "ground.F"),
            pin("gripperrock.Q", "gripperlink.Q"),
            pin("gripperlink.M", "gripper.M"),
            pin("gripper.K", "ground.K"),
        ],
        {"joint": 0, "rpm": 6000, "direction": "ccw"},
        ["needlearm.N", "gripper.P"],
        # The needle point below the plate (y = 0, our plate level) and the gripper point past
        # the needle's line, the slot's x = 41, going right (it crosses the line going right
        # after the needle's lowest position). No conflict: their overlap is the loop-taking.
        {"windows": [f"needle=needlearm.N:y<{plain(float(OV_PLATE))}",
                     f"gripper=gripper.P:x>{plain(float(OV_XS))}"]})


def overedge_numbers():
    """Printed for README.md and the comments above: the swings, the needle's travel and where the
    gripper point crosses the needle's line, sampled every 0.01 degree (floats)."""
    def at(deg):
        t = math.radians(deg)
        A = (D(-7.5 * math.sin(t)), D(7.5 * math.cos(t)))
        B = circles(A, OV_L1, OV_H, OV_W1, left=False)
        C = turned(OV_H, B, OV_PHASE2, OV_W2 / OV_W1)
        dx = OV_XS - C[0]
        Gy = C[1] - (OV_L2 * OV_L2 - dx * dx).sqrt()
        Dp = (D(-6 * math.cos(t) - 8 * math.sin(t)), D(-6 * math.sin(t) + 8 * math.cos(t)))
        E = circles(Dp, OV_L3, OV_F, OV_W3, left=False)
        Q = turned(OV_F, E, OV_PHASE4, OV_W4 / OV_W3)
        M = circles(Q, OV_L4, OV_K, OV_W5, left=True)
        P = along(OV_K, M, OV_W5, OV_P)
        ang = lambda c, p: math.degrees(math.atan2(float(p[1] - c[1]), float(p[0] - c[0])))
        return ang(OV_H, C), float(Gy - OV_NEEDLE), ang(OV_F, E), ang(OV_K, M), float(P[0])
    rows = [at(k / 100) for k in range(36000)]
    for i, what in enumerate(("a2", "needle y", "a3", "a5")):
        v = [r[i] % 360 if what == "a3" else r[i] for r in rows]
        print(f"  {what}: {min(v):.4f} to {max(v):.4f}")
    low = min(range(36000), key=lambda k: rows[k][1])
    cross = [k / 100 for k in range(1, 36000) if rows[k - 1][4] < 41 <= rows[k][4]]
    print(f"  needle lowest at crank {low / 100} deg; gripper point crosses x = 41 going right at "
          f"{cross} deg")


def main():
    s = lockstitch_sketch()
    write("lockstitch-arm-shaft.linkage.json", lockstitch_file(s))
    print("lockstitch-arm-shaft: " + ", ".join(f"{k} = {tuple(rounded(v))}" for k, v in s.items()))
    lockstitch_timing()
    f = feed_sketch()
    write("lockstitch-machine.linkage.json", lockstitch_machine_file(s, f))
    print("lockstitch-machine: " + ", ".join(f"{k} = {tuple(rounded(v))}" for k, v in f.items()))
    write("gear-four-bar.linkage.json", gear_four_bar_file())
    print("gear-four-bar: the four-bar-crank-rocker four-bar on a gear, pinion at (-45, 0)")
    write("planet-epicycloid.linkage.json", planet_file())
    print("planet-epicycloid: sun 20, planet 10, P = (40, 0)")
    A, B = curved_guide_sketch()
    write("curved-guide.linkage.json", curved_guide_file())
    print(f"curved-guide: A = {tuple(rounded(A))}, B = {tuple(rounded(B))}")
    o = overedge_sketch()
    write("overedge-needle-arm.linkage.json", overedge_file(o))
    print("overedge-needle-arm: " + ", ".join(f"{k} = {tuple(rounded(v))}" for k, v in o.items()))
    overedge_numbers()


if __name__ == "__main__":
    main()
