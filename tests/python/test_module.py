"""The Python module against the command line (docs/python.md): the same solver, so the same
numbers to the last bit, parsed from the command line's 17 significant digits (which read back
to the same double). Run by ctest (tests/python/CMakeLists.txt) with the module on PYTHONPATH
and LINKAGE_CLI naming build/app/linkage-cli."""
import csv
import io
import json
import os
import subprocess
import threading
import time

import numpy as np
import pytest

import linkage

CLI = os.environ.get("LINKAGE_CLI", "linkage-cli")


def cli(*args, check=True):
    r = subprocess.run([CLI, *args], capture_output=True, text=True)
    if check:
        assert r.returncode == 0, r.stderr
    return r


def cli_table(*args):
    """A CSV of the command line as a header and an array of exactly parsed doubles."""
    rows = list(csv.reader(io.StringIO(cli(*args).stdout)))
    return rows[0], np.array([[float(v) for v in r] for r in rows[1:]])


def same_bits(a, b):
    """Bit for bit, but for the sign of zero: the command line writes -0 as 0."""
    a, b = np.asarray(a, dtype=float) + 0.0, np.asarray(b, dtype=float) + 0.0
    return a.shape == b.shape and a.tobytes() == b.tobytes()


@pytest.mark.parametrize("model, args, points", [
    ("wanzer-inversion-2", ["--steps", "360"], ["needlebar.G"]),
    ("four-bar-crank-rocker", ["--steps", "100", "--revs", "2", "--rpm", "123.5"],
     ["coupler.P", "rocker.B"]),
    ("overedge-machine", ["--steps", "72"], []),  # in space: x, y, z; the file's outputs
    ("slider-crank-22a-lambda-0.3", ["--steps", "7", "--revs", "3"], []),
])
def test_analyze_is_the_command_lines_table(model, args, points):
    header, table = cli_table("analyze", model, *args, *sum((["--point", p] for p in points), []))
    m = linkage.load(model)
    steps = int(args[1])
    revs = float(args[args.index("--revs") + 1]) if "--revs" in args else 1
    rpm = float(args[args.index("--rpm") + 1]) if "--rpm" in args else 0
    a = m.analyze(steps=steps, revs=revs, rpm=rpm, points=points)
    assert m.columns(points) == header
    assert same_bits(a, table)


def test_analyze_does_not_depend_on_earlier_queries():
    m = linkage.load("wanzer-inversion-2")
    first = m.analyze(steps=36, points=["needlebar.G"])
    m.instant_centres(123.4)
    m.sweep("needlebar.G", np.linspace(0, 700, 99))
    assert same_bits(m.analyze(steps=36, points=["needlebar.G"]), first)


def test_sweep_is_analyze_at_the_same_angles():
    m = linkage.load("four-bar-crank-rocker")
    a = m.analyze(steps=360, points=["coupler.P"])
    s = m.sweep("coupler.P", a[:, 1])
    assert s.shape == (361, 6)
    assert same_bits(s, a[:, 2:])


def test_sweep_in_space_is_analyze_in_the_world():
    m = linkage.load("overedge-machine")
    point = m.columns()[2].rsplit(".", 1)[0]
    a = m.analyze(steps=72, points=[point])
    s = m.sweep(point, a[:, 1])
    assert s.shape == (73, 9)
    assert same_bits(s, a[:, 2:])


def test_sweep_lets_other_threads_run():
    m = linkage.load("four-bar-crank-rocker")
    angles = np.linspace(0, 360 * 300, 3_000_000)
    done, ticks = [], [0]

    def work():
        done.append(m.sweep("coupler.P", angles))

    t = threading.Thread(target=work)
    start = time.perf_counter()
    t.start()
    while t.is_alive():
        ticks[0] += 1  # Python runs here only while the sweep has let go of the GIL
        time.sleep(0.001)
    t.join()
    assert done and done[0].shape == (3_000_000, 6)
    assert time.perf_counter() - start > 0.05  # long enough for the count to mean something
    assert ticks[0] > 10


