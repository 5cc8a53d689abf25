#include "kinematics/motion.h"

namespace linkage {

void Motion::fromCoordinates(double phiAt, const Eigen::VectorXd& q, const Eigen::VectorXd& dq,
                             const Eigen::VectorXd& ddq) {
  phi = phiAt;
  accelerations = true;
  body.resize(q.size() / 3);
  for (int k = 0; k < static_cast<int>(body.size()); ++k) bodyFromCoordinates(k, q, dq, ddq);
}

void Motion::bodyFromCoordinates(int k, const Eigen::VectorXd& q, const Eigen::VectorXd& dq,
                                 const Eigen::VectorXd& ddq) {
  BodyState& b = body[k];
  const int c = 3 * k;
  const double th = q[c + 2];
  b.r = Vec2(q[c], q[c + 1]);
  b.R = Rot{std::cos(th), std::sin(th)};
  b.turns = std::round((th - std::atan2(b.R.s, b.R.c)) / (2 * M_PI));
  b.v = Vec2(dq[c], dq[c + 1]);
  b.w = dq[c + 2];
  b.a = Vec2(ddq[c], ddq[c + 1]);
  b.al = ddq[c + 2];
}

void Motion::toCoordinates(Eigen::VectorXd& q, Eigen::VectorXd& dq, Eigen::VectorXd& ddq) const {
  const int n = 3 * static_cast<int>(body.size());
  q.resize(n);
  dq.resize(n);
  ddq.resize(n);
  for (size_t k = 0; k < body.size(); ++k) {
    const BodyState& b = body[k];
    const int c = 3 * static_cast<int>(k);
    q.segment<2>(c) = b.r;
    q[c + 2] = b.angle();
    dq.segment<2>(c) = b.v;
    dq[c + 2] = b.w;
    ddq.segment<2>(c) = b.a;
    ddq[c + 2] = b.al;
  }
}

}  // namespace linkage
