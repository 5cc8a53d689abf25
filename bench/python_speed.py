#!/usr/bin/env python3
"""A four-bar's coupler point P, V, A at many crank angles from Python, one call each
(docs/benchmarks.md, "Python"; docs/python.md):

  linkage    Model.sweep: the solver's tracked closed-form step, in C++, the GIL released
  pylinkage  pylinkage's own numba kernel, from a checkout given by --pylinkage DIR (or
             $PYLINKAGE_SRC; DIR/src/pylinkage or DIR/pylinkage), imported from there (no
             install): solver.simulation.simulate_with_kinematics on the arrays its kernel
             takes (a crank, a revolute joint, a fixed joint), and the same through its API
             (simulation.Linkage.step_fast_with_kinematics; the coupler point an RRRDyad:
             see pylinkage_api); rows skipped when no checkout is given
  numba      a four-bar loop written here (not pylinkage's code) and specialised to this one
             four-bar: what a hand-written numba loop can do with no per-joint dispatch
  numpy      the same closed form vectorised over all angles (one branch, fixed by a sign)

Each result is checked against the solver's to 1e-9 of its peak; the numbers are the medians
of --repeat runs. Usage:
  PYTHONPATH=build/python taskset -c 1 /usr/bin/python3 bench/python_speed.py \
      [--steps N] [--repeat R] [--pylinkage DIR]
"""
import argparse
import json
import math
import os
import statistics
import sys
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
                theta0=math.atan2(a[1] - o2[1], a[0] - o2[0]), b0=b, e0=e,
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


def pylinkage_import(top):
    """pylinkage's package from a checkout (its git tree or an unpacked release), or None with
    the reason. Imported in place: nothing installed, nothing copied into this repository."""
    if not top:
        return None, "no checkout given (--pylinkage DIR or $PYLINKAGE_SRC)"
    for root in (os.path.join(top, "src"), top):
        if os.path.isfile(os.path.join(root, "pylinkage", "__init__.py")):
            break
    else:
        return None, f"{top}: no pylinkage package in it (src/pylinkage or pylinkage)"
    if numba is None:
        return None, "numba not installed: its kernel would run as plain Python"
    sys.path.insert(0, root)
    try:
        import pylinkage
        from pylinkage.solver.simulation import simulate_with_kinematics
    except ImportError as e:
        return None, f"{top}: pylinkage does not import ({e})"
    return (pylinkage, simulate_with_kinematics), ""


def pylinkage_arrays(g, steps_rad):
    """The four-bar as the arrays pylinkage's kernel takes (solver/types.py): joints O2, O4
    static; A a crank about O2 turned steps_rad a step; B a revolute joint at |AB| from A and
    |BO4| from O4, the intersection nearest its last position; P a fixed joint at |AP| from A,
    at a constant angle from the direction A->B. Velocities and accelerations: the crank's
    omega (rad/s), alpha 0."""
    a0 = g["o2"] + g["r2"] * np.array([math.cos(g["theta0"]), math.sin(g["theta0"])])
    p0 = a0 + g["u"] * g["e0"] + g["v"] * np.array([-g["e0"][1], g["e0"][0]])
    positions = np.array([g["o2"], g["o4"], a0, g["b0"], p0])
    constraints = np.array([g["r2"], steps_rad, g["r3"], g["r4"], math.hypot(g["u"], g["v"]),
                            math.atan2(g["v"], g["u"])])
    types = np.array([0, 0, 1, 2, 3], np.int32)  # static, static, crank, revolute, fixed
    parents = np.array([[-1, -1, -1], [-1, -1, -1], [0, -1, -1], [2, 1, -1], [2, 3, -1]], np.int32)
    offsets = np.array([0, 0, 0, 2, 4], np.int32)
    return positions, constraints, types, parents, offsets, np.arange(5, dtype=np.int32)


def pylinkage_kernel(kernel, g, steps):
    """P, V, A of the coupler point after each of `steps` crank steps of 1 degree: one call of
    pylinkage's kernel (it returns every joint's; the copy of the start positions is ours)."""
    pos, con, types, parents, offsets, order = pylinkage_arrays(g, math.radians(1))
    p, v, a = kernel(pos, np.zeros((5, 2)), np.zeros((5, 2)), con, types, parents, offsets, order,
                     np.array([g["omega"]]), np.zeros(1), np.array([2], np.int32), steps, 1.0)
    return np.concatenate([p[:, 4], v[:, 4], a[:, 4]], axis=1)


def pylinkage_api(g):
    """The same four-bar through pylinkage's API (Ground, Crank, RRRDyad, simulation.Linkage).
    The coupler point is an RRRDyad at |AP| from A and |BP| from B, not a FixedDyad: its
    converter to the kernel's arrays (bridge/solver_conversion.py, linkage_to_solver_data)
    types every dyad as a revolute joint and reads distance1/distance2, which a FixedDyad lacks,
    so step_fast gives the fixed point NaN at every step."""
    from pylinkage.actuators import Crank
    from pylinkage.components import Ground
    from pylinkage.dyads import RRRDyad
    from pylinkage.simulation import Linkage
    pos, *_ = pylinkage_arrays(g, 0.0)
    o2, o4 = Ground(*pos[0], name="O2"), Ground(*pos[1], name="O4")
    crank = Crank(o2, g["r2"], angular_velocity=math.radians(1), initial_angle=g["theta0"])
    b = RRRDyad(crank.output, o4, g["r3"], g["r4"], x=pos[3][0], y=pos[3][1], name="B")
    p = RRRDyad(crank.output, b, math.hypot(g["u"], g["v"]), float(np.linalg.norm(pos[4] - pos[3])),
                x=pos[4][0], y=pos[4][1], name="P")
    model = Linkage([o2, o4, crank, b, p])
    model.set_input_velocity(crank, g["omega"])
    return model