def test_an_edit_while_a_sweep_runs_does_not_touch_it():
    m = linkage.load("four-bar-crank-rocker")
    angles = np.linspace(0, 360 * 50, 500_000)
    wants = []  # the sweep sees the model as it was at its call: one of these
    for crank in (16, 15, 20):
        m.set_dimension("crank.O2-A", crank)
        wants.append(m.sweep("coupler.P", angles))
    got = []
    t = threading.Thread(target=lambda: got.append(m.sweep("coupler.P", angles)))
    t.start()
    n = 0
    while t.is_alive():
        m.set_dimension("crank.O2-A", 15 + (n % 2))  # edits the model the sweep was called on
        n += 1
    t.join()
    assert n > 0
    # (Loosely: a design redrawn after other edits may differ in its last bits.)
    assert any(np.allclose(got[0], w, rtol=0, atol=1e-9 * np.abs(w).max()) for w in wants)


def test_instant_centres_are_the_command_lines():
    for model, angle in [("four-bar-crank-rocker", "30"), ("wanzer-inversion-2", "-47.5")]:
        want = json.loads(cli("ics", model, "--angle", angle, "--json").stdout)["centres"]
        got = linkage.load(model).instant_centres(float(angle))
        assert len(got) == len(want)
        for g, w in zip(got, want):
            for key in ("i", "j", "body_i", "body_j", "status", "determined", "at_infinity"):
                assert g[key] == w[key], (model, key, g, w)
            for key in ("x_mm", "y_mm", "dir_x", "dir_y"):
                assert (key in g) == (key in w and w[key] is not None)
                if key in g:
                    assert g[key] + 0.0 == w[key], (model, key, g, w)


def test_forces_are_the_command_lines():
    header, table = cli_table("dynamics", "wanzer-inversion-2-masses", "--steps", "12")
    row = dict(zip(header, table[1]))  # crank angle 30
    assert row["crank_deg"] == 30
    f = linkage.load("wanzer-inversion-2-masses").forces(30)
    assert f["driver_torque_Nm"] == row["driver_torque_Nm"]
    assert f["shaking_force_N"] == (row["shaking_fx_N"], row["shaking_fy_N"])
    assert f["shaking_moment_Nm"] == row["shaking_moment_Nm"]
    pin = f["joints"][0]
    assert pin["joint"].startswith("joints[0] (pin ground.A")
    assert pin["force_N"] == (row["pin:ground.A.fx_N"], row["pin:ground.A.fy_N"])


def test_sensitivity_is_the_command_lines():
    out = cli("sensitivity", "four-bar-crank-rocker", "--point", "coupler.P", "--steps", "12").stdout
    rows = [r for r in csv.reader(io.StringIO(out))][1:]
    want = {r[1]: (float(r[2]), float(r[3])) for r in rows if float(r[0]) == 30}
    got = linkage.load("four-bar-crank-rocker").sensitivity("coupler.P", 30)
    assert list(got) == list(want)
    assert {k: (x + 0.0, y + 0.0) for k, (x, y) in got.items()} == want


def rows_at(out, deg, columns):
    rows = [r for r in csv.reader(io.StringIO(out))][1:]
    return {r[1]: tuple(float(v) for v in r[2:2 + columns]) for r in rows if float(r[0]) == deg}


def zero_signed(d):
    return {k: tuple(x + 0.0 for x in v) for k, v in d.items()}


def test_rates_and_space_sensitivities_are_the_command_lines():
    out = cli("sensitivity", "drop-feed", "--point", "feedbar.D", "--steps", "8", "--velocity",
              "--acceleration").stdout
    rows = [r for r in csv.reader(io.StringIO(out))][1:]
    m = linkage.load("drop-feed")
    for quantity, cols in (("velocity", slice(4, 6)), ("acceleration", slice(6, 8))):
        want = {r[1]: tuple(float(v) for v in r[cols]) for r in rows if float(r[0]) == 45}
        assert zero_signed(m.sensitivity("feedbar.D", 45, quantity=quantity)) == want
    # In space: the world's x, y, z (linkage-cli's dz columns).
    out = cli("sensitivity", "overedge-machine", "--point", "needlearm.N", "--steps", "4").stdout
    got = linkage.load("overedge-machine").sensitivity("needlearm.N", 90)
    assert all(len(v) == 3 for v in got.values())
    assert zero_signed(got) == rows_at(out, 90, 3)
    with pytest.raises(ValueError, match="quantity"):
        m.sensitivity("feedbar.D", 0, quantity="jerk")


