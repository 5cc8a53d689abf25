// A cam's profile written for the workshop (linkage-cli cam --out): the points as CSV, or the
// surface (and a roller's pitch curve) as closed polylines in DXF (through Debian's dxflib) or
// SVG, in the cam's own frame (mm, its centre at the origin, its axes as drawn).
#pragma once

#include <string>
#include <vector>

#include "linkage/cam_checks.h"
#include "linkage/io/atomic_file.h"

namespace linkage {

// Header `cam_deg,surface_x_mm,surface_y_mm,pitch_x_mm,pitch_y_mm,pressure_angle_deg,radius_mm`
// and a row a point (shortest round-trip numbers).
std::string camProfileCsv(const std::vector<cam::CamPoint>& points);

// An SVG of the surface (and, with `pitch`, the pitch curve dashed) in mm, y up as drawn.
std::string camProfileSvg(const std::vector<cam::CamPoint>& points, bool pitch);

// A DXF (R12, AC1009: what any CAM program reads) with the surface as a closed POLYLINE on
// layer CAM_SURFACE and, with `pitch`, the pitch curve on CAM_PITCH; written atomically.
WriteResult writeCamProfileDxf(const std::vector<cam::CamPoint>& points, bool pitch,
                               const std::string& path);

}  // namespace linkage
