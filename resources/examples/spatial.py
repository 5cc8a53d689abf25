#!/usr/bin/env python3
"""The spatial examples (docs/spatial.md), written as the program saves them: run
`python3 resources/examples/spatial.py` (no dependencies). Numbers are Python floats, whose repr
reads back to the same double."""
import math

from generate import linkage_file, write


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


def main():
    write("rssr-crank-rocker.linkage.json", rssr_file())
    print("rssr-crank-rocker: crank 7.5 at 30 degrees, rocker 28.5 at 160 degrees, rho 23")


if __name__ == "__main__":
    main()
