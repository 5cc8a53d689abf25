#!/usr/bin/env python3
"""A four-bar's coupler point P, V, A at many crank angles from Python, one call each
(docs/benchmarks.md, "Python"):

  linkage   Model.sweep: the solver's tracked closed-form step, in C++, the GIL released
  numba     a four-bar loop compiled by numba, written the way pylinkage's numba kernel
            (src/pylinkage/solver/{joints,velocity,acceleration,simulation}.py) works: the
            crank turned, the coupler-rocker pin at the intersection of two circles nearest to
            its last position, velocities and accelerations from the 2 x 2 systems of the
            differentiated distance constraints; specialised to one four-bar (no per-joint
            dispatch), so a bound on what pylinkage's general loop can do
  numpy     the same closed form vectorised over all angles (one branch, fixed by a sign)

Each result is checked against the solver's to 1e-9 of its peak; the numbers are the best of
--repeat runs. Usage: PYTHONPATH=build/python python3 bench/python_speed.py [--steps N]
"""
import argparse
import json
import math
import time

import numpy as np

import linkage

try:
    import numba
except ImportError:  # Debian: python3-numba (scripts/setup.sh --tests)
    numba = None


def four_bar(m):
    """The example's dimensions as the loops want them."""
    d = json.load(open(m.path))
    pts = {b["name"]: {k: np.array(v, float) for k, v in b["points"].items()} for b in d["bodies"]}
    o2, o4 = pts["ground"]["O2"], pts["ground"]["O4"]
    a, b, p = pts["coupler"]["A"], pts["coupler"]["B"], pts["coupler"]["P"]
    e = (b - a) / np.linalg.norm(b - a)
    n = np.array([-e[1], e[0]])
    return dict(o2=o2, o4=o4, r2=np.linalg.norm(a - o2), r3=np.linalg.norm(b - a),
                r4=np.linalg.norm(b - o4), u=(p - a) @ e, v=(p - a) @ n,
                theta0=math.atan2(a[1] - o2[1], a[0] - o2[0]), b0=b,
                omega=2 * math.pi * d["driver"]["rpm"] / 60)


def loop(phi, o2x, o2y, o4x, o4y, r2, r3, r4, u, v, theta0, omega, bx, by, out):
    """P, V, A of the coupler point at each crank angle phi (rad), tracked from (bx, by)."""
    for i in range(phi.shape[0]):
        c, s = math.cos(theta0 + phi[i]), math.sin(theta0 + phi[i])
        ax, ay = o2x + r2 * c, o2y + r2 * s
        avx, avy = -omega * r2 * s, omega * r2 * c
        aax, aay = -omega * omega * r2 * c, -omega * omega * r2 * s
        # Circle (A, r3) and circle (O4, r4): the intersection nearest the last B.
        dx, dy = o4x - ax, o4y - ay
        d2 = dx * dx + dy * dy
        d = math.sqrt(d2)
        l = (r3 * r3 - r4 * r4 + d2) / (2 * d)
        h = math.sqrt(max(r3 * r3 - l * l, 0.0))
        mx, my = ax + l * dx / d, ay + l * dy / d
        x1, y1 = mx - h * dy / d, my + h * dx / d
        x2, y2 = mx + h * dy / d, my - h * dx / d
        if (x1 - bx) ** 2 + (y1 - by) ** 2 <= (x2 - bx) ** 2 + (y2 - by) ** 2:
            bx, by = x1, y1
        else:
            bx, by = x2, y2
        # (B - A).(B' - A') = 0 and (B - O4).B' = 0; then the same differentiated again.
        a11, a12, a21, a22 = bx - ax, by - ay, bx - o4x, by - o4y
        det = a11 * a22 - a12 * a21
        r1 = a11 * avx + a12 * avy
        bvx, bvy = (r1 * a22) / det, (-r1 * a21) / det
        wx, wy = bvx - avx, bvy - avy
        s1 = a11 * aax + a12 * aay - (wx * wx + wy * wy)
        s2 = -(bvx * bvx + bvy * bvy)
        bax, bay = (s1 * a22 - a12 * s2) / det, (a11 * s2 - a21 * s1) / det
        # The coupler's angular velocity and acceleration from B relative to A.
        w3 = (a11 * wy - a12 * wx) / (r3 * r3)
        al3 = (a11 * (bay - aay) - a12 * (bax - aax)) / (r3 * r3)
        ex, ey = a11 / r3, a12 / r3
        px, py = u * ex - v * ey, u * ey + v * ex  # P - A
        out[i, 0], out[i, 1] = ax + px, ay + py
        out[i, 2], out[i, 3] = avx - w3 * py, avy + w3 * px
        out[i, 4] = aax - al3 * py - w3 * w3 * px
        out[i, 5] = aay + al3 * px - w3 * w3 * py


