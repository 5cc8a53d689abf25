// The machine the tests of ground slots out of the drawing share (edge on): a slider-crank in a
// plane square to the drawing whose block runs in a ground arc written in the world (its x, y three
// points on one line), beside a ground slot along z and an arc turning through three quarters.
#pragma once

#include <QFile>
#include <QTemporaryDir>
#include <string>

// Ground slots written in the world in planes square to the drawing: an arc g a slider's block
// runs in (in the side plane x = 0), a slot z along z, and an arc w of three quarters of a turn
// about (10, -80, 0), radius 10, in the plane x = 10.
inline std::string edgeOnText() {
  return R"({"format": "linkage", "version": 1, "name": "arc on edge",
  "planes": {"side": {"origin": [0, 0, 0], "x_axis": [0, 0, -1], "y_axis": [0, 1, 0]}},
  "bodies": [
    {"name": "ground", "ground": true, "points": {"O": [0, 0]},
     "slots": {"g": [[0, -20, 0], [0, -35, 5], [0, -50, 0]], "z": [[0, -60, 0], [0, -60, 9]],
               "w": [[10, -70, 0], [10, -87.07106781186548, 7.0710678118654755],
                     [10, -80, -10]]}},
    {"name": "crank", "plane": "side", "points": {"O": [0, 0], "A": [0, 10]}},
    {"name": "rod", "plane": "side", "points": {"A": [0, 10], "B": [0, -30]}},
    {"name": "block", "plane": "side", "points": {"B": [0, -30]}}],
  "joints": [{"type": "pin", "a": "ground.O", "b": "crank.O"},
    {"type": "pin", "a": "crank.A", "b": "rod.A"},
    {"type": "pin", "a": "rod.B", "b": "block.B"},
    {"type": "slider", "a": "block.B", "slot": "ground.g"}],
  "driver": {"joint": 0, "rpm": 60, "direction": "ccw"}})";
}

// It written to a file in dir; the file's path ("" where it could not be written).
inline QString writeEdgeOn(const QTemporaryDir& dir) {
  const QString path = dir.filePath("edge.linkage.json");
  QFile f(path);
  if (!f.open(QIODevice::WriteOnly)) return {};
  f.write(QByteArray::fromStdString(edgeOnText()));
  return path;
}
