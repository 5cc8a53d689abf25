#!/usr/bin/env python3
"""Writes the cam examples (see README.md):

  cam-translating-roller   a cam on a shaft lifting a translating roller follower with an
                           offset, against a return spring (a constant load) and gravity
                           (dimensions, masses and speed ours)

The follower is drawn at its lowest position, as the format requires: its roller centre b on the
slot's line at sqrt((base + roller)^2 - e^2) from the foot of the perpendicular from the cam's
centre. base 33 + roller 8 = 41 and the offset e = 9 make that 40, a whole number, so the file is
exactly closed.

Run from anywhere:  python3 resources/examples/cams.py
"""

import math

from generate import linkage_file, write

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


def main():
    write("cam-translating-roller.linkage.json", translating_roller_file())
    print(f"cam-translating-roller: b = ({OFFSET}, 40), base {BASE}, roller {ROLLER}")


if __name__ == "__main__":
    main()