def vectorised(phi, g):
    """The closed form over all angles at once (the branch of the drawing: B left of A->O4)."""
    t = g["theta0"] + phi
    c, s, w = np.cos(t), np.sin(t), g["omega"]
    ax, ay = g["o2"][0] + g["r2"] * c, g["o2"][1] + g["r2"] * s
    avx, avy, aax, aay = -w * g["r2"] * s, w * g["r2"] * c, -w * w * g["r2"] * c, -w * w * g["r2"] * s
    dx, dy = g["o4"][0] - ax, g["o4"][1] - ay
    d2 = dx * dx + dy * dy
    d = np.sqrt(d2)
    l = (g["r3"] ** 2 - g["r4"] ** 2 + d2) / (2 * d)
    h = np.sqrt(np.maximum(g["r3"] ** 2 - l * l, 0))
    b0, o4 = g["b0"], g["o4"]
    a0 = g["o2"] + g["r2"] * np.array([math.cos(g["theta0"]), math.sin(g["theta0"])])
    side = np.sign((o4[0] - a0[0]) * (b0[1] - a0[1]) - (o4[1] - a0[1]) * (b0[0] - a0[0]))
    bx = ax + l * dx / d - side * h * dy / d
    by = ay + l * dy / d + side * h * dx / d
    a11, a12, a21, a22 = bx - ax, by - ay, bx - o4[0], by - o4[1]
    det = a11 * a22 - a12 * a21
    r1 = a11 * avx + a12 * avy
    bvx, bvy = r1 * a22 / det, -r1 * a21 / det
    wx, wy = bvx - avx, bvy - avy
    s1 = a11 * aax + a12 * aay - (wx * wx + wy * wy)
    s2 = -(bvx * bvx + bvy * bvy)
    bax, bay = (s1 * a22 - a12 * s2) / det, (a11 * s2 - a21 * s1) / det
    r3 = g["r3"]
    w3 = (a11 * wy - a12 * wx) / r3 ** 2
    al3 = (a11 * (bay - aay) - a12 * (bax - aax)) / r3 ** 2
    ex, ey = a11 / r3, a12 / r3
    px, py = g["u"] * ex - g["v"] * ey, g["u"] * ey + g["v"] * ex
    return np.stack([ax + px, ay + py, avx - w3 * py, avy + w3 * px,
                     aax - al3 * py - w3 * w3 * px, aay + al3 * px - w3 * w3 * py], axis=1)


def best(f, repeat):
    """The best wall and CPU times of `repeat` calls (CPU: this process's, all threads; on a
    shared machine the wall time also counts what others take)."""
    wall, cpu = [], []
    for _ in range(repeat):
        t, c = time.perf_counter(), time.process_time()
        r = f()
        wall.append(time.perf_counter() - t)
        cpu.append(time.process_time() - c)
    return (min(wall), min(cpu)), r


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--steps", type=int, default=2_000_000)
    ap.add_argument("--repeat", type=int, default=5)
    o = ap.parse_args()
    m = linkage.load("four-bar-crank-rocker")
    g = four_bar(m)
    deg = np.arange(o.steps, dtype=float)  # 1 degree of crank a step, as bench/ counts a step
    phi = np.radians(deg)

    t, ref = best(lambda: m.sweep("coupler.P", deg), o.repeat)
    peak = np.abs(ref).max(axis=0)
    rows = [("linkage Model.sweep (C++, tracked, exact P V A)", t, 0.0)]

    def check(r):
        return float((np.abs(r - ref).max(axis=0) / peak).max())

    args = (g["o2"][0], g["o2"][1], g["o4"][0], g["o4"][1], g["r2"], g["r3"], g["r4"], g["u"],
            g["v"], g["theta0"], g["omega"], g["b0"][0], g["b0"][1])
    if numba is not None:
        kernel = numba.njit(cache=False, fastmath=False)(loop)
        out = np.empty((o.steps, 6))
        t0 = time.perf_counter()
        kernel(phi[:10], *args, out[:10])
        compile_s = time.perf_counter() - t0
        t, _ = best(lambda: kernel(phi, *args, out), o.repeat)
        rows.append((f"numba {numba.__version__} loop, pylinkage's way (compile {compile_s:.2f} s)",
                     t, check(out)))
    else:
        rows.append(("numba: not installed (apt-get install python3-numba)",
                     (float("nan"), float("nan")), 0.0))
    t, r = best(lambda: vectorised(phi, g), o.repeat)
    rows.append((f"numpy {np.__version__} vectorised closed form", t, check(r)))
    print(f"{o.steps} steps (1 degree each), four-bar-crank-rocker, coupler.P; best of {o.repeat}")
    print(f"{'':60s} {'wall s':>8s} {'M steps/s':>10s} {'ns/step':>8s} {'CPU M steps/s':>14s}"
          f" {'ns/step':>8s} {'max diff / peak':>16s}")
    for name, (wall, cpu), diff in rows:
        print(f"{name:60s} {wall:8.4f} {o.steps / wall / 1e6:10.2f} {wall / o.steps * 1e9:8.1f}"
              f" {o.steps / cpu / 1e6:14.2f} {cpu / o.steps * 1e9:8.1f} {diff:16.2e}")
        assert not diff > 1e-9, f"{name}: differs from the solver by {diff:.2e} of the peak"


if __name__ == "__main__":
    main()