def test_stroke_shaking_and_force_sensitivities_are_the_command_lines():
    m = linkage.load("drop-feed")
    out = cli("sensitivity", "drop-feed", "--point", "feedbar.D", "--stroke").stdout
    want = {r[0]: float(r[1]) for r in list(csv.reader(io.StringIO(out)))[1:]}
    assert {k: v + 0.0 for k, v in m.stroke_sensitivity("feedbar.D").items()} == want
    # A machine in space: along the world's y, as the command line takes it there.
    out = cli("sensitivity", "rssr-crank-rocker", "--point", "rocker.C", "--stroke").stdout
    want = {r[0]: float(r[1]) for r in list(csv.reader(io.StringIO(out)))[1:]}
    got = linkage.load("rssr-crank-rocker").stroke_sensitivity("rocker.C")
    assert {k: v + 0.0 for k, v in got.items()} == want and want["ball-rod:crank.A.length"] != 0
    # Along a direction given, as --direction gives it; one out of a planar machine's plane refused.
    out = cli("sensitivity", "rssr-crank-rocker", "--point", "rocker.C", "--stroke",
              "--direction", "1,0,2").stdout
    want = {r[0]: float(r[1]) for r in list(csv.reader(io.StringIO(out)))[1:]}
    got = linkage.load("rssr-crank-rocker").stroke_sensitivity("rocker.C", direction="1,0,2")
    assert {k: v + 0.0 for k, v in got.items()} == want and want["crank.O-A"] != 0
    with pytest.raises(ValueError, match="out of the plane"):
        m.stroke_sensitivity("feedbar.D", direction="z")
    out = cli("sensitivity", "drop-feed", "--shaking", "--steps", "6").stdout
    assert zero_signed(m.shaking_sensitivity(120)) == rows_at(out, 120, 3)  # (dfx, dfy, dm)
    space = linkage.load("overedge-machine")  # in the world: (dfx, dfy, dfz, dmx, dmy, dmz)
    out = cli("sensitivity", "overedge-machine", "--shaking", "--steps", "6").stdout
    assert zero_signed(space.shaking_sensitivity(60)) == rows_at(out, 60, 6)
    out = cli("sensitivity", "drop-feed", "--force", "pin:ground.L", "--steps", "6").stdout
    assert zero_signed(m.force_sensitivity("pin:ground.L", 240)) == rows_at(out, 240, 2)
    with pytest.raises(ValueError, match="no joint 'pin:x.Y'"):
        m.force_sensitivity("pin:x.Y", 0)
    out = cli("sensitivity", "drop-feed", "--force", "gear:armshaft.M", "--steps", "6").stdout
    assert zero_signed(m.force_sensitivity("gear:armshaft.M", 60)) == rows_at(out, 60, 2)
    s = linkage.load("slider-crank-22a-masses")
    out = cli("sensitivity", "slider-crank-22a-masses", "--force", "slider:needlebar.B",
              "--steps", "6").stdout
    assert zero_signed(s.force_sensitivity("slider:needlebar.B", 180)) == rows_at(out, 180, 3)


def test_a_bearings_out_of_plane_derivatives_are_the_command_lines(tmp_path):
    # The RSSR with masses on its crank and rocker and gravity across both planes: the crank's
    # pin bears (dfx, dfy) in its plane and (dfn, dmx, dmy) out of it, as --force writes them.
    with open(linkage.load("rssr-crank-rocker").path) as f:
        doc = json.load(f)
    for body, kg, com in (("crank", 0.3, [5, 1]), ("rocker", 0.2, [-15, 8])):
        next(b for b in doc["bodies"] if b["name"] == body)["mass"] = {
            "kg": kg, "com": com, "j_kg_mm2": 60}
    doc["gravity"] = [0, -9.81, -3]
    path = tmp_path / "loaded.linkage.json"
    path.write_text(json.dumps(doc))
    out = cli("sensitivity", str(path), "--force", "pin:ground.O", "--steps", "4").stdout
    got = zero_signed(linkage.load(str(path)).force_sensitivity("pin:ground.O", 90))
    assert got == rows_at(out, 90, 5)
    assert any(abs(v[2]) > 1e-6 and abs(v[3]) > 1e-6 for v in got.values())


def test_points_bodies_dimensions():
    m = linkage.load("four-bar-crank-rocker")
    assert m.bodies == ["ground", "crank", "coupler", "rocker"]
    assert "coupler.P" in m.points and "ground.O4" in m.points
    assert m.dimensions["crank.O2-A"] == pytest.approx(20, abs=1e-12)
    assert m.side_lengths("crank") == [pytest.approx(20, abs=1e-12)]


