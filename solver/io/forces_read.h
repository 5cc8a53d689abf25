// Reading the fields of forces (optional; the format's version stays 1): a body's "mass", the
// model's "gravity" and "loads" (../shared/specs/model-format.md), refused with the place named
// when negative, not finite or of the wrong shape.
#pragma once

#include <functional>

#include "io/json_read.h"

namespace linkage::json_read {

Mass readMass(const Json& v, const std::string& path);
// [gx, gy] or [gx, gy, gz] (the world's, m/s^2): its x and y, and its z to `z` when written.
Vec2 readGravity(const Json& v, const std::string& path, std::optional<double>& z);
// "body.point" and body names resolved by the reader that knows them.
using PointRef = std::function<PointId(const Json&, const std::string&)>;
using BodyRef = std::function<BodyId(const Json&, const std::string&)>;
void readLoads(const Json& v, const std::string& path, Mechanism& m, const PointRef& point,
               const BodyRef& body);

}  // namespace linkage::json_read
