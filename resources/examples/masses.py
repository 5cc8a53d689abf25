#!/usr/bin/env python3
"""Writes the examples with masses, gravity and loads (see README.md, "Examples with masses"):

  slider-crank-22a-masses     the 22-A central slider-crank needle bar (seed 002) with masses
  wanzer-inversion-2-masses   the Wanzer needle bar (seed 000) with masses, gravity and a needle
                              penetration load around its bottom dead centre
  drop-feed                   a drop feed in its plane (seed 003 gives no dimensions: ours),
                              lift and advance from two eccentrics on the lower shaft, belted
                              1:1 from the arm shaft

Neither seed gives a mass; every mass, centre of mass and moment of inertia here is our choice,
representative of the parts (README.md says which and why). The drawings of the first two are
those of slider-crank-22a-lambda-0.5 and wanzer-inversion-2 (generate.py), unchanged but for the
needle point added to the Wanzer needle bar; the drop feed is drawn at crank angle 0 with exact
decimal coordinates, so nothing is solved there. Each file is laid out as the program saves it.

Run from anywhere:  python3 resources/examples/masses.py
"""

from decimal import Decimal

from generate import plain, slider_crank_file, wanzer_file, wanzer_sketch, write

D = Decimal


def mass(kg, com, j):
    """A body's "mass" as the program writes it: kg, centre of mass (sketch), J about it."""
    return {"kg": plain(kg), "com": [plain(c) for c in com], "j_kg_mm2": plain(j)}


def with_masses(data, masses):
    """The file's bodies with the given masses (by body name) added after their slots."""
    for body in data["bodies"]:
        if body["name"] in masses:
            body["mass"] = masses[body["name"]]
    return data


# ----------------------------------------------------------------------------------------------
# 22-A central slider-crank (seed 002: r = 15, l = 30, lambda = 0.5). The paper gives no masses
# and no speed. Ours: the crank balanced on its shaft (its centre of mass on the axis), a light rod
# (40 g, its centre of mass a third of the way from the crank pin), the needle bar with its clamp
# and needle 100 g; 3000 rpm, the top of the 1,200 to 3,000 stitches a minute of industrial
# machines. No gravity: the seed's quantity is the inertia force.
def slider_crank_masses_file():
    data = slider_crank_file("0.5", 30)
    data["name"] = "Central slider-crank needle bar (22-A), lambda = 0.5, with masses"
    data["driver"]["rpm"] = 3000
    return with_masses(data, {
        "crank": mass(0.15, (0, 0), 60),
        "rod": mass(0.04, (0, 25), 3),
        "needlebar": mass(0.1, (0, 75), 40),
    })


# ----------------------------------------------------------------------------------------------
# Wanzer needle bar, inversion 2 (seed 000), at its 240 rpm cw, with masses (ours), gravity, and
# the needle's penetration force on the needle point N, 30 mm below G (ours): 5 N up while the
# point goes down through the material (from 10 mm above its lowest, at crank 47 degrees, to the
# bottom dead centre, 81.5 degrees), 2 N down (friction) while it rises out (to 233 degrees).
NEEDLE_BELOW_G = 30
PENETRATION = ({"force_N": [0, 5], "from_deg": 47, "to_deg": 81.5},
               {"force_N": [0, -2], "from_deg": 81.5, "to_deg": 233})


def wanzer_masses_file():
    E, F, G, _, _ = wanzer_sketch(2, (20, 20, -40))
    data = wanzer_file(2, E, F, G)
    data["name"] = "Wanzer needle bar, inversion 2, with masses and the needle's load"
    N = [0, plain(float(D(repr(G[1])) - NEEDLE_BELOW_G))]
    needlebar = next(b for b in data["bodies"] if b["name"] == "needlebar")
    needlebar["points"]["N"] = N
    data["outputs"]["points"] = ["needlebar.G", "needlebar.N"]
    # The triangle's centre of mass at its centroid, J of a uniform triangle about it:
    # m (a^2 + b^2 + c^2) / 36 with the sides 16, 56, 62.
    centroid = [plain(float(sum(D(repr(p[i])) for p in (E, F, G)) / 3)) for i in range(2)]
    j_triangle = float(D("0.04") * (16 ** 2 + 56 ** 2 + 62 ** 2) / 36)
    data = with_masses(data, {
        "disk": mass(0.25, (0, 0), 120),
        "triangle": mass(0.04, centroid, round(j_triangle, 3)),
        "slider4": mass(0.005, E, 0.1),
        "slider5": mass(0.005, F, 0.1),
        "needlebar": mass(0.06, (0, plain(float(D(repr(G[1])) - 10))), 20),
    })
    data["gravity"] = [0, -9.81]
    data["loads"] = [dict({"point": "needlebar.N"}, **load) for load in PENETRATION]
    return data