def test_edit_save_and_the_command_line_on_the_saved_file(tmp_path):
    m = linkage.load("four-bar-crank-rocker")
    m.set_dimension("crank.O2-A", 15)
    m.set_dimension("ground.O4.x", 62)
    assert m.side_lengths("crank")[0] == pytest.approx(15, abs=1e-12)
    assert m.dimensions["ground.O4.x"] == 62
    path = tmp_path / "edited.linkage.json"
    m.save(path)  # a pathlib.Path, or a str
    assert not [p for p in os.listdir(tmp_path) if p != "edited.linkage.json"]  # no temporaries
    again = linkage.load(path)
    assert again.dimensions == m.dimensions
    _, table = cli_table("analyze", str(path), "--steps", "90", "--point", "coupler.P")
    assert same_bits(m.analyze(steps=90, points=["coupler.P"]), table)
    # The motion changed: the crank is shorter.
    before = linkage.load("four-bar-crank-rocker").analyze(steps=90, points=["coupler.P"])
    assert not np.allclose(before[:, 2:4], table[:, 2:4])


def test_any_named_dimension_is_set_exactly():
    # The slider-crank of 22-A: its slot's angle and a gear-free offset, as optimize sets them.
    m = linkage.load("slider-crank-22a-lambda-0.3")
    m.set_dimension("ground.guide.angle", 85)
    assert m.dimensions["ground.guide.angle"] == pytest.approx(85, abs=1e-9)
    m.set_dimension("crank.O-A", 17)
    assert m.dimensions["crank.O-A"] == pytest.approx(17, abs=1e-12)
    with pytest.raises(ValueError, match="positive"):
        m.set_dimension("rod.A-B", -3)


def test_optimize_is_the_command_lines_and_applies(tmp_path):
    # Seed 001's stroke adjustment (tests/test_cli_optimize.cpp), the same numbers to the bit.
    vary = {"ground.F.x": (10, 30), "ground.F.y": (137.05539931644228, 160)}
    targets = ["stroke:needlebar.G=22.768569616037638",
               "position:rocker.E@0=43,137.05539931644228"]
    out = cli("optimize", "needle-876-alpha-0", *[f"--vary={k}={lo!r}:{hi!r}" for k, (lo, hi)
                                                   in vary.items()],
              *[f"--target={t}" for t in targets], "--starts", "4").stdout
    want = {tuple(r[:2]): r[2:] for r in csv.reader(io.StringIO(out))}
    m = linkage.load("needle-876-alpha-0")
    r = m.optimize(vary, targets, starts=4, apply=True)
    for name, (before, after) in r["variables"].items():
        assert (before, after) == (float(want["variable", name][0]), float(want["variable", name][1]))
        assert m.dimensions[name] == pytest.approx(after, abs=1e-9)
    assert r["targets"][targets[0]][1][0] == float(want["stroke_mm", "needlebar.G"][1])
    assert r["starts"] == 4 and r["starts_found_best"] == int(want["starts_found_best", ""][0])
    m.save(tmp_path / "found.linkage.json")
    limits = cli("limits", str(tmp_path / "found.linkage.json"), "--point", "needlebar.G").stdout
    assert "stroke,,22.7685696160" in limits


def test_optimize_counterweights_and_refusals():
    # Seed 003's problem: the lower shaft's counterweight for the least peak |fx| (balance's).
    m = linkage.load("drop-feed")
    r = m.optimize({"lowershaft.counterweight.x": (-50, 50),
                    "lowershaft.counterweight.y": (-50, 50)}, ["shaking:fx<=0"], starts=2)
    before, after = r["targets"]["shaking:fx<=0"]
    balance = {tuple(row[:2]): row[2:] for row in csv.reader(io.StringIO(
        cli("balance", "drop-feed", "--counterweight", "lowershaft", "--minimize", "fx").stdout))}
    assert after[0] == pytest.approx(float(balance["peak_after", ""][0]), rel=1e-7)
    assert before[0] == pytest.approx(float(balance["peak_before", ""][0]), rel=1e-12)
    assert r["counterweights_kg"]["lowershaft"] > 0
    with pytest.raises(ValueError, match="no dimension 'nothing'"):
        m.optimize({"nothing": (0, 1)}, ["shaking:fx<=0"])
    with pytest.raises(ValueError, match="planar machine's shaking force has no fz"):
        m.optimize({"lowershaft.counterweight.x": (0, 1)}, ["shaking:fz<=0"])
    with pytest.raises(ValueError, match="shaking:fx<=N"):
        m.optimize({"lowershaft.counterweight.x": (0, 1)}, ["shaking:fw<=0"])


