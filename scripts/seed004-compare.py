#!/usr/bin/env python3
"""Seed 004's needle arm in space against its planar stand-in, and the paper's Lagrange fits
against the exact derivatives, from the program's own motion tables (`linkage-cli analyze`,
17 significant digits): the numbers of docs/seed004.md. No dependencies beyond python3.

    scripts/seed004-compare.py [BUILD_DIR]      (default: build)

- overedge-machine (the paper's spatial needle arm): U = (G - H) . u along the needle arm's
  line, u = (0, -cos 23, sin 23); W1's angle in the rockers' plane.
- overedge-needle-arm (the planar stand-in): U = -y of G (its slot is vertical, u down); W1's
  angle about H = (0, 71.8).
Both at 6000 rpm. The needle curves are compared from each one's top position (U smallest), as a
designer lays two needle curves over each other; the rockers by their swings.
"""
import csv
import io
import math
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RHO = math.radians(23)
H3, U3 = (111, 134.5, 53.5), (0, -math.cos(RHO), math.sin(RHO))
X3, Y3 = (1, 0, 0), (0, -math.cos(RHO), math.sin(RHO))


def table(cli, model, steps):
    out = subprocess.run([cli, "analyze", model, "--steps", str(steps), "--point", "needlearm.G",
                          "--point", "needlerock.B"], check=True, capture_output=True, text=True)
    return list(csv.DictReader(io.StringIO(out.stdout)))


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def spatial(rows):
    """U, U', U'' (mm, mm/s, mm/s^2) and W1's angle (degrees) a row."""
    out = []
    for r in rows:
        g = [float(r[f"needlearm.G.{c}_mm"]) for c in "xyz"]
        v = [float(r[f"needlearm.G.v{c}_mm_s"]) for c in "xyz"]
        a = [float(r[f"needlearm.G.a{c}_mm_s2"]) for c in "xyz"]
        b = [float(r[f"needlerock.B.{c}_mm"]) - h for c, h in zip("xyz", H3)]
        out.append((dot([p - h for p, h in zip(g, H3)], U3), dot(v, U3), dot(a, U3),
                    math.degrees(math.atan2(dot(b, Y3), dot(b, X3)))))
    return out


def planar(rows):
    out = []
    for r in rows:
        bx, by = float(r["needlerock.B.x_mm"]), float(r["needlerock.B.y_mm"]) - 71.8
        out.append((-float(r["needlearm.G.y_mm"]), -float(r["needlearm.G.vy_mm_s"]),
                    -float(r["needlearm.G.ay_mm_s2"]), math.degrees(math.atan2(by, bx)) % 360))
    return out


def from_top(u):
    """The needle curve from its top (smallest U), a sample a step: U - U_top, and where."""
    n = len(u) - 1  # the last row repeats the first
    top = min(range(n), key=lambda i: u[i][0])
    return [u[(top + i) % n][0] - u[top][0] for i in range(n + 1)], top


def rocker_from_end(u):
    """W1's distance (degrees) from the end of its swing where the needle arm is highest."""
    n = len(u) - 1
    top = min(range(n), key=lambda i: u[i][0])
    ends = (min(r[3] for r in u[:n]), max(r[3] for r in u[:n]))
    end = min(ends, key=lambda e: abs(u[top][3] - e))
    at = min(range(n), key=lambda i: abs(u[i][3] - end))
    return [abs(u[(at + i) % n][3] - end) for i in range(n + 1)]


def describe(name, u, steps):
    n = len(u) - 1
    swing = [r[3] for r in u[:n]]
    top = min(range(n), key=lambda i: u[i][0])
    low = max(range(n), key=lambda i: u[i][0])
    down = (low - top) % n * 360 / steps
    print(f"{name}: stroke {max(r[0] for r in u) - min(r[0] for r in u):.4f} mm, W1 swings "
          f"{max(swing) - min(swing):.4f} deg, top at crank {top * 360 / steps:.1f}, lowest "
          f"{down:.1f} deg later, up again {360 - down:.1f}; peak |U'| {max(abs(r[1]) for r in u):.1f}"
          f" mm/s, |U''| {max(abs(r[2]) for r in u):.4g} mm/s^2")