def median(f, repeat):
    """The median wall and CPU times of `repeat` calls (CPU: this process's, all threads; on a
    shared machine the wall time also counts what others take), and the last result."""
    wall, cpu = [], []
    for _ in range(repeat):
        t, c = time.perf_counter(), time.process_time()
        r = f()
        wall.append(time.perf_counter() - t)
        cpu.append(time.process_time() - c)
    return (statistics.median(wall), statistics.median(cpu)), r


def first_call(f):
    """The seconds of a first call (numba compiles then, or loads its cache), and its result."""
    t0 = time.perf_counter()
    r = f()
    return time.perf_counter() - t0, r


def pylinkage_rows(top, g, o, check):
    """The pylinkage rows, or one row saying why there are none."""
    found, why = pylinkage_import(top)
    if found is None:
        return [(f"pylinkage: skipped, {why}", (float("nan"), float("nan")), 0.0)]
    pylinkage, kernel = found
    ver = getattr(pylinkage, "__version__", "?")
    compile_s, _ = first_call(lambda: pylinkage_kernel(kernel, g, 10))
    t, r = median(lambda: pylinkage_kernel(kernel, g, o.steps), o.repeat)
    rows = [(f"pylinkage {ver} kernel simulate_with_kinematics (1st call {compile_s:.2f} s)", t,
             check(r))]

    def api():
        p, v, a = pylinkage_api(g).step_fast_with_kinematics(iterations=o.steps)
        return np.concatenate([p[:, 4], v[:, 4], a[:, 4]], axis=1)
    t, r = median(api, o.repeat)
    rows.append((f"pylinkage {ver} Linkage.step_fast_with_kinematics", t, check(r)))
    return rows


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--steps", type=int, default=2_000_000)
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--pylinkage", default=os.environ.get("PYLINKAGE_SRC", ""),
                    help="a pylinkage checkout (default $PYLINKAGE_SRC); its rows skipped without")
    o = ap.parse_args()
    m = linkage.load("four-bar-crank-rocker")
    g = four_bar(m)
    # 1 degree of crank a step, as bench/ counts a step; from the first step, as pylinkage's
    # kernel turns its crank before it writes a row.
    deg = np.arange(1, o.steps + 1, dtype=float)
    phi = np.radians(deg)

    t, ref = median(lambda: m.sweep("coupler.P", deg), o.repeat)
    peak = np.abs(ref).max(axis=0)
    rows = [("linkage Model.sweep (C++, tracked, exact P V A)", t, 0.0)]

    def check(r):
        return float((np.abs(r - ref).max(axis=0) / peak).max())

    rows += pylinkage_rows(o.pylinkage, g, o, check)
    args = (g["o2"][0], g["o2"][1], g["o4"][0], g["o4"][1], g["r2"], g["r3"], g["r4"], g["u"],
            g["v"], g["theta0"], g["omega"], g["b0"][0], g["b0"][1])
    if numba is not None:
        kernel = numba.njit(cache=False, fastmath=False)(loop)
        out = np.empty((o.steps, 6))
        compile_s, _ = first_call(lambda: kernel(phi[:10], *args, out[:10]))
        t, _ = median(lambda: kernel(phi, *args, out), o.repeat)
        rows.append((f"numba {numba.__version__} loop hand-specialised here (compile {compile_s:.2f} s)",
                     t, check(out)))
    else:
        rows.append(("numba: not installed (apt-get install python3-numba)",
                     (float("nan"), float("nan")), 0.0))
    t, r = median(lambda: vectorised(phi, g), o.repeat)
    rows.append((f"numpy {np.__version__} vectorised closed form", t, check(r)))
    print(f"{o.steps} steps (1 degree each), four-bar-crank-rocker, coupler.P; median of {o.repeat}")
    print(f"{'':66s} {'wall s':>8s} {'M steps/s':>10s} {'ns/step':>8s} {'CPU M steps/s':>14s}"
          f" {'ns/step':>8s} {'max diff / peak':>16s}")
    for name, (wall, cpu), diff in rows:
        if math.isnan(wall):  # skipped: the reason alone
            print(name)
            continue
        print(f"{name:66s} {wall:8.4f} {o.steps / wall / 1e6:10.2f} {wall / o.steps * 1e9:8.1f}"
              f" {o.steps / cpu / 1e6:14.2f} {cpu / o.steps * 1e9:8.1f} {diff:16.2e}")
        assert not diff > 1e-9, f"{name}: differs from the solver by {diff:.2e} of the peak"


if __name__ == "__main__":
    main()
