#include "linkage/tables/cam_export.h"

#include <dxflib/dl_dxf.h>

#include <unistd.h>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <sstream>

#include "linkage/io/numbers.h"

namespace linkage {

std::string camProfileCsv(const std::vector<cam::CamPoint>& points) {
  std::string s =
      "cam_deg,surface_x_mm,surface_y_mm,pitch_x_mm,pitch_y_mm,pressure_angle_deg,radius_mm\n";
  for (const cam::CamPoint& p : points) {
    for (double v : {p.camDeg, p.surface.x(), p.surface.y(), p.pitch.x(), p.pitch.y(),
                     p.pressureDeg, p.radiusMm})
      s.append(formatNumber(v)).append(",");
    s.back() = '\n';
  }
  return s;
}

namespace {

std::string svgPath(const std::vector<cam::CamPoint>& points, bool pitch) {
  std::string d;
  for (const cam::CamPoint& p : points) {
    const Vec2& v = pitch ? p.pitch : p.surface;
    d += (d.empty() ? "M" : " L") + formatNumber(v.x(), 9) + " " + formatNumber(-v.y(), 9);
  }
  return d + " Z";
}

}  // namespace

std::string camProfileSvg(const std::vector<cam::CamPoint>& points, bool pitch) {
  double r = 1;
  for (const cam::CamPoint& p : points)
    r = std::max(
        {r, std::abs(p.surface.x()), std::abs(p.surface.y()), pitch ? p.pitch.norm() : 0.0});
  r *= 1.05;
  const std::string R = formatNumber(r, 9), D = formatNumber(2 * r, 9);
  std::string s = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  s += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"";
  s += D;
  s += "mm\" height=\"";
  s += D;
  s += "mm\" viewBox=\"-";
  s += R;
  s += " -";
  s += R;
  s += " ";
  s += D;
  s += " ";
  s += D;
  s += "\">\n<title>Cam profile (mm, the cam's frame; y up as drawn)</title>\n";
  s += "<path id=\"surface\" d=\"" + svgPath(points, false) +
       "\" fill=\"none\" stroke=\"black\" stroke-width=\"0.2\"/>\n";
  if (pitch)
    s += "<path id=\"pitch\" d=\"" + svgPath(points, true) +
         "\" fill=\"none\" stroke=\"grey\" stroke-width=\"0.1\" stroke-dasharray=\"1 1\"/>\n";
  s += "<circle id=\"centre\" cx=\"0\" cy=\"0\" r=\"0.5\" fill=\"black\"/>\n</svg>\n";
  return s;
}

namespace {

void polyline(DL_Dxf& dxf, DL_WriterA& dw, const std::vector<cam::CamPoint>& points, bool pitch) {
  const std::string layer = pitch ? "CAM_PITCH" : "CAM_SURFACE";
  dxf.writePolyline(dw, DL_PolylineData(static_cast<int>(points.size()), 0, 0, 1),
                    DL_Attributes(layer, 256, 0, "BYLAYER", 1.0));
  for (const cam::CamPoint& p : points) {
    const Vec2& v = pitch ? p.pitch : p.surface;
    dxf.writeVertex(dw, DL_VertexData(v.x(), v.y(), 0, 0));
  }
  dxf.writePolylineEnd(dw);
}

// The sections dxflib's guide lists, in its order, for a drawing of two layers.
void writeDrawing(DL_Dxf& dxf, DL_WriterA& dw, const std::vector<cam::CamPoint>& points,
                  bool pitch) {
  dxf.writeHeader(dw);
  dw.sectionEnd();
  dw.sectionTables();
  dxf.writeVPort(dw);
  dw.tableLinetypes(1);
  dxf.writeLinetype(dw, DL_LinetypeData("CONTINUOUS", "Continuous", 0, 0, 0.0));
  dw.tableEnd();
  dw.tableLayers(3);
  for (const char* name : {"0", "CAM_SURFACE", "CAM_PITCH"})
    dxf.writeLayer(dw, DL_LayerData(name, 0),
                   DL_Attributes("",
                                 name[0] == '0'   ? 7
                                 : name[4] == 'S' ? 5
                                                  : 8,
                                 0, "CONTINUOUS", 1.0));
  dw.tableEnd();
  dxf.writeStyle(dw, DL_StyleData("standard", 0, 2.5, 1.0, 0.0, 0, 2.5, "txt", ""));
  dxf.writeView(dw);
  dxf.writeUcs(dw);
  dw.tableAppid(1);
  dxf.writeAppid(dw, "ACAD");
  dw.tableEnd();
  dxf.writeDimStyle(dw, 1, 1, 1, 1, 1);
  dxf.writeBlockRecord(dw);
  dw.tableEnd();
  dw.sectionEnd();
  dw.sectionBlocks();
  for (const char* b : {"*Model_Space", "*Paper_Space"}) {
    dxf.writeBlock(dw, DL_BlockData(b, 0, 0.0, 0.0, 0.0));
    dxf.writeEndBlock(dw, b);
  }
  dw.sectionEnd();
  dw.sectionEntities();
  polyline(dxf, dw, points, false);
  if (pitch) polyline(dxf, dw, points, true);
  dw.sectionEnd();
  dxf.writeObjects(dw);
  dxf.writeObjectsEnd(dw);
  dw.dxfEOF();
}

}  // namespace

WriteResult writeCamProfileDxf(const std::vector<cam::CamPoint>& points, bool pitch,
                               const std::string& path) {
  // dxflib writes to a file of its own: a scratch one, read back and written atomically.
  char scratch[] = "/tmp/linkage-cam-XXXXXX";
  const int fd = mkstemp(scratch);
  if (fd < 0) return {false, path + ": no scratch file for the DXF"};
  ::close(fd);
  {
    DL_Dxf dxf;
    std::unique_ptr<DL_WriterA> dw(dxf.out(scratch, DL_Codes::AC1009));
    if (!dw) {
      std::remove(scratch);
      return {false, path + ": the DXF writer could not open its scratch file"};
    }
    writeDrawing(dxf, *dw, points, pitch);
    dw->close();
  }
  std::ifstream in(scratch, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  std::remove(scratch);
  return writeFileAtomically(path, text.str());
}

}  // namespace linkage