def lagrange(u, steps, omega):
    """Worst errors of the central 5- and 7-point Lagrange derivatives of the sampled U against
    the exact U' and U'', relative to their peaks over the turn."""
    n = steps
    y, v, a = [r[0] for r in u[:n]], [r[1] for r in u[:n]], [r[2] for r in u[:n]]
    h = 2 * math.pi / n / omega
    d5, s5 = (1, -8, 0, 8, -1), (-1, 16, -30, 16, -1)
    d7, s7 = (-1, 9, -45, 0, 45, -9, 1), (2, -27, 270, -490, 270, -27, 2)
    pv, pa = max(map(abs, v)), max(map(abs, a))
    err = [0, 0, 0, 0]
    for i in range(n):
        f5 = sum(c * y[(i + j - 2) % n] for j, c in enumerate(d5)) / (12 * h)
        g5 = sum(c * y[(i + j - 2) % n] for j, c in enumerate(s5)) / (12 * h * h)
        f7 = sum(c * y[(i + j - 3) % n] for j, c in enumerate(d7)) / (60 * h)
        g7 = sum(c * y[(i + j - 3) % n] for j, c in enumerate(s7)) / (180 * h * h)
        for k, e in enumerate((abs(f5 - v[i]) / pv, abs(g5 - a[i]) / pa, abs(f7 - v[i]) / pv,
                               abs(g7 - a[i]) / pa)):
            err[k] = max(err[k], e)
    return err


def main():
    build = sys.argv[1] if len(sys.argv) > 1 else "build"
    cli = os.path.join(ROOT, build, "app", "linkage-cli")
    steps = 3600
    s = spatial(table(cli, "overedge-machine", steps))
    p = planar(table(cli, "overedge-needle-arm", steps))
    describe("overedge-machine (in space)", s, steps)
    describe("overedge-needle-arm (planar stand-in)", p, steps)
    cs, ts = from_top(s)
    cp, tp = from_top(p)
    diff = [abs(x - y) for x, y in zip(cs, cp)]
    worst = max(range(len(diff)), key=diff.__getitem__)
    print(f"needle curves from their tops: largest difference {diff[worst]:.4f} mm, "
          f"{worst * 360 / steps:.1f} deg after the top")
    # The rockers alike: W1's angle from one end of its swing, over the crank from there (each
    # rocker's own sense: the distance from that end), the part of the difference that is space.
    rs, rp = rocker_from_end(s), rocker_from_end(p)
    dr = [abs(x - y) for x, y in zip(rs, rp)]
    worst = max(range(len(dr)), key=dr.__getitem__)
    print(f"W1 from the same end of its swing: largest difference {dr[worst]:.4f} deg, "
          f"{worst * 360 / steps:.1f} deg after it")
    omega = 6000 * 2 * math.pi / 60
    vs = [s[(ts + i) % steps][1] for i in range(steps)]
    vp = [p[(tp + i) % steps][1] for i in range(steps)]
    dv = max(abs(x - y) for x, y in zip(vs, vp))
    print(f"  velocities from the tops: largest difference {dv:.1f} mm/s "
          f"({dv / max(map(abs, vs)):.3f} of the spatial peak)")
    print("Lagrange fits of the spatial needle arm's U (N samples a turn): worst error / peak")
    print("| N | 5 points, velocity | 5 points, acceleration | 7 points, velocity | "
          "7 points, acceleration |")
    print("|---|---|---|---|---|")
    for n in (36, 72, 360, 3600):
        rows = spatial(table(cli, "overedge-machine", n))
        e = lagrange(rows, n, omega)
        print(f"| {n} | " + " | ".join(f"{x:.1e}" for x in e) + " |")


if __name__ == "__main__":
    main()
