#!/usr/bin/env python3
"""Writes the cam examples (see README.md):

  cam-translating-roller   a cam on a shaft lifting a translating roller follower with an
                           offset, against a return spring (a constant load) and gravity
                           (dimensions, masses and speed ours)
  lockstitch-cams          a lockstitch machine's arm shaft and lower shaft (belted 1:1) with a
                           thread take-up cam and a feed-lift cam, each with an oscillating
                           roller follower, and the needle bar for the timing (dimensions ours)
  chainstitch-looper-cam   a chain-stitch machine's looper rocked by a cam through a flat-faced
                           oscillating follower (dimensions ours)

Every follower is drawn at its lowest position (s = 0), as the format requires. The translating
one: its roller centre b on the slot's line at sqrt((base + roller)^2 - e^2) from the foot of the perpendicular from the cam's
centre. base 33 + roller 8 = 41 and the offset e = 9 make that 40, a whole number, so the file is
exactly closed. The oscillating ones: b straight above the cam's centre at base + roller (or
the base, for a flat face), whole numbers.

Run from anywhere:  python3 resources/examples/cams.py
"""

import math

from generate import linkage_file, write
from machines import NEEDLE, NL, NR, PLATE_Y, bodies, pin, plain

BASE, ROLLER, OFFSET = 33, 8, 9
RISE = 8


def translating_roller_file():
    lowest = math.isqrt((BASE + ROLLER) ** 2 - OFFSET ** 2)
    assert lowest * lowest == (BASE + ROLLER) ** 2 - OFFSET ** 2
    data = linkage_file(
        "Cam and translating roller follower (offset)",
        [
            {"name": "ground", "ground": True, "number": 1, "points": {"O": [0, 0]},
             "slots": {"guide": [[OFFSET, 30], [OFFSET, 90]]}},
            {"name": "cam", "number": 2, "points": {"O": [0, 0]},
             "mass": {"kg": 0.2, "com": [0, 0], "j_kg_mm2": 100}},
            {"name": "follower", "number": 3,
             "points": {"R": [OFFSET, lowest], "T": [OFFSET, lowest + 40]},
             "mass": {"kg": 0.05, "com": [OFFSET, lowest + 20], "j_kg_mm2": 8}},
        ],
        [
            {"type": "pin", "a": "ground.O", "b": "cam.O"},
            {"type": "slider", "a": "follower.R", "slot": "ground.guide"},
            {"type": "cam", "a": "cam.O", "b": "follower.R", "base_mm": BASE,
             "roller_mm": ROLLER, "motion": [
                 {"to_deg": 100, "rise_mm": RISE, "law": "cycloidal"},
                 {"to_deg": 160},
                 {"to_deg": 280, "rise_mm": -RISE, "law": "polynomial-345"},
                 {"to_deg": 360}]},
        ],
        {"joint": 0, "rpm": 1200, "direction": "ccw"},
        ["follower.T"])
    data["gravity"] = [0, -9.81]
    data["loads"] = [{"point": "follower.T", "force_N": [0, -20]}]
    return data


# ----------------------------------------------------------------------------------------------
# The lockstitch machine's shafts (machines.py, lockstitch-machine): the arm shaft O = (0, 0),
# 1200 rpm ccw, and the lower shaft S = (-60, -225) belted 1:1 (gear, ratio +1); the needle bar's
# slider-crank on the arm shaft as there (crank 16 straight up at crank 0, the needle's top dead
# centre; rod 45; the needle point N 131 below the rod's pin), for the timing.
#
# Both followers are levers whose roller rises (moves away from the cam) as the part they drive
# goes down: s = 0, the drawing, is the take-up eye at the top and the feed dog at the top, each
# in a dwell that contains crank 0 (the format draws s = 0; the programmes start there).
#
# Take-up: the lever pivots at P = (32, 31) above the arm shaft; its roller arm 32 reaches back
# to the roller centre R = (0, 31) on the cam (base 24, roller 7), its eye E 90 away on the
# other side (P + (72, 54)). A rise turns it clockwise: R up, E down (the lever gives thread).
O, S = (0, 0), (-60, -225)
TU_BASE, TU_ROLLER = 24, 7
TU_P, TU_EYE = (32, 31), (72, 54)
TU_MOTION = [
    (40, None, None),                # dwell: the stitch set, the needle going down to the cloth
    (180, 8, "polynomial-345"),      # thread for the needle going through the cloth
    (290, 16, "modified-sine"),      # the hook (206 deg) carrying the loop round the bobbin
    (300, None, None),               # the loop at its largest: the hook casts it off
    (360, -24, "cycloidal"),         # pull the thread up and set the stitch, quickly
]
# Feed lift: a rocker about H = (-35, -205) on the lower shaft's cam (base 15, roller 5): its
# roller arm 25 reaches back to R = (-60, -205) over the cam, its lift arm 20 forward to F =
# (-15, -205), under the feed bar's fork. A rise turns it clockwise: R up, F down (the dog
# drops). The dog is up (s = 0) from 300 through 0 to 60, down (s = 6 deg: F 2.09 mm lower) from
# 120 to 240; the plate is taken 1 mm below the dog's top: the dog is above it for half a turn.
FL_BASE, FL_ROLLER = 15, 5
FL_H, FL_LIFT = (-35, -205), (20, 0)
FL_RISE = 6
FL_MOTION = [
    (60, None, None),                   # the dog up: the feed moves the cloth (needle out)
    (120, FL_RISE, "cycloidal"),        # the dog drops under the plate before the needle enters
    (240, None, None),                  # the dog down while the needle is in the cloth
    (300, -FL_RISE, "cycloidal"),       # the dog comes up after the needle has left the cloth
    (360, None, None),
]


