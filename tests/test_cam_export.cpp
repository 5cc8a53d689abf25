// A cam's profile written for the workshop (linkage/tables/cam_export.h): the DXF read back with
// dxflib's own reader (two closed polylines on their layers, every vertex where the profile has
// it), the CSV's columns read back, the SVG's paths.
#include <gtest/gtest.h>

#include <dxflib/dl_creationadapter.h>
#include <dxflib/dl_dxf.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "linkage/io/numbers.h"
#include "linkage/tables/cam_export.h"

namespace linkage {
namespace {

std::vector<cam::CamPoint> profilePoints(int steps) {
  cam::CamGeometry g;
  g.baseMm = 30;
  g.rollerMm = 8;
  g.offsetMm = 6;
  g.program = cam::Program({{90, 10, cam::Law::Cycloidal},
                            {150, 0, std::nullopt},
                            {270, -10, cam::Law::Polynomial345},
                            {360, 0, std::nullopt}});
  return cam::camPoints(g, steps);
}

// What dxflib's reader hands over: each polyline's flags, layer and vertices.
struct Reader : DL_CreationAdapter {
  struct Poly {
    int flags = 0;
    std::string layer;
    std::vector<Vec2> vertices;
  };
  std::vector<Poly> polys;
  void addPolyline(const DL_PolylineData& d) override {
    polys.push_back({d.flags, attributes.getLayer(), {}});
  }
  void addVertex(const DL_VertexData& d) override {
    if (!polys.empty()) polys.back().vertices.emplace_back(d.x, d.y);
  }
};

TEST(CamExport, TheDxfReadsBackAsTwoClosedPolylinesThroughEveryPoint) {
  const std::vector<cam::CamPoint> points = profilePoints(360);
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "linkage-cam-dxf";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "cam.dxf").string();
  const WriteResult w = writeCamProfileDxf(points, true, path);
  ASSERT_TRUE(w.ok) << w.error;
  Reader r;
  DL_Dxf dxf;
  ASSERT_TRUE(dxf.in(path, &r));
  ASSERT_EQ(r.polys.size(), 2u);
  EXPECT_EQ(r.polys[0].layer, "CAM_SURFACE");
  EXPECT_EQ(r.polys[1].layer, "CAM_PITCH");
  for (int k = 0; k < 2; ++k) {
    EXPECT_EQ(r.polys[k].flags & 1, 1) << "closed";
    ASSERT_EQ(r.polys[k].vertices.size(), points.size());
    for (size_t i = 0; i < points.size(); ++i) {
      const Vec2& want = k == 0 ? points[i].surface : points[i].pitch;
      EXPECT_LT((r.polys[k].vertices[i] - want).norm(), 1e-9) << k << " " << i;
    }
  }
  std::filesystem::remove_all(dir);
}

TEST(CamExport, TheCsvHasAPointARowInItsColumns) {
  const std::vector<cam::CamPoint> points = profilePoints(8);
  std::istringstream in(camProfileCsv(points));
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line,
            "cam_deg,surface_x_mm,surface_y_mm,pitch_x_mm,pitch_y_mm,pressure_angle_deg,radius_mm");
  for (const cam::CamPoint& p : points) {
    ASSERT_TRUE(std::getline(in, line));
    std::vector<double> v;
    std::istringstream cells(line);
    for (std::string c; std::getline(cells, c, ',');) v.push_back(*parseNumber(c));
    ASSERT_EQ(v.size(), 7u);
    const double want[] = {p.camDeg,    p.surface.x(), p.surface.y(), p.pitch.x(),
                           p.pitch.y(), p.pressureDeg, p.radiusMm};
    for (int c = 0; c < 7; ++c) EXPECT_EQ(v[c], want[c]) << line;
  }
  EXPECT_FALSE(std::getline(in, line));
}

TEST(CamExport, TheSvgDrawsTheSurfaceAndThePitchCurve) {
  const std::string svg = camProfileSvg(profilePoints(36), true);
  EXPECT_NE(svg.find("<svg xmlns=\"http://www.w3.org/2000/svg\""), std::string::npos);
  EXPECT_NE(svg.find("id=\"surface\" d=\"M"), std::string::npos);
  EXPECT_NE(svg.find("id=\"pitch\" d=\"M"), std::string::npos);
  EXPECT_EQ(camProfileSvg(profilePoints(36), false).find("id=\"pitch\""), std::string::npos);
}

}  // namespace
}  // namespace linkage
