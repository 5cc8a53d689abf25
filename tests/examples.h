// The example mechanisms (resources/examples) by name, for tests.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "linkage/io/model_file.h"
#include "linkage/timing.h"

namespace linkage::test {

// The example's mechanism; a failure of the test (and an empty mechanism) when it cannot be read.
inline Mechanism example(const std::string& name) {
  LoadResult r =
      loadMechanismFile(std::string(LINKAGE_EXAMPLES_DIR) + "/" + name + ".linkage.json");
  EXPECT_TRUE(r.mechanism.has_value()) << r.error;
  return r.mechanism ? *r.mechanism : Mechanism{};
}

// The example with a timing window as `linkage-cli timing --window` types it ("low=P:z>6").
inline Mechanism exampleWithWindow(const std::string& name, const std::string& window) {
  Mechanism m = example(name);
  std::string why;
  const std::optional<CycleWindow> w = parseWindow(m, window, &why);
  EXPECT_TRUE(w) << why;
  if (w) m.timing.windows.push_back({w->name, w->output.measure, w->below, w->level});
  return m;
}

// The RSSR crank-rocker with masses on its crank and rocker and gravity along -y: what the tests
// of forces, balancing and their derivatives on a machine in space share.
inline Mechanism rssrWithMasses() {
  Mechanism m = example("rssr-crank-rocker");
  m.body(m.bodyNamed("crank")->id)->mass = Mass{0.3, Vec2(10, 3), 60, ""};
  m.body(m.bodyNamed("rocker")->id)->mass =
      Mass{0.2, m.point(*m.findPoint("rocker.C"))->pos, 90, ""};
  m.gravity = Vec2(0, -9.81);
  return m;
}

}  // namespace linkage::test