# ----------------------------------------------------------------------------------------------
# A drop feed in the plane across the shafts (x: the feed's direction, y: up), every dimension
# ours. The arm shaft M (the driver, 1200 rpm ccw as seed 003's machine) drives the lower shaft L
# by a 1:1 toothed belt. On the lower shaft, two eccentrics: the advance eccentric Ea (4.5 mm)
# works the feed rock shaft R through the rod Ea-P (a crank-rocker: its arm R-P 24 down, R-F 40
# up, so the feed bar's pin F swings 15 mm, seed 003's stitch length); the lift eccentric El
# (1.5 mm) lifts the feed bar through its strap El-C. The feed bar is pinned to the rock shaft's
# arm at F and to the lift strap at C; its feed dog's teeth D rise about 3.9 mm, up while they
# advance. Drawn at crank 0: both eccentrics straight up (in phase: the rock shaft reverses the
# advance, so the dog is highest in mid-advance), the dog at the top of its path.
FEED = {
    "M": (0, 220), "L": (0, 0), "R": (-70, 24),
    "Ea": (0, 4.5), "El": (0, 1.5), "P": (-70, 0), "F": (-70, 64), "C": (0, 50), "D": (20, 70),
}


def pin(a, b):
    return {"type": "pin", "a": a, "b": b}


def drop_feed_file():
    p = {k: [plain(x) for x in v] for k, v in FEED.items()}

    def body(name, number, points, m):
        out = {"name": name, "number": number, "points": {k: p[k] for k in points}}
        if m:
            out["mass"] = m
        return out

    return {
        "format": "linkage", "version": 1,
        "name": "Drop feed: lift and advance eccentrics on the lower shaft",
        "units": {"length": "mm"},
        "bodies": [
            {"name": "ground", "ground": True, "number": 1,
             "points": {k: p[k] for k in ("M", "L", "R")}},
            body("armshaft", 2, ("M",), None),
            body("lowershaft", 3, ("L", "Ea", "El"), mass(0.7, (0, 1), 40)),
            body("advancerod", 4, ("Ea", "P"), mass(0.09, (-25, 3), 45)),
            body("feedrock", 5, ("R", "P", "F"), mass(0.3, (-70, 30), 150)),
            body("liftstrap", 6, ("El", "C"), mass(0.05, (0, 15), 12)),
            body("feedbar", 7, ("F", "C", "D"), mass(0.25, (-20, 62), 200)),
        ],
        "joints": [
            pin("ground.M", "armshaft.M"),
            pin("ground.L", "lowershaft.L"),
            {"type": "gear", "a": "armshaft.M", "b": "lowershaft.L", "ratio": 1},
            pin("lowershaft.Ea", "advancerod.Ea"),
            pin("advancerod.P", "feedrock.P"),
            pin("feedrock.R", "ground.R"),
            pin("lowershaft.El", "liftstrap.El"),
            pin("feedrock.F", "feedbar.F"),
            pin("liftstrap.C", "feedbar.C"),
        ],
        "driver": {"joint": 0, "rpm": 1200, "direction": "ccw"},
        "outputs": {"points": ["feedbar.D"]},
    }


def main():
    write("slider-crank-22a-masses.linkage.json", slider_crank_masses_file())
    print("slider-crank-22a-masses: r = 15, l = 30, 3000 rpm; crank 0.15, rod 0.04, "
          "needle bar 0.1 kg")
    data = wanzer_masses_file()
    write("wanzer-inversion-2-masses.linkage.json", data)
    print("wanzer-inversion-2-masses: needle point N = "
          f"{data['bodies'][5]['points']['N']}, triangle's centre of mass "
          f"{data['bodies'][2]['mass']['com']}")
    write("drop-feed.linkage.json", drop_feed_file())
    print("drop-feed: " + ", ".join(f"{k} = {v}" for k, v in FEED.items()))


if __name__ == "__main__":
    main()
