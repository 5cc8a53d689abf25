#!/usr/bin/env python3
"""Reproduces the stroke adjustment of seed 001 with `linkage-cli study`: the 876-class needle
mechanism's fixed pivot F moved on its arc about E (formula 8), alpha from 0 to 45 degrees, and
writes the table into docs/needle-876-study.md (between its table markers) and the figure
docs/needle-876-study.svg. No dependencies beyond python3.

    scripts/needle-876-study.py [BUILD_DIR]      (default: build)
"""
import csv
import io
import json
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DOC = os.path.join(ROOT, "docs", "needle-876-study.md")
FIG = os.path.join(ROOT, "docs", "needle-876-study.svg")
EXAMPLE = os.path.join(ROOT, "resources", "examples", "needle-876-alpha-0.linkage.json")


def study(cli, alpha_to, values):
    # F turns clockwise about E (its place at the lowest position) by alpha: --angle -1, t = alpha.
    with open(EXAMPLE, encoding="utf-8") as f:
        model = json.load(f)
    rocker = next(b for b in model["bodies"] if b["name"] == "rocker")
    ex, ey = rocker["points"]["E"]
    out = subprocess.run(
        [cli, "study", EXAMPLE, "--move", "ground.F", "--about", f"{ex!r},{ey!r}", "--angle", "-1",
         "--from", "0", "--to", str(alpha_to), "--steps", str(values), "--point", "needlebar.G"],
        check=True, capture_output=True, text=True).stdout
    rows = []
    for r in csv.DictReader(io.StringIO(out)):
        rows.append({k: (float(v) if v not in ("",) else None) for k, v in r.items()})
    return rows


