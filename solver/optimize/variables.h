// How the search's variables act on a design (linkage/optimize.h): each one a dimension (an index
// into the dimensions the sensitivities are prepared with) or an axis of a counterweight's static
// moment; and the peak targets' rows (the shaking force's).
#pragma once

#include <string>
#include <vector>

#include "linkage/balance.h"
#include "linkage/optimize.h"
#include "linkage/sensitivity.h"

namespace linkage::opt {

struct Variables {
  std::vector<int> dim;   // by variable: its index into `dims`, -1 for a counterweight's
  std::vector<int> cw;    // by variable: its index into `counterweights`, -1 for a dimension's
  std::vector<int> axis;  // 0 x, 1 y (a counterweight's)
  std::vector<Dimension> dims;                // the design's, in the variables' order
  std::vector<Counterweight> counterweights;  // on the base design, none added yet
  size_t dimensionCount() const { return dims.size(); }
  // Counterweight k's static moment (kg mm) at x; its mass the least that gives it.
  Vec2 moment(const std::vector<double>& x, size_t k) const;
  double kg(const std::vector<double>& x, size_t k) const;
};

// `BODY.counterweight.x` or `.y`: the body's name and the axis; false for another name.
bool counterweightName(const std::string& name, std::string& body, int& axis);

// The counterweights (from the base design: their pivots and reaches) and the design's
// dimensions the variables name. BadModel naming the variable.
Status mapVariables(const Mechanism& base, const Mechanism& design, const OptimizeSpec& spec,
                    Variables& out);

// A clearance's or a window's end's residual, measure, objective term and gradient at design k
// (sens prepared with vars.dims when a gradient is asked for, else null).
Status clearanceResiduals(const Kinematics& k, const OptimizeSpec& spec, size_t target,
                          const Variables& vars, bool withGradient, Evaluation& e);
Status windowResiduals(const Kinematics& k, const OptimizeSpec& spec, size_t target,
                       const Variables& vars, bool withGradient, Evaluation& e);

// A shaking target's rows, measure, objective term and gradients at design k, its variables x.
Status shakingResiduals(const Kinematics& k, const OptimizeSpec& spec, size_t target,
                        const Variables& vars, const std::vector<double>& x, Sensitivity* sens,
                        Evaluation& e);

}  // namespace linkage::opt