def test_a_triangles_side_and_refused_edits():
    m = linkage.load("wanzer-inversion-2")
    m.set_dimension("triangle.F-G", 57)
    assert m.side_lengths("triangle")[1] == pytest.approx(57, abs=1e-12)
    before = m.dimensions
    with pytest.raises(ValueError, match="no dimension"):
        m.set_dimension("triangle.X-Y", 3)
    with pytest.raises(ValueError, match="positive"):
        m.set_side_lengths("triangle", [16, -1, 62])
    with pytest.raises(ValueError, match="no body"):
        m.set_side_lengths("nobody", [1])
    assert m.dimensions == before


def test_a_crank_that_cannot_turn_is_a_motion_error(tmp_path):
    m = linkage.load("four-bar-crank-rocker")
    m.set_dimension("crank.O2-A", 45)  # s + l > p + q: no longer a crank-rocker
    with pytest.raises(linkage.MotionError, match="cannot reach crank angle") as e:
        m.analyze(steps=360, points=["coupler.P"])
    path = tmp_path / "locks.linkage.json"
    m.save(str(path))
    r = cli("analyze", str(path), "--point", "coupler.P", check=False)
    assert r.returncode == 3
    assert str(e.value) in r.stderr
    assert isinstance(e.value, RuntimeError)


def test_bad_files_and_names_are_value_errors(tmp_path):
    bad = tmp_path / "bad.linkage.json"
    text = open(linkage.load("four-bar-crank-rocker").path).read()
    bad.write_text(text.replace('"coupler.A"', '"coupler.Q"', 1) if '"coupler.A"' in text
                   else text.replace('"A"', '"Q"', 1))
    with pytest.raises(ValueError) as e:
        linkage.load(str(bad))
    r = cli("info", str(bad), check=False)
    assert r.returncode == 2 and str(e.value) in r.stderr
    assert str(bad) in str(e.value)
    with pytest.raises(ValueError, match="no such file, and no example of that name"):
        linkage.load("no-such-example")
    m = linkage.load("four-bar-crank-rocker")
    with pytest.raises(ValueError, match='no point "Z" on body "coupler"'):
        m.analyze(points=["coupler.Z"])
    with pytest.raises(ValueError, match="not a finite"):
        m.instant_centres(float("nan"))
    with pytest.raises(ValueError, match="not finite"):
        m.sweep("coupler.P", np.array([0.0, float("inf")]))
    with pytest.raises(ValueError, match="one-dimensional"):
        m.sweep("coupler.P", np.zeros((2, 2)))
    with pytest.raises(ValueError, match="whole number"):
        m.analyze(steps=3, revs=0.5)
    with pytest.raises(ValueError, match="more than the 50000000"):
        m.analyze(steps=360, revs=1e6)
    with pytest.raises(ValueError):
        m.save(str(tmp_path / "no-such-dir" / "x.linkage.json"))


def test_examples_and_version():
    assert "wanzer-inversion-2" in linkage.examples()
    assert linkage.__version__ == cli("--version").stdout.split()[-1]


def test_the_docs_example_runs(tmp_path, monkeypatch, capsys):
    docs = os.path.join(os.path.dirname(__file__), "..", "..", "docs", "python.md")
    text = open(docs).read()
    code = text.split("```python\n", 1)[1].split("```", 1)[0]
    monkeypatch.chdir(tmp_path)
    exec(compile(code.replace("/tmp/", str(tmp_path) + "/"), "docs/python.md", "exec"), {})
    out = capsys.readouterr().out
    assert "needle stroke" in out and "refused:" in out
    assert (tmp_path / "wanzer-longer.linkage.json").exists()


@pytest.mark.parametrize("model", linkage.examples())
def test_every_examples_table_and_no_crash(model):
    """Every example: the command line's table; every query answers or raises with a message."""
    m = linkage.load(model)
    header, table = cli_table("analyze", model, "--steps", "36")
    assert m.columns() == header
    assert same_bits(m.analyze(steps=36), table)
    for query in (lambda: m.instant_centres(33), lambda: m.forces(33),
                  lambda: m.sensitivity(m.points[-1], 33),
                  lambda: m.sweep(m.points[-1], np.array([])), lambda: m.forces(1e300)):
        try:
            query()
        except (ValueError, linkage.MotionError) as e:
            assert str(e)