def table(rows):
    lines = ["| alpha (deg) | stroke (mm) | lowest y_G (mm) | highest y_G (mm) | min mu_1 | "
             "min mu_2 | max mu_2 | min mu_3 | peak speed (mm/s) | peak accel. (m/s^2) |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        if r["t"] % 5 != 0:
            continue
        lines.append(
            "| %g | %.4f | %.7f | %.4f | %.2f | %.2f | %.2f | %.2f | %.0f | %.0f |" % (
                r["t"], r["needlebar.G.stroke_mm"], r["needlebar.G.min_mm"],
                r["needlebar.G.max_mm"], r["mu:coupler.B.min_deg"], r["mu:link.E.min_deg"],
                r["mu:link.E.max_deg"], r["mu:rod.G.min_deg"], r["needlebar.G.peak_speed_mm_s"],
                r["needlebar.G.peak_accel_mm_s2"] / 1000))
    return "\n".join(lines)


def svg(rows, path):
    W, H = 1020, 360
    panels = [
        ("needle stroke S (mm)", [("needlebar.G.stroke_mm", "#1b7837", "this program")],
         (16, 28, 2), [(0, 18), (35, 23)]),
        ("needle bar y_G at the bottom and top (mm)",
         [("needlebar.G.min_mm", "#2166ac", "lowest"), ("needlebar.G.max_mm", "#b2182b",
                                                          "highest")], (100, 140, 10), []),
        ("smallest transmission angles (deg)",
         [("mu:coupler.B.min_deg", "#762a83", "mu_1"), ("mu:link.E.min_deg", "#d6604d", "mu_2"),
          ("mu:rod.G.min_deg", "#4393c3", "mu_3")], (0, 100, 20), []),
    ]
    pw, left, top, ph = W / 3, 55, 30, H - 90
    amax = max(r["t"] for r in rows)
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" '
           f'font-family="sans-serif" font-size="12">',
           f'<rect width="{W}" height="{H}" fill="white"/>']
    for p, (title, series, (y0, y1, ystep), paper) in enumerate(panels):
        ox = p * pw + left
        w = pw - left - 15

        def X(a):
            return ox + a / amax * w

        def Y(v):
            return top + (y1 - v) / (y1 - y0) * ph

        out.append(f'<text x="{ox + w / 2}" y="18" text-anchor="middle">{title}</text>')
        out.append(f'<rect x="{ox}" y="{top}" width="{w}" height="{ph}" fill="none" '
                   f'stroke="#888"/>')
        # The paper's range of adjustment: alpha up to 35 degrees.
        out.append(f'<rect x="{X(35)}" y="{top}" width="{X(amax) - X(35)}" height="{ph}" '
                   f'fill="#f0f0f0"/><text x="{(X(35) + X(amax)) / 2}" y="{top + ph - 8}" '
                   f'text-anchor="middle" fill="#777">beyond 35</text>')
        for a in range(0, int(amax) + 1, 5):
            out.append(f'<line x1="{X(a)}" y1="{top + ph}" x2="{X(a)}" y2="{top + ph + 4}" '
                       f'stroke="#888"/><text x="{X(a)}" y="{top + ph + 17}" '
                       f'text-anchor="middle">{a}</text>')
        for k in range(int(round((y1 - y0) / ystep)) + 1):
            v = y0 + k * ystep
            out.append(f'<line x1="{ox - 4}" y1="{Y(v)}" x2="{ox}" y2="{Y(v)}" stroke="#888"/>'
                       f'<text x="{ox - 6}" y="{Y(v) + 4}" text-anchor="end">{v:g}</text>')
        out.append(f'<text x="{ox + w / 2}" y="{top + ph + 34}" text-anchor="middle">'
                   f'alpha (deg)</text>')
        if p == 2:  # the band's lower end
            out.append(f'<line x1="{ox}" y1="{Y(30)}" x2="{ox + w}" y2="{Y(30)}" '
                       f'stroke="#444" stroke-dasharray="5,4"/><text x="{ox + 4}" '
                       f'y="{Y(30) - 4}">30 (band)</text>')
        for i, (key, colour, label) in enumerate(series):
            pts = " ".join(f"{X(r['t']):.1f},{Y(r[key]):.1f}" for r in rows if r[key] is not None)
            out.append(f'<polyline points="{pts}" fill="none" stroke="{colour}" '
                       f'stroke-width="2"/>')
            out.append(f'<line x1="{ox + 10}" y1="{top + 14 + 16 * i}" x2="{ox + 30}" '
                       f'y2="{top + 14 + 16 * i}" stroke="{colour}" stroke-width="2"/>'
                       f'<text x="{ox + 34}" y="{top + 18 + 16 * i}">{label}</text>')
        for a, v in paper:
            out.append(f'<circle cx="{X(a)}" cy="{Y(v)}" r="4" fill="none" stroke="black"/>')
        if paper:
            i = len(series)
            out.append(f'<circle cx="{ox + 20}" cy="{top + 14 + 16 * i}" r="4" fill="none" '
                       f'stroke="black"/><text x="{ox + 34}" y="{top + 18 + 16 * i}">'
                       f'the paper (18 and 23 mm)</text>')
    out.append("</svg>")
    with open(path, "w", encoding="utf-8") as f:
        f.write("\n".join(out) + "\n")


def main():
    build = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build")
    cli = os.path.join(build, "app", "linkage-cli")
    rows = study(cli, 45, 91)  # every half degree
    svg(rows, FIG)
    with open(DOC, encoding="utf-8") as f:
        doc = f.read()
    doc = re.sub(r"(<!-- table -->\n)(?:.*?\n)?(<!-- /table -->)",
                 lambda m: m.group(1) + table(rows) + "\n" + m.group(2), doc, flags=re.S)
    with open(DOC, "w", encoding="utf-8") as f:
        f.write(doc)
    # The alpha where mu_2's minimum reaches 30 degrees (linear between rows).
    for a, b in zip(rows, rows[1:]):
        if a["mu:link.E.min_deg"] >= 30 > b["mu:link.E.min_deg"]:
            f = (a["mu:link.E.min_deg"] - 30) / (a["mu:link.E.min_deg"] - b["mu:link.E.min_deg"])
            print("min mu_2 = 30 at alpha = %.4f deg" % (a["t"] + f * (b["t"] - a["t"])))
    print("wrote", os.path.relpath(DOC, ROOT), "and", os.path.relpath(FIG, ROOT))


if __name__ == "__main__":
    main()
