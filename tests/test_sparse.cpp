// Large mechanisms: the sparse LU (sparse_lu.h) against the dense one and against the
// closed-form group solve, and the sparse proof of independent rows (independent_rows.h)
// against a dense singular value decomposition and the dense structure analysis.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <climits>
#include <random>

#include "elements/body_view.h"
#include "kinematics/kinematics_state.h"
#include "linkage/elements.h"
#include "linkage/kinematics.h"
#include "mechanisms.h"
#include "structure/independent_rows.h"
#include "system/dense_lu.h"
#include "system/sparse_lu.h"

namespace linkage {
namespace {

// A random sparse matrix shaped like a mechanism's Jacobian: every row touches two "bodies"
// (three columns each), with a unit diagonal added so that it is regular.
Eigen::SparseMatrix<double> randomJacobianLike(int bodies, std::mt19937& rng) {
  std::uniform_int_distribution<int> body(0, bodies - 1);
  std::uniform_real_distribution<double> value(-1, 1);
  const int n = 3 * bodies;
  std::vector<Eigen::Triplet<double>> t;
  for (int r = 0; r < n; ++r) {
    const int a = r / 3, b = body(rng);
    for (int c = 0; c < 3; ++c) {
      t.emplace_back(r, 3 * a + c, value(rng));
      t.emplace_back(r, 3 * b + c, value(rng));
    }
    t.emplace_back(r, r, 2.0);
  }
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  A.makeCompressed();
  return A;
}

TEST(SparseLU, SolvesAndSignAgreeWithTheDenseLU) {
  std::mt19937 rng(20261122);
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::SparseMatrix<double> A = randomJacobianLike(30 + trial, rng);
    const Eigen::MatrixXd D(A);
    SparseLU s;
    s.analyzePattern(A);
    s.compute(A);
    DenseLU d;
    d.resize(static_cast<int>(D.rows()));
    d.compute(D);
    EXPECT_EQ(s.detSign(), d.detSign()) << trial;
    // Independent of both: the determinant's sign from Eigen's full-pivot LU.
    EXPECT_EQ(s.detSign(), D.fullPivLu().determinant() > 0 ? 1 : -1) << trial;
    EXPECT_GT(s.pivotRatio(), 1e-8);
    Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(D.rows(), -1, 2), x = b;
    s.solveInPlace(x);
    EXPECT_LT((D * x - b).norm(), 1e-12 * b.norm()) << trial;
  }
}

// The transposed solves (forces reuse the kinematics' factors), checked by the residual of A^T,
// for the unblocked dense LU, the blocked one (64 on) and the sparse one.
TEST(SparseLU, TransposedSolvesOfAllThreeFactorisations) {
  std::mt19937 rng(20261124);
  for (const int bodies : {3, 17, 25, 40}) {
    const Eigen::SparseMatrix<double> A = randomJacobianLike(bodies, rng);
    const Eigen::MatrixXd D(A);
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(D.rows(), -1, 2);
    SparseLU s;
    s.analyzePattern(A);
    s.compute(A);
    DenseLU d;
    d.resize(static_cast<int>(D.rows()));
    d.compute(D);
    Eigen::VectorXd xs = b, xd = b;
    s.solveTransposedInPlace(xs);
    d.solveTransposedInPlace(xd);
    EXPECT_LT((D.transpose() * xs - b).norm(), 1e-12 * b.norm() * D.norm()) << bodies;
    EXPECT_LT((D.transpose() * xd - b).norm(), 1e-12 * b.norm() * D.norm()) << bodies;
    // Not the plain solve: A is not symmetric.
    Eigen::VectorXd plain = b;
    d.solveInPlace(plain);
    EXPECT_GT((plain - xd).norm(), 1e-3 * xd.norm()) << bodies;
  }
}

TEST(SparseLU, SingularMatricesHaveARoundingLevelPivotRatio) {
  std::mt19937 rng(7);
  Eigen::SparseMatrix<double> A = randomJacobianLike(40, rng);
  // Row 5 replaced by the sum of rows 11 and 30: singular, in the same pattern plus fill.
  Eigen::MatrixXd D(A);
  D.row(5) = D.row(11) + D.row(30);
  Eigen::SparseMatrix<double> S = D.sparseView();
  SparseLU s;
  s.compute(S);
  EXPECT_LT(s.pivotRatio(), 1e-12);
  // A zero column leaves nothing to pivot on at all.
  D.col(7).setZero();
  S = D.sparseView();
  S.makeCompressed();
  SparseLU z;
  z.compute(S);
  EXPECT_EQ(z.pivotRatio(), 0.0);
}

TEST(SparseLU, CopiesKeepTheirResultsAndFactorAgain) {
  std::mt19937 rng(11);
  const Eigen::SparseMatrix<double> A = randomJacobianLike(25, rng);
  SparseLU s;
  s.analyzePattern(A);
  s.compute(A);
  SparseLU copy = s;
  EXPECT_EQ(copy.detSign(), s.detSign());
  EXPECT_EQ(copy.pivotRatio(), s.pivotRatio());
  copy.compute(A);
  Eigen::VectorXd x = Eigen::VectorXd::Ones(A.rows()), y = x;
  s.solveInPlace(x);
  copy.solveInPlace(y);
  EXPECT_LT((x - y).norm(), 1e-12 * x.norm());
}

TEST(IndependentRows, NeverClaimsMoreThanTheSingularValuesShow) {
  std::mt19937 rng(3);
  int proved = 0;
  for (int trial = 0; trial < 30; ++trial) {
    Eigen::SparseMatrix<double> A = randomJacobianLike(20, rng);
    Eigen::MatrixXd D(A);
    if (trial % 3 == 1) D.row(4) = D.row(9) + 1e-6 * D.row(4);  // nearly dependent
    if (trial % 3 == 2) D.row(4) = D.row(9) + 1e-2 * D.row(4);  // clearly independent
    for (int r = 0; r < D.rows(); ++r) D.row(r).normalize();
    const double smin = Eigen::JacobiSVD<Eigen::MatrixXd>(D).singularValues().minCoeff();
    A = D.sparseView();
    const bool yes = rowsIndependent(A, 1e-5);
    if (yes) {
      ++proved;
      EXPECT_GT(smin, 1e-5) << trial;
    }
    if (smin > 1e-4) EXPECT_TRUE(yes) << trial << ": smallest singular value " << smin;
  }
  EXPECT_GT(proved, 10);
}

// The structure analysis's sparse path applies to the chains of four-bars (the benchmarks' large
// mechanisms): joint and driver rows, theta columns scaled by 1 / L as structure.cpp does.
TEST(IndependentRows, ChainsOfFourBarsAreProved) {
  for (int loops : {25, 250}) {
    const Mechanism m = test::fourBarChain(loops);
    Status st;
    const std::optional<System> sys = compile(m, st);
    ASSERT_TRUE(sys);
    std::vector<BodyView> views;
    makeViews(*sys, sketchCoordinates(*sys), nullptr, views);
    std::vector<int> all(sys->nRows);
    for (int r = 0; r < sys->nRows; ++r) all[r] = r;
    ASSERT_EQ(sys->nRows, sys->nCoords());
    Eigen::MatrixXd J(sys->nRows, sys->nCoords());
    evalJacobian(*sys, views, all, J);
    for (int k = 0; k < sys->nBodies; ++k) J.col(3 * k + 2) /= sys->size;
    EXPECT_TRUE(rowsIndependent(J.sparseView(), 1e-5)) << loops;
  }
}

KinematicsOptions options(bool closedForm, bool sparse) {
  KinematicsOptions o;
  o.closedForm = closedForm;
  o.sparseFrom = sparse ? 0 : INT_MAX;
  return o;
}

// 101 bodies, 303 coordinates: the general solve by the sparse LU against the group solve,
// which shares no factorisation with it.
TEST(SparseSolve, LargeChainMatchesTheClosedFormGroups) {
  const Mechanism m = test::fourBarChain(50);
  Kinematics general(options(false, true)), groups(options(true, true));
  ASSERT_TRUE(general.load(m).ok());
  ASSERT_TRUE(groups.load(m).ok());
  ASSERT_TRUE(general.sparseSolve());
  ASSERT_FALSE(general.closedForm());
  ASSERT_TRUE(groups.closedForm());
  const PointId out = m.outputs[0];
  for (double a = 0; a <= 360; a += 7.5) {
    ASSERT_TRUE(general.moveTo(a).ok()) << a;
    ASSERT_TRUE(groups.moveTo(a).ok()) << a;
    const double dqScale = 1 + groups.dq().cwiseAbs().maxCoeff();
    const double ddqScale = 1 + groups.ddq().cwiseAbs().maxCoeff();
    EXPECT_LT((general.q() - groups.q()).cwiseAbs().maxCoeff(), 1e-9) << a;
    EXPECT_LT((general.dq() - groups.dq()).cwiseAbs().maxCoeff(), 1e-9 * dqScale) << a;
    EXPECT_LT((general.ddq() - groups.ddq()).cwiseAbs().maxCoeff(), 1e-9 * ddqScale) << a;
    EXPECT_LT((general.acceleration(out) - groups.acceleration(out)).norm(),
              1e-9 * (1 + groups.acceleration(out).norm()))
        << a;
  }
}

// Same mechanism, dense and sparse: the same structure, the same motion, copies included.
TEST(SparseSolve, DenseAndSparseGiveTheSameStructureAndMotion) {
  const Mechanism m = test::fourBarChain(25);
  Kinematics dense(options(false, false)), sparse(options(false, true));
  ASSERT_TRUE(dense.load(m).ok());
  ASSERT_TRUE(sparse.load(m).ok());
  ASSERT_FALSE(dense.sparseSolve());
  ASSERT_TRUE(sparse.sparseSolve());
  EXPECT_EQ(internal::structure(sparse).activeRows, internal::structure(dense).activeRows);
  ASSERT_TRUE(sparse.moveTo(100).ok());
  Kinematics copy = sparse;  // Eigen's factors cannot be copied: the copy analyses again
  for (double a = 100; a <= 250; a += 50) {
    ASSERT_TRUE(dense.moveTo(a).ok()) << a;
    ASSERT_TRUE(copy.moveTo(a).ok()) << a;
    EXPECT_LT((dense.q() - copy.q()).cwiseAbs().maxCoeff(), 1e-9) << a;
    EXPECT_LT((dense.dq() - copy.dq()).cwiseAbs().maxCoeff(),
              1e-9 * (1 + dense.dq().cwiseAbs().maxCoeff()))
        << a;
  }
}

// 51 bodies; loop 0 is non-Grashof (crank 45, coupler 70, rocker 50 on 60): turned clockwise, the
// crank locks where coupler and rocker fold, |A - O4| = 20, at crank angle 1 rad - acos(5225 /
// 5400).
TEST(SparseSolve, LargeChainLockingIsReportedAsByTheDenseSolve) {
  Mechanism m = test::fourBarChain(25, 45, 70, 50);
  m.driver->direction = Direction::Cw;
  const double lockDeg = (1.0 - std::acos(5225.0 / 5400)) * 180 / M_PI;
  for (bool closedForm : {false, true}) {
    Kinematics dense(options(closedForm, false)), sparse(options(closedForm, true));
    ASSERT_TRUE(dense.load(m).ok());
    ASSERT_TRUE(sparse.load(m).ok());
    const Status d = dense.moveTo(60), s = sparse.moveTo(60);
    EXPECT_EQ(s.code, StatusCode::Unreachable) << s.message;
    EXPECT_EQ(s.code, d.code);
    EXPECT_EQ(s.message, d.message);
    ASSERT_TRUE(s.lastReachedDeg && d.lastReachedDeg);
    EXPECT_NEAR(*s.lastReachedDeg, lockDeg, 1e-3);
    EXPECT_NEAR(*s.lastReachedDeg, *d.lastReachedDeg, 1e-9);
    EXPECT_NE(s.message.find("'coupler0', 'rocker0'"), std::string::npos) << s.message;
    EXPECT_LT((sparse.q() - dense.q()).cwiseAbs().maxCoeff(), 1e-9);
  }
}

// Loop 0 a parallelogram (25, 60, 25 on 60): all in line at crank angle -1 rad, where its two
// branches cross. The chain on the general path, turned to -56 degrees, 1.3 degrees short of it.
constexpr double changeDeg = -180 / M_PI;

Kinematics nearChangePoint(const Mechanism& m, bool sparse) {
  Kinematics k(options(false, sparse));
  EXPECT_TRUE(k.load(m).ok());
  EXPECT_EQ(k.sparseSolve(), sparse);
  EXPECT_TRUE(k.moveTo(-56).ok());
  return k;
}

// Landing on it: 12 loops, 75 coordinates, sparse by default.
TEST(SparseSolve, LandingOnTheChangePointOfALargeChainIsReportedAsByTheDenseSolve) {
  const Mechanism m = test::fourBarChain(12, 25, 60, 25);
  Kinematics dense = nearChangePoint(m, false), sparse = nearChangePoint(m, true);
  const Status d = dense.moveTo(changeDeg), s = sparse.moveTo(changeDeg);
  EXPECT_EQ(s.code, StatusCode::Singular) << s.message;
  EXPECT_EQ(s.message, d.message);
  EXPECT_FALSE(sparse.derivativesValid());
  EXPECT_FALSE(dense.derivativesValid());
  EXPECT_LT((sparse.q() - dense.q()).cwiseAbs().maxCoeff(), 1e-9);
}

// Across it: both stop before it, on the parallelogram branch. Where exactly they give up, within
// a 1e-6 degree of it, depends on rounding in Newton next to a singular J, so the angle in the
// message is compared to 1e-5 degrees, not as text.
TEST(SparseSolve, CrossingTheChangePointIsRefusedAsByTheDenseSolve) {
  const Mechanism m = test::fourBarChain(4, 25, 60, 25);
  Kinematics dense = nearChangePoint(m, false), sparse = nearChangePoint(m, true);
  const Status d = dense.moveTo(-70), s = sparse.moveTo(-70);
  EXPECT_EQ(s.code, StatusCode::Singular) << s.message;
  EXPECT_EQ(d.code, StatusCode::Singular) << d.message;
  EXPECT_NE(s.message.find("branches meet"), std::string::npos) << s.message;
  EXPECT_NE(d.message.find("branches meet"), std::string::npos) << d.message;
  ASSERT_TRUE(s.lastReachedDeg && d.lastReachedDeg);
  EXPECT_NEAR(*s.lastReachedDeg, *d.lastReachedDeg, 1e-5);
  EXPECT_GT(*s.lastReachedDeg, changeDeg);
  EXPECT_NEAR(*s.lastReachedDeg, changeDeg, 1e-5);
  const int coupler0 = internal::system(sparse).bodyIndex(m.bodyNamed("coupler0")->id);
  EXPECT_NEAR(sparse.q()[3 * coupler0 + 2], 0, 1e-6);  // still the parallelogram
}

void expectSameStructure(const Structure& a, const Structure& b, const std::string& what) {
  EXPECT_EQ(a.coordinates, b.coordinates) << what;
  EXPECT_EQ(a.jointEquations, b.jointEquations) << what;
  EXPECT_EQ(a.gruebler, b.gruebler) << what;
  EXPECT_EQ(a.rank, b.rank) << what;
  EXPECT_EQ(a.mobility, b.mobility) << what;
  EXPECT_EQ(a.dependentRows, b.dependentRows) << what;
  EXPECT_EQ(a.redundantJoints, b.redundantJoints) << what;
  EXPECT_EQ(a.driverMoves, b.driverMoves) << what;
  EXPECT_EQ(a.freeAfterDriver, b.freeAfterDriver) << what;
  EXPECT_EQ(a.freeBodies, b.freeBodies) << what;
  EXPECT_EQ(a.holdCoordinates, b.holdCoordinates) << what;
  EXPECT_EQ(a.activeRows, b.activeRows) << what;
  ASSERT_EQ(a.nullBasis.rows(), b.nullBasis.rows()) << what;
  ASSERT_EQ(a.nullBasis.cols(), b.nullBasis.cols()) << what;
  if (a.nullBasis.size()) EXPECT_LT((a.nullBasis - b.nullBasis).cwiseAbs().maxCoeff(), 1e-12);
}

// The sparse proof where it applies, the dense Gram-Schmidt where it does not: the Structure
// is the one the dense analysis alone gives, in every case.
TEST(SparseStructure, SameAsTheDenseAnalysisWhateverTheCase) {
  struct Case {
    std::string what;
    Mechanism m;
    StatusCode load = StatusCode::Ok;
    size_t redundant = 0;
    int free = 0;
  };
  std::vector<Case> cases;
  const Mechanism chain = test::fourBarChain(25);  // 51 bodies, 153 coordinates
  cases.push_back({"chain", chain, StatusCode::Ok, 0, 0});
  {
    // The last loop's coupler-rocker pin drawn twice: the second is redundant.
    Mechanism m = chain;
    const BodyId c = m.bodyNamed("coupler24")->id, r = m.bodyNamed("rocker24")->id;
    const Vec2 B = m.pointNamed(c, "B")->pos;
    m.addPin(m.addPoint(c, "B2", B), m.addPoint(r, "B2", B));
    cases.push_back({"redundant pin", m, StatusCode::Ok, 1, 0});
  }
  {
    // A roller on the last rocker's pin spins freely: a freedom the driver leaves.
    Mechanism m = chain;
    const BodyId r = m.bodyNamed("rocker24")->id, roller = m.addBody("roller");
    const Vec2 A = m.pointNamed(r, "A")->pos;
    m.addPin(m.addPoint(r, "axle", A), m.addPoint(roller, "C", A));
    m.addPoint(roller, "rim", A + Vec2(5, 0));
    cases.push_back({"idle roller", m, StatusCode::Ok, 0, 1});
  }
  {
    // The first rocker pinned to the ground a second time: the driver cannot turn.
    Mechanism m = chain;
    const BodyId r = m.bodyNamed("rocker0")->id;
    const Vec2 A = m.pointNamed(r, "A")->pos;
    m.addPin(m.addPoint(r, "fix", A), m.addPoint(m.ground()->id, "fix", A));
    cases.push_back({"locked", m, StatusCode::Locked, 1, 0});
  }
  {
    Mechanism m = chain;
    m.driver.reset();
    cases.push_back({"no driver", m, StatusCode::Ok, 0, 1});
  }
  for (const Case& c : cases) {
    Status st;
    const std::optional<System> sys = compile(c.m, st);
    ASSERT_TRUE(sys) << c.what;
    const Eigen::VectorXd q = sketchCoordinates(*sys);
    const Structure a = analyzeStructure(*sys, q, 0);
    EXPECT_EQ(a.redundantJoints.size(), c.redundant) << c.what;
    EXPECT_EQ(a.freeAfterDriver, c.free) << c.what;
    expectSameStructure(a, analyzeStructure(*sys, q, INT_MAX), c.what);
    Kinematics dense(options(false, false)), sparse(options(false, true));
    const Status d = dense.load(c.m), s = sparse.load(c.m);
    EXPECT_EQ(s.code, c.load) << c.what << ": " << s.message;
    EXPECT_EQ(s.code, d.code) << c.what;
    EXPECT_EQ(s.message, d.message) << c.what;
    EXPECT_EQ(sparse.notes(), dense.notes()) << c.what;
  }
}

// Assembly of large drawings: a hand-drawn one closes as with the dense solve, and one that
// cannot close is explained in the same words (the least-squares fit by sparse normal
// equations finds the same closest configuration).
TEST(SparseAssembly, LargeDrawingsAssembleOrFailAsWithTheDenseSolve) {
  const int loops = 15;
  Mechanism hand = test::fourBarChain(loops);
  const BodyId rocker = hand.bodyNamed("rocker7")->id;
  for (Point& p : hand.points)
    if (p.body == rocker && p.name == "B") p.pos += Vec2(0.3, -0.2);
  Kinematics dense(options(false, false)), sparse(options(false, true));
  ASSERT_TRUE(dense.load(hand).ok());
  ASSERT_TRUE(sparse.load(hand).ok());
  EXPECT_TRUE(sparse.assembly().moved);
  EXPECT_EQ(sparse.notes(), dense.notes());
  EXPECT_LT((sparse.q() - dense.q()).cwiseAbs().maxCoeff(), 1e-9);
  const PointId rB = *hand.findPoint("rocker7.B"), cB = *hand.findPoint("coupler7.B");
  EXPECT_LT((sparse.position(rB) - sparse.position(cB)).norm(), 1e-9);

  Mechanism broken = test::fourBarChain(loops);
  for (Point& p : broken.points)
    if (p.body == broken.ground()->id && p.name == "O4_7") p.pos += Vec2(300, 0);
  const Status d = dense.load(broken), s = sparse.load(broken);
  EXPECT_EQ(s.code, StatusCode::AssemblyFailed) << s.message;
  EXPECT_NE(s.message.find(jointName(broken, broken.joints[24].id)), std::string::npos)
      << s.message;
  EXPECT_EQ(s.message.find("joints["), std::string::npos) << s.message;
  EXPECT_EQ(s.message, d.message);
  EXPECT_EQ(s.joints, d.joints);
}

// A mechanism that does not decompose into groups (a chain of triads, 49 bodies): the sparse
// general solve against the dense one, and every pin closed.
TEST(SparseSolve, ChainOfTriadsIsSolvedAsByTheDenseSolve) {
  const Mechanism m = test::triadChain(12);
  Kinematics dense(options(true, false)), sparse(options(true, true));
  ASSERT_TRUE(dense.load(m).ok());
  ASSERT_TRUE(sparse.load(m).ok());
  ASSERT_FALSE(sparse.closedForm());
  ASSERT_TRUE(sparse.sparseSolve());
  for (double a = 0; a <= 180; a += 30) {
    ASSERT_TRUE(dense.moveTo(a).ok()) << a;
    ASSERT_TRUE(sparse.moveTo(a).ok()) << a;
    EXPECT_LT((sparse.q() - dense.q()).cwiseAbs().maxCoeff(), 1e-9) << a;
    EXPECT_LT((sparse.dq() - dense.dq()).cwiseAbs().maxCoeff(),
              1e-9 * (1 + dense.dq().cwiseAbs().maxCoeff()))
        << a;
    EXPECT_LT((sparse.ddq() - dense.ddq()).cwiseAbs().maxCoeff(),
              1e-9 * (1 + dense.ddq().cwiseAbs().maxCoeff()))
        << a;
    for (const Joint& j : m.joints)
      EXPECT_LT((sparse.position(j.a) - sparse.position(j.b)).norm(), 1e-9) << a;
  }
}

// Landing on it and crossing it on chains of any length. The pivots of a partial-pivot LU stop
// showing the singular position from about 18 loops (the small factor spreads over many
// pivots), and across it the step may land on the other branch with det J of the same sign:
// the inverse-iteration estimate (NewtonSolver::nearness) and the velocity continuity test
// (Kinematics::sameBranch) must catch both, dense and sparse alike.
TEST(GeneralSolve, LandingOnAChangePointIsReportedOnChainsOfAnyLength) {
  for (int loops : {18, 30, 50}) {
    const Mechanism m = test::fourBarChain(loops, 25, 60, 25);
    for (bool sparse : {false, true}) {
      if (!sparse && loops > 20) continue;  // the dense solve is slow there, and says the same
      Kinematics k = nearChangePoint(m, sparse);
      const std::string what = std::to_string(loops) + (sparse ? " loops, sparse" : " loops");
      const Status s = k.moveTo(changeDeg);
      EXPECT_EQ(s.code, StatusCode::Singular) << what << ": " << s.message;
      EXPECT_FALSE(k.derivativesValid()) << what;
      EXPECT_TRUE(std::isnan(k.velocity(m.outputs[0]).x())) << what;
    }
  }
}

TEST(GeneralSolve, CrossingAChangePointIsRefusedOnChainsOfAnyLength) {
  for (int loops : {4, 8, 20, 50}) {
    const Mechanism m = test::fourBarChain(loops, 25, 60, 25);
    for (bool sparse : {false, true}) {
      if (!sparse && loops > 20) continue;  // the dense solve is slow there, and says the same
      Kinematics k = nearChangePoint(m, sparse);
      const std::string what = std::to_string(loops) + (sparse ? " loops, sparse" : " loops");
      const Status s = k.moveTo(-70);
      EXPECT_EQ(s.code, StatusCode::Singular) << what << ": " << s.message;
      EXPECT_NE(s.message.find("branches meet"), std::string::npos) << what << ": " << s.message;
      EXPECT_NEAR(k.bodyAngle(m.bodyNamed("coupler0")->id), 0, 1e-6)
          << what << ": left the parallelogram branch";
    }
  }
}

}  // namespace
}  // namespace linkage