def motion(segments, unit):
    out = []
    for to, rise, law in segments:
        seg = {"to_deg": to}
        if rise is not None:
            seg[unit] = rise
            seg["law"] = law
        out.append(seg)
    return out


def lockstitch_cams_file():
    A, B = (0, NR), (0, NR - NL)
    N = (0, B[1] - NEEDLE)
    tu_r = (O[0], O[1] + TU_BASE + TU_ROLLER)
    tu_e = (TU_P[0] + TU_EYE[0], TU_P[1] + TU_EYE[1])
    fl_r = (S[0], S[1] + FL_BASE + FL_ROLLER)
    fl_f = (FL_H[0] + FL_LIFT[0], FL_H[1] + FL_LIFT[1])
    data = linkage_file(
        "Lockstitch machine's cams: thread take-up on the arm shaft, feed lift on the lower shaft",
        bodies(
            ("ground", 1, {"O": O, "P": TU_P, "S": S, "H": FL_H},
             {"needle": [(0, -20), (0, -170)]}),
            ("armshaft", 2, {"O": O, "A": A}, None),
            ("rod", 3, {"A": A, "B": B}, None),
            ("needlebar", 4, {"B": B, "N": N}, None),
            ("takeup", 5, {"P": TU_P, "R": tu_r, "E": tu_e}, None),
            ("lowershaft", 6, {"S": S}, None),
            ("feedlift", 7, {"H": FL_H, "R": fl_r, "F": fl_f}, None),
        ),
        [
            pin("ground.O", "armshaft.O"),
            pin("armshaft.A", "rod.A"),
            pin("rod.B", "needlebar.B"),
            {"type": "slider", "a": "needlebar.B", "slot": "ground.needle"},
            pin("ground.P", "takeup.P"),
            {"type": "cam", "a": "armshaft.O", "b": "takeup.R", "base_mm": TU_BASE,
             "roller_mm": TU_ROLLER, "motion": motion(TU_MOTION, "rise_deg")},
            pin("ground.S", "lowershaft.S"),
            {"type": "gear", "a": "armshaft.O", "b": "lowershaft.S", "ratio": 1},
            pin("ground.H", "feedlift.H"),
            {"type": "cam", "a": "lowershaft.S", "b": "feedlift.R", "base_mm": FL_BASE,
             "roller_mm": FL_ROLLER, "motion": motion(FL_MOTION, "rise_deg")},
        ],
        {"joint": 0, "rpm": 1200, "direction": "ccw"},
        ["needlebar.N", "takeup.E", "feedlift.F"],
        {"windows": [f"needle=needlebar.N:y<{plain(float(PLATE_Y))}",
                     f"feed=feedlift.F:y>{plain(fl_f[1] - 1)}"],
         "conflicts": [["needle", "feed"]]})
    return data


# ----------------------------------------------------------------------------------------------
# A chain-stitch looper's cam (ours): the looper shaft's cam C = (0, 0), 1200 rpm ccw (crank 0 the
# needle's top dead centre, its lowest at 180), rocks the looper's rocker about K = (45, 25)
# through a hardened flat shoe on the rocker's arm: the face, through b = (0, 25) at the base
# (25) from the cam's centre, is the line y = 25 as drawn, through the pivot. The looper's point
# L is 40 from K, straight down: L = (45, -15). A rise turns the rocker clockwise (b up, L to
# the left: the looper retreats); s = 0 is the looper at its foremost, in a dwell through crank 0.
LP_BASE, LP_K, LP_POINT = 30, (50, 30), (0, -50)
LP_RISE = 14
LP_MOTION = [
    (60, None, None),                           # foremost: the needle comes down behind it
    (150, LP_RISE, "modified-trapezoid"),       # retreat: the looper sheds the needle's loop
    (200, None, None),                          # back while the needle rises from its lowest
    (330, -LP_RISE, "polynomial-4567"),         # forward: its point enters the needle's loop
    (360, None, None),
]


def looper_file():
    b = (0, LP_BASE)
    point = (LP_K[0] + LP_POINT[0], LP_K[1] + LP_POINT[1])
    return linkage_file(
        "Chain-stitch looper cam: flat-faced oscillating follower",
        bodies(
            ("ground", 1, {"C": (0, 0), "K": LP_K}, None),
            ("loopershaft", 2, {"C": (0, 0)}, None),
            ("looper", 3, {"K": LP_K, "B": b, "L": point}, None),
        ),
        [
            pin("ground.C", "loopershaft.C"),
            pin("ground.K", "looper.K"),
            {"type": "cam", "a": "loopershaft.C", "b": "looper.B", "base_mm": LP_BASE,
             "flat": True, "motion": motion(LP_MOTION, "rise_deg")},
        ],
        {"joint": 0, "rpm": 1200, "direction": "ccw"},
        ["looper.L"])


def main():
    write("cam-translating-roller.linkage.json", translating_roller_file())
    print(f"cam-translating-roller: b = ({OFFSET}, 40), base {BASE}, roller {ROLLER}")
    write("lockstitch-cams.linkage.json", lockstitch_cams_file())
    write("chainstitch-looper-cam.linkage.json", looper_file())


if __name__ == "__main__":
    main()
