// Mechanisms built in code for tests: a four-bar and a slider-crank of any dimensions.
#pragma once

#include <cmath>

#include "linkage/model.h"

namespace linkage::test {

struct FourBar {
  Mechanism m;
  BodyId ground, crank, coupler, rocker;
  PointId O2, A, B, O4, P;  // P: the coupler point
  JointId drive, pinA, pinB, pinO4;
};

// Crank pivot O2 = (0, 0), rocker pivot O4 = (d, 0); crank r2 at `crankDeg` (from +x, ccw);
// open branch (B above the line O2-O4 side chosen by `open`); coupler point at (px, py) in the
// frame of A->B. Returns nullopt-like empty mechanism if it cannot close.
inline FourBar fourBar(double d, double r2, double r3, double r4, double crankDeg, bool open = true,
                       double px = 0, double py = 0, Direction dir = Direction::Ccw,
                       double rpm = 60) {
  FourBar f;
  Mechanism& m = f.m;
  const double t = crankDeg * M_PI / 180;
  const Vec2 O2(0, 0), O4(d, 0), A(r2 * std::cos(t), r2 * std::sin(t));
  // B: intersection of circle(A, r3) and circle(O4, r4).
  const Vec2 AO = O4 - A;
  const double e = AO.norm();
  const double a = (r3 * r3 - r4 * r4 + e * e) / (2 * e);
  const double h = std::sqrt(std::max(0.0, r3 * r3 - a * a));
  const Vec2 u = AO / e, n(-u.y(), u.x());
  const Vec2 B = A + a * u + (open ? h : -h) * n;
  const Vec2 ab = (B - A).normalized(), abn(-ab.y(), ab.x());
  const Vec2 P = A + px * ab + py * abn;
  f.ground = m.addBody("ground", true);
  f.crank = m.addBody("crank");
  f.coupler = m.addBody("coupler");
  f.rocker = m.addBody("rocker");
  const PointId gO2 = m.addPoint(f.ground, "O2", O2), gO4 = m.addPoint(f.ground, "O4", O4);
  f.O2 = m.addPoint(f.crank, "O2", O2);
  const PointId cA = m.addPoint(f.crank, "A", A);
  f.A = m.addPoint(f.coupler, "A", A);
  f.B = m.addPoint(f.coupler, "B", B);
  f.P = m.addPoint(f.coupler, "P", P);
  const PointId rB = m.addPoint(f.rocker, "B", B);
  f.O4 = m.addPoint(f.rocker, "O4", O4);
  f.drive = m.addPin(gO2, f.O2);
  f.pinA = m.addPin(cA, f.A);
  f.pinB = m.addPin(f.B, rB);
  f.pinO4 = m.addPin(f.O4, gO4);
  m.driver = Driver{f.drive, rpm, dir, 0, ""};
  m.outputs = {f.P};
  return f;
}

struct SliderCrank {
  Mechanism m;
  BodyId ground, crank, rod, slider;
  PointId A, B;
  JointId drive;
};

// Crank pivot at the origin, slider on the vertical line x = e above it, crank at `crankDeg`
// from +x (ccw). The slider is a block in a ground slot (slider joint) or, with pinInSlot, the
// rod's end runs in the slot directly (no block body).
inline SliderCrank sliderCrank(double r, double l, double e, double crankDeg,
                               Direction dir = Direction::Ccw, double rpm = 60,
                               bool pinInSlot = false) {
  SliderCrank s;
  Mechanism& m = s.m;
  const double t = crankDeg * M_PI / 180;
  const Vec2 A(r * std::cos(t), r * std::sin(t));
  const Vec2 B(e, A.y() + std::sqrt(l * l - (e - A.x()) * (e - A.x())));
  s.ground = m.addBody("ground", true);
  s.crank = m.addBody("crank");
  s.rod = m.addBody("rod");
  const PointId gO = m.addPoint(s.ground, "O", Vec2(0, 0));
  const SlotId guide = m.addSlot(s.ground, "guide", Vec2(e, 0), Vec2(e, r + l));
  const PointId cO = m.addPoint(s.crank, "O", Vec2(0, 0));
  const PointId cA = m.addPoint(s.crank, "A", A);
  s.A = m.addPoint(s.rod, "A", A);
  const PointId rB = m.addPoint(s.rod, "B", B);
  s.drive = m.addPin(gO, cO);
  m.addPin(cA, s.A);
  if (pinInSlot) {
    s.B = rB;
    m.addPinInSlot(rB, guide);
  } else {
    s.slider = m.addBody("slider");
    s.B = m.addPoint(s.slider, "B", B);
    m.addPin(rB, s.B);
    m.addSlider(s.B, guide);
  }
  m.driver = Driver{s.drive, rpm, dir, 0, ""};
  m.outputs = {s.B};
  return s;
}

// A Watt II six-bar drawn where its ground pivots, the crank pin A and the pin F all lie on the
// line y = 0 (tests/test_instant_centres.cpp explains why Kennedy cannot fix IC(2,6) there).
// Bodies: ground, crank, coupler, rocker (with a third pin E), link, output.
struct WattSixBar {
  Mechanism m;
  BodyId crank, output;
};

inline WattSixBar wattSixBar() {
  WattSixBar w;
  Mechanism& m = w.m;
  const Vec2 O2(0, 0), O4(60, 0), O6(150, 0), A(20, 0), B(70, std::sqrt(2400.0)), E(85, 25),
      F(110, 0);
  const BodyId g = m.addBody("ground", true), crank = m.addBody("crank"),
               coupler = m.addBody("coupler"), rocker = m.addBody("rocker"),
               link = m.addBody("link"), output = m.addBody("output");
  const JointId drive = m.addPin(m.addPoint(g, "O2", O2), m.addPoint(crank, "O2", O2));
  m.addPin(m.addPoint(crank, "A", A), m.addPoint(coupler, "A", A));
  m.addPin(m.addPoint(coupler, "B", B), m.addPoint(rocker, "B", B));
  m.addPin(m.addPoint(rocker, "O4", O4), m.addPoint(g, "O4", O4));
  m.addPin(m.addPoint(rocker, "E", E), m.addPoint(link, "E", E));
  m.addPin(m.addPoint(link, "F", F), m.addPoint(output, "F", F));
  m.addPin(m.addPoint(output, "O6", O6), m.addPoint(g, "O6", O6));
  m.driver = Driver{drive, 60, Direction::Ccw, 0, ""};
  w.crank = crank;
  w.output = output;
  return w;
}

// A chain of `loops` four-bars along the x axis: loop k has ground pivots at 60k and 60k + 60;
// loop 0's crank is driven, and the rocker of loop k, extended, is the input of loop k + 1.
// 1 + 2 loops bodies; every loop after the first is a dyad on the previous one. Loop 0's crank,
// coupler and rocker lengths can be changed (a non-Grashof or a parallelogram first loop); the
// other loops are 20, 70, 50 on 60 mm of ground, crank-rockers whatever their input does.
inline Mechanism fourBarChain(int loops, double crankLength = 20, double couplerLength = 70,
                              double rockerLength = 50) {
  Mechanism m;
  const BodyId g = m.addBody("ground", true);
  auto circle = [](Vec2 a, double ra, Vec2 b, double rb) {  // upper intersection
    const Vec2 e = b - a;
    const double d = e.norm(), x = (ra * ra - rb * rb + d * d) / (2 * d);
    const double h = std::sqrt(std::max(0.0, ra * ra - x * x));
    const Vec2 u = e / d;
    return Vec2(a + x * u + h * Vec2(-u.y(), u.x()));
  };
  BodyId input = m.addBody("crank");
  const Vec2 O0(0, 0);
  const JointId drive = m.addPin(m.addPoint(g, "O0", O0), m.addPoint(input, "O0", O0));
  Vec2 pivot = O0, A = Vec2(crankLength * std::cos(1.0), crankLength * std::sin(1.0));
  PointId inputA = m.addPoint(input, "A", A);
  for (int k = 0; k < loops; ++k) {
    const std::string n = std::to_string(k);
    const Vec2 O4 = pivot + Vec2(60, 0);
    const Vec2 B = circle(A, k == 0 ? couplerLength : 70, O4, k == 0 ? rockerLength : 50);
    const BodyId coupler = m.addBody("coupler" + n), rocker = m.addBody("rocker" + n);
    m.addPin(inputA, m.addPoint(coupler, "A", A));
    m.addPin(m.addPoint(coupler, "B", B), m.addPoint(rocker, "B", B));
    m.addPin(m.addPoint(rocker, "O4", O4), m.addPoint(g, "O4_" + n, O4));
    // The next loop's input: the rocker extended beyond its pivot, 20 mm long.
    const Vec2 next = O4 + 20 * (O4 - B).normalized();
    pivot = O4;
    A = next;
    inputA = m.addPoint(rocker, "A", A);
  }
  m.driver = Driver{drive, 60, Direction::Ccw, 0, ""};
  m.outputs = {inputA};
  return m;
}

// One class-III group (triad) that the closed-form groups cannot solve, its points shifted by
// `at`: a triangle hung from the ground g by two long links and pushed sideways by a third
// link from `input` (a point of a known body, 35 mm to the left of the push's other end). No
// body of it is held to known bodies by two joints or a core's three conditions. Returns the
// triangle's output point S. Its bodies are named triangle, push, left and right + n.
inline PointId addTriad(Mechanism& m, BodyId g, PointId input, const Vec2& at,
                        const std::string& n) {
  const Vec2 P = at + Vec2(-30, -5), Q = at + Vec2(-10, 0), R = at + Vec2(20, 5);
  const Vec2 S = at + Vec2(40, -10), G2 = at + Vec2(-15, 80), G3 = at + Vec2(25, 85);
  const BodyId t = m.addBody("triangle" + n), push = m.addBody("push" + n),
               left = m.addBody("left" + n), right = m.addBody("right" + n);
  m.addPin(input, m.addPoint(push, "in", m.point(input)->pos));
  m.addPin(m.addPoint(push, "P", P), m.addPoint(t, "P", P));
  m.addPin(m.addPoint(t, "Q", Q), m.addPoint(left, "Q", Q));
  m.addPin(m.addPoint(left, "G", G2), m.addPoint(g, "G2_" + n, G2));
  m.addPin(m.addPoint(t, "R", R), m.addPoint(right, "R", R));
  m.addPin(m.addPoint(right, "G", G3), m.addPoint(g, "G3_" + n, G3));
  return m.addPoint(t, "S", S);
}

// A chain of `units` triads (addTriad): unit k pushed by the previous unit's triangle (unit 0:
// by a 5 mm crank). Only the general solve takes it. 1 + 4 units bodies. The crank turns
// fully; the first triangle swings 10 mm and each next one about a tenth less (its output
// point is nearer the point its two hangers converge to).
inline Mechanism triadChain(int units) {
  Mechanism m;
  const BodyId g = m.addBody("ground", true);
  const Vec2 C(-70, -5);
  const BodyId crank = m.addBody("crank");
  const JointId drive = m.addPin(m.addPoint(g, "C", C), m.addPoint(crank, "C", C));
  PointId input = m.addPoint(crank, "A", C + Vec2(5, 0));
  for (int k = 0; k < units; ++k)
    input = addTriad(m, g, input, Vec2(100.0 * k, 0), std::to_string(k));
  m.driver = Driver{drive, 60, Direction::Ccw, 0, ""};
  m.outputs = {input};
  return m;
}

// A machine on one main shaft: the shaft "main" about the origin (driven, ccw), a "hook" shaft
// at (0, -200) belted 2:1 to it, and `units` mechanisms around it, each on its own crank pin of
// the main shaft at radius 10 and phase 25 k degrees, in the direction psi_k = 360 k / units:
// even k a radial slider-crank (rod k of 40 mm, block k in a ground slot "guide_k" along
// psi_k), odd k a crank-rocker (coupler k of 40 mm, rocker k of 30 mm about a ground pivot 45 mm
// out along psi_k). 3 + 2 units bodies with the ground; every mechanism is solved group by group.
inline Mechanism shaftMachine(int units) {
  Mechanism m;
  const BodyId g = m.addBody("ground", true), main = m.addBody("main"), hook = m.addBody("hook");
  const Vec2 O(0, 0), H(0, -200);
  const PointId mainO = m.addPoint(main, "O", O), hookO = m.addPoint(hook, "O", H);
  const JointId drive = m.addPin(m.addPoint(g, "O", O), mainO);
  m.addPin(m.addPoint(g, "H", H), hookO);
  m.addPoint(hook, "K", H + Vec2(12, 9));
  m.addGear(mainO, hookO, 2);
  const double r = 10, l = 40;
  for (int k = 0; k < units; ++k) {
    const std::string n = std::to_string(k);
    const double phase = 25.0 * k * M_PI / 180, psi = 2 * M_PI * k / units;
    const Vec2 P = r * Vec2(std::cos(phase), std::sin(phase));
    const Vec2 u(std::cos(psi), std::sin(psi)), v(-u.y(), u.x());
    const PointId pin = m.addPoint(main, "P" + n, P);
    if (k % 2 == 0) {
      const Vec2 B = (P.dot(u) + std::sqrt(l * l - P.dot(v) * P.dot(v))) * u;
      const BodyId rod = m.addBody("rod" + n), block = m.addBody("block" + n);
      m.addPin(pin, m.addPoint(rod, "A", P));
      const PointId b = m.addPoint(block, "B", B);
      m.addPin(m.addPoint(rod, "B", B), b);
      m.addSlider(b, m.addSlot(g, "guide" + n, (l - r - 5) * u, (l + r + 5) * u));
    } else {
      const Vec2 G = 45 * u, e = G - P;
      const double d = e.norm(), x = (l * l - 30.0 * 30.0 + d * d) / (2 * d);
      const Vec2 w = e / d, C = P + x * w + std::sqrt(l * l - x * x) * Vec2(-w.y(), w.x());
      const BodyId coupler = m.addBody("coupler" + n), rocker = m.addBody("rocker" + n);
      m.addPin(pin, m.addPoint(coupler, "A", P));
      const PointId c = m.addPoint(rocker, "C", C);
      m.addPin(m.addPoint(coupler, "C", C), c);
      m.addPin(m.addPoint(rocker, "G", G), m.addPoint(g, "G" + n, G));
    }
  }
  m.driver = Driver{drive, 1200, Direction::Ccw, 0, ""};
  return m;
}

}  // namespace linkage::test
