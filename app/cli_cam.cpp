// linkage-cli cam: a cam joint's checks (pressure angle, radii of curvature, undercut), exact,
// and its profile written for the workshop (linkage/cam_checks.h, linkage/tables/cam_export.h).
#include <iostream>

#include "cli_common.h"
#include "cli_parser.h"
#include "linkage/cam_checks.h"
#include "linkage/cam_joint.h"
#include "linkage/elements.h"
#include "linkage/io/numbers.h"
#include "linkage/tables/cam_export.h"

namespace linkage::cli {

namespace {

const char* kHelp = R"(usage: linkage-cli cam MODEL [--joint N] [--steps N] [--out FILE.csv|dxf|svg]

The checks of MODEL's cam joint (the first, or joints[N]) over a turn of the cam, each exact
(found by root-finding on the exact profile, whatever --steps is), as CSV rows
quantity,value,at_cam_deg:
  pressure_angle_max_deg   the largest angle between the follower's motion and the common
                           normal (roller and knife followers; usual limits 30 translating,
                           35 oscillating)
  pitch_radius_min_mm      the pitch curve's smallest convex radius (roller and knife)
  surface_radius_min_mm    the surface's smallest radius of curvature (flat face; below 0 it is
                           not convex)
  undercut,yes|no          a roller larger than the pitch curve's convex radius, or a flat face
                           on a surface that is not convex (standard error says where)
Angles are the cam's turn relative to its guide, counter-clockwise from the drawing.

  --joint N   the cam joint's index in the file's joints (default: the first cam)
  --steps N   profile points a turn for --out (default 360; the checks do not use it)
  --out FILE  the profile in the cam's own frame (mm, its centre at the origin, axes as drawn):
              .csv (cam_deg, surface x y, pitch x y, pressure angle, radius), .dxf (closed
              polylines on layers CAM_SURFACE and CAM_PITCH) or .svg; written atomically

Exit status: 0 success (undercut or not), 2 bad input (no cam joint, a bad law or a programme
that does not close, naming the place), 1 the file could not be written.
)";

struct Options {
  std::string model, out;
  long long joint = -1;  // -1: the first cam
  long long steps = 360;
};

// The cam joint asked for, or why not.
const Joint* camOf(const Mechanism& m, const Options& o) {
  const ElementKind* kind = elementKindNamed("cam");
  for (size_t i = 0; i < m.joints.size(); ++i) {
    const Joint& j = m.joints[i];
    if (o.joint >= 0 && static_cast<long long>(i) != o.joint) continue;
    if (kind && elementKind(j.type).name == kind->name) return &j;
    if (o.joint >= 0) {
      error("joints[" + std::to_string(i) + "] is a " + toString(j.type) + ", not a cam");
      return nullptr;
    }
  }
  error(o.joint >= 0 ? "the model has no joints[" + std::to_string(o.joint) + "]"
                     : "the model has no cam joint");
  return nullptr;
}

void row(std::string& out, const char* name, const cam::CamExtreme& e) {
  if (!e.found) return;
  out += std::string(name) + "," + formatNumber(e.value) + "," + formatNumber(e.atDeg) + "\n";
}

int writeProfile(const Options& o, const cam::CamGeometry& g) {
  const std::vector<cam::CamPoint> points = cam::camPoints(g, static_cast<int>(o.steps));
  const bool pitch = g.face == cam::FollowerFace::Roller;
  const std::string ext = o.out.size() > 4 ? o.out.substr(o.out.size() - 4) : "";
  WriteResult w;
  if (ext == ".dxf")
    w = writeCamProfileDxf(points, pitch, o.out);
  else
    w = writeFileAtomically(o.out,
                            ext == ".svg" ? camProfileSvg(points, pitch) : camProfileCsv(points));
  if (!w.ok) error(w.error);
  return w.ok ? kOk : kFailure;
}

int camCommandRun(const Options& o) {
  const std::string ext = o.out.size() > 4 ? o.out.substr(o.out.size() - 4) : o.out;
  if (!o.out.empty() && ext != ".csv" && ext != ".dxf" && ext != ".svg") {
    error("--out " + o.out + ": the profile is written as .csv, .dxf or .svg");
    return kBadInput;
  }
  std::optional<Mechanism> m = openModel(o.model);
  if (!m) return kBadInput;
  const Joint* j = camOf(*m, o);
  if (!j) return kBadInput;
  std::string why, where;
  const std::optional<CamJoint> c = camJoint(*m, *j, &why, &where);
  if (!c) {
    error(where + ": " + why);
    return kBadInput;
  }
  const cam::CamGeometry g = cam::geometryOf(*c);
  const cam::CamChecks k = cam::camChecks(g);
  std::string out = "quantity,value,at_cam_deg\n";
  row(out, "pressure_angle_max_deg", k.pressureMax);
  row(out, g.face == cam::FollowerFace::Flat ? "surface_radius_min_mm" : "pitch_radius_min_mm",
      g.face == cam::FollowerFace::Flat ? k.surfaceRadiusMin : k.pitchRadiusMin);
  out += std::string("undercut,") + (k.undercut ? "yes" : "no") + ",\n";
  std::cout << out << std::flush;
  if (k.undercut) note("undercut: " + k.undercutWhy);
  return o.out.empty() ? kOk : writeProfile(o, g);
}

}  // namespace

Command camCommand(Parser& parser) {
  auto o = std::make_shared<Options>();
  CLI::App& c = parser.command("cam", kHelp);
  addModel(c, o->model);
  addWhole(c, "--joint", o->joint, 0, 1'000'000);
  addWhole(c, "--steps", o->steps, 8, 1'000'000);
  addText(c, "--out", o->out);
  return {&c, [o] { return camCommandRun(*o); }};
}

}  // namespace linkage::cli
