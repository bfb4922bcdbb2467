// The interval certificates against independent facts: the MPFR polish's 50-digit optimum must lie
// in the certified enclosure; the dodecahedron's vertices are an exact 5-design (proof.d_designs);
// programs that are not strict optima must not be certified as such.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <random>

#include "numeric/certify/certify.hpp"
#include "numeric/certify/eigenvalue_kkt.hpp"
#include "numeric/certify/interval.hpp"
#include "numeric/criteria/evaluation.hpp"
#include "numeric/polish/polish.hpp"
#include "numeric/program/catalogue.hpp"
#include "numeric/program/program_csv.hpp"
#include "numeric/synthesis/synthesize.hpp"
#include "tests/common/run_cli.hpp"

namespace scalcal {
namespace {

Program optimum(int n, CriterionKind c) {
  SynthesisOptions o;
  o.positions = n;
  o.criterion = c;
  o.seed = 1;
  o.starts = 16;  // finds the sweep's optima at these N (E at N = 9: 2 of 16 starts) in a tenth of the default's time
  return synthesize(o).program;
}

void expect_enclosure_holds_polish(const Program& p, const char* name) {
  const CriterionKind c = *parse_criterion(name);
  const CertifyResult r = certify(p, c);
  ASSERT_EQ(r.status, CertifiedStatus::missed_local_optimum) << r.reason;
  EXPECT_GE(r.enclosure_digits, 30);
  const PolishResult polished = polish(p, c, PolishOptions{50, 40});
  ASSERT_TRUE(polished.converged());
  const certify_detail::IntervalPrecision precision(80);
  const certify_detail::Real value(polished.value_digits), lo(r.enclosure_lo), hi(r.enclosure_hi);
  // The polish prints 50 digits; the enclosure is far narrower, so compare to the polish's last digit.
  const certify_detail::Real slack = abs(value) * certify_detail::Real("1e-48");
  EXPECT_LE(lo - slack, value) << r.enclosure_lo << " vs " << polished.value_digits;
  EXPECT_GE(hi + slack, value) << r.enclosure_hi << " vs " << polished.value_digits;
}

void expect_enclosure_holds_polish(int n, const char* name) {
  expect_enclosure_holds_polish(optimum(n, *parse_criterion(name)), name);
}

TEST(Certify, DAtNineIsACertifiedLocalOptimumHoldingThePolishedValue) { expect_enclosure_holds_polish(9, "D"); }
TEST(Certify, AAtTenIsACertifiedLocalOptimumHoldingThePolishedValue) { expect_enclosure_holds_polish(10, "A"); }
TEST(Certify, SAtTenIsACertifiedLocalOptimumHoldingThePolishedValue) { expect_enclosure_holds_polish(10, "S"); }

TEST(Certify, TheDodecahedronVerticesAttainDProven) {
  const CertifyResult r = certify(resolve_program("icosahedral-20"), *parse_criterion("D"));
  EXPECT_EQ(r.status, CertifiedStatus::attained_proven) << r.reason;
  EXPECT_EQ(r.equations, 24);
  EXPECT_EQ(r.unknowns, 24);
}

TEST(Certify, OptimaThatReachTheLimitAreProvenForEveryCriterion) {
  for (const char* name : {"D", "A", "E", "S"}) {
    const CertifyResult r = certify(optimum(18, *parse_criterion(name)), *parse_criterion(name));
    EXPECT_EQ(r.status, CertifiedStatus::attained_proven) << name << ": " << r.reason;
    EXPECT_LT(std::stod(r.radius), 1e-6) << name;
  }
}

// N = 12 for D: the moment system is overdetermined, so the certificate fits the pentagonal family
// (two poles, pentagons at z = +-1/sqrt 5, proof.pentagonal_designs). A member built here by hand with
// the pentagons turned 10 and 61 degrees, then rotated, is exact up to rounding: radius at rounding level.
Program pentagonal_member(double turn0, double turn1) {
  Program p;
  p.positions = {Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(0, 0, -1)};
  const double h = 1 / std::sqrt(5.0), r = 2 / std::sqrt(5.0), pi = std::acos(-1.0);
  for (int k = 0; k < 5; ++k) {
    const double a = turn0 * pi / 180 + 2 * pi * k / 5, b = turn1 * pi / 180 + 2 * pi * k / 5;
    p.positions.push_back(Eigen::Vector3d(r * std::cos(a), r * std::sin(a), h));
    p.positions.push_back(Eigen::Vector3d(r * std::cos(b), r * std::sin(b), -h));
  }
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  for (auto& e : p.positions) e = R * e;
  return p;
}

TEST(Certify, TwelvePointDOptimaAreProvenThroughThePentagonalFamily) {
  const CriterionKind d = *parse_criterion("D");
  for (const Program& p : {resolve_program("dodecahedral-12"), pentagonal_member(10, 61)}) {
    const CertifyResult r = certify(p, d);
    EXPECT_EQ(r.status, CertifiedStatus::attained_proven) << r.reason;
    EXPECT_LT(std::stod(r.radius), 1e-14);
  }
  const CertifyResult optimised = certify(optimum(12, d), d);
  EXPECT_EQ(optimised.status, CertifiedStatus::attained_proven) << optimised.reason;
  EXPECT_LT(std::stod(optimised.radius), 1e-6);
  // Moved off the family (loose tolerance, so the attainment check runs first): by 2e-5 the fit still
  // reaches, by 1e-3 Newton on the gradient returns to a member first; either way the radius must
  // cover the move. Moved by 3e-2, beyond Newton's reach (1e-3): not proven.
  CertifyOptions loose;
  loose.attained_tolerance = 1e-2;
  for (double move : {3e-2, 1e-3, 2e-5}) {
    Program moved = pentagonal_member(10, 61);
    moved.positions[4] = (moved.positions[4] + Eigen::Vector3d(move, 0, 0)).normalized();
    const CertifyResult r = certify(moved, d, loose);
    if (move > 1e-2) {
      EXPECT_NE(r.status, CertifiedStatus::attained_proven) << r.reason;
      EXPECT_NE(r.status, CertifiedStatus::missed_local_optimum) << r.reason;
    } else {
      ASSERT_EQ(r.status, CertifiedStatus::attained_proven) << r.reason;
      EXPECT_GT(std::stod(r.radius), 0.5 * move);
      EXPECT_LT(std::stod(r.radius), 10 * move);
    }
  }
}

// A design moved off the limit lies near a continuum of optima (N = 20 has many 4-designs), so
// no strict local optimum may be claimed; a random program is no optimum at all.
TEST(Certify, ProgramsThatAreNotStrictOptimaAreNotCertified) {
  Program moved = resolve_program("icosahedral-20");
  moved.positions[3] = (moved.positions[3] + Eigen::Vector3d(1e-3, -2e-3, 0)).normalized();
  EXPECT_EQ(certify(moved, *parse_criterion("D")).status, CertifiedStatus::missed_numerical);
  EXPECT_EQ(certify(resolve_program("random-18-s7"), *parse_criterion("A")).status, CertifiedStatus::missed_numerical);
}

// E at N = 9 from the committed best program (proofs/designs/e9_best.csv, E = 12.1871926420): the multistart's
// 16 starts reach it under some BLAS kernels and not others (Haswell's best start ends at 12.3957, a
// different critical point whose 4-fold cluster is no strict minimum), so the certificate is tested on
// the program itself, whatever the kernel.
TEST(Certify, EAtNineIsACertifiedLocalOptimumHoldingThePolishedValue) {
  const Program best = read_program_csv(std::string(SCALCAL_SOURCE_DIR) + "/proofs/designs/e9_best.csv");
  ASSERT_EQ(best.size(), 9);
  EXPECT_NEAR(criterion_value(best, *parse_criterion("E")), 12.1871926420, 1e-9);
  expect_enclosure_holds_polish(best, "E");
}

// The E certificate claims a strict local minimum of a nonsmooth function (the smallest eigenvalue of
// M is 5-fold there): no small random move of the positions may lower E. A D optimum is no E
// optimum, so the E certificate must refuse it.
TEST(Certify, TheEOptimumAtTenSurvivesRandomMovesAndADOptimumIsRefused) {
  const CriterionKind e = *parse_criterion("E");
  const Program p = optimum(10, e);
  const CertifyResult r = certify(p, e);
  ASSERT_EQ(r.status, CertifiedStatus::missed_local_optimum) << r.reason;
  EXPECT_NE(r.reason.find("multiplicity 5"), std::string::npos) << r.reason;
  const double e0 = criterion_value(p, e);
  std::mt19937_64 rng(11);
  std::normal_distribution<double> gauss;
  double lowest = 1e300;
  for (int trial = 0; trial < 400; ++trial) {
    Program q = p;
    for (auto& x : q.positions) x = (x + 1e-4 * Eigen::Vector3d(gauss(rng), gauss(rng), gauss(rng))).normalized();
    lowest = std::min(lowest, criterion_value(q, e));
  }
  EXPECT_GT(lowest, e0 * (1 + 1e-12)) << "a random move lowered E: not a local minimum";
  EXPECT_EQ(certify(optimum(9, *parse_criterion("D")), e).status, CertifiedStatus::missed_numerical);
}

// Krawczyk is only as sound as the Jacobian it is given: the E system's closed-form Jacobian (second
// derivatives of a Schur complement) against central differences of its residual, at a point off the
// solution (moved positions, lambda and Omega arbitrary), where every term is nonzero.
TEST(Certify, TheESystemJacobianMatchesCentralDifferences) {
  using namespace certify_detail;
  const Program p = optimum(10, *parse_criterion("E"));
  const SphereChart chart = SphereChart::of(p);
  EigenvalueKktSystem system{&chart, FreeCoordinates::all_but(2 * p.size(), {}), 5, {}};
  const Eigen::Matrix<double, 9, 9> M0 = assemble_information<double>(chart, Eigen::VectorXd::Zero(2 * p.size()));
  system.basis = Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 9, 9>>(M0).eigenvectors();
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> uniform(-0.02, 0.02);
  Eigen::VectorXd z(system.size());
  for (int k = 0; k < system.size(); ++k) z(k) = uniform(rng);
  z(system.free_size()) = 0.9 * Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 9, 9>>(M0).eigenvalues()(0);
  Eigen::VectorXd F;
  Eigen::MatrixXd J;
  system.eval<double>(z, F, &J);
  double worst = 0;
  for (int k = 0; k < system.size(); ++k) {
    const double step = 1e-6;
    Eigen::VectorXd up = z, down = z, Fu, Fd;
    up(k) += step;
    down(k) -= step;
    system.eval<double>(up, Fu, nullptr);
    system.eval<double>(down, Fd, nullptr);
    worst = std::max(worst, ((Fu - Fd) / (2 * step) - J.col(k)).cwiseAbs().maxCoeff());
  }
  EXPECT_LT(worst, 1e-6 * std::max(1.0, J.cwiseAbs().maxCoeff())) << "largest entry " << J.cwiseAbs().maxCoeff();
}

TEST(CertifyCli, JsonHasTheIssueKeys) {
  const auto r = testing::run_cli("certify icosahedral-20 --criterion D --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("status"), "limit attained, proven");
  EXPECT_TRUE(j.at("radius").is_string());
  EXPECT_TRUE(j.at("enclosure").is_null());
  EXPECT_GE(j.at("seconds").get<double>(), 0.0);
  const auto text = testing::run_cli("certify nine-2axes --criterion D");
  ASSERT_EQ(text.status, 0) << text.err;
  EXPECT_NE(text.out.find("status     "), std::string::npos);
}

TEST(CertifyCli, BadInputExitsTwo) {
  const auto singular = testing::run_cli("certify rotation-4 --criterion D");
  EXPECT_EQ(singular.status, 2);
  EXPECT_NE(singular.err.find("singular"), std::string::npos) << singular.err;
  EXPECT_EQ(testing::run_cli("certify classic18 --criterion Q").status, 2);
  EXPECT_EQ(testing::run_cli("certify classic18").status, 2);
  const std::string few = testing::write_file("few.csv", "x,y,z\n1,0,0\n0,1,0\n0,0,1\n");
  EXPECT_EQ(testing::run_cli("certify " + few + " --criterion D").status, 2);
}

// polish reports the second order: the D optimum at N = 9 is a certified minimum; the critical point
// that the polish reaches from rotation-3 is a saddle, which plain perturbations show independently.
TEST(PolishSecondOrder, TellsAMinimumFromASaddle) {
  const std::string optimum9 = (testing::scratch_dir() / "optimum9.csv").string();
  ASSERT_EQ(testing::run_cli("optimize --positions 9 --criterion D --seed 1 --out " + optimum9).status, 0);
  const auto minimum = testing::run_cli("polish " + optimum9 + " --criterion D --digits 30 --json");
  ASSERT_EQ(minimum.status, 0) << minimum.err;
  EXPECT_EQ(nlohmann::json::parse(minimum.out).at("second_order"), "missed, certified local optimum");

  const std::string out = (testing::scratch_dir() / "saddle.csv").string();
  const auto saddle = testing::run_cli("polish rotation-3 --criterion D --digits 30 --json --out " + out);
  ASSERT_EQ(saddle.status, 0) << saddle.err;
  EXPECT_NE(nlohmann::json::parse(saddle.out).at("second_order"), "missed, certified local optimum");
  const Program p = read_program_csv(out);
  const double d0 = criterion_value(p, *parse_criterion("D"));
  std::mt19937_64 rng(7);
  std::normal_distribution<double> gauss;
  double best = d0;
  for (int trial = 0; trial < 400; ++trial) {
    Program q = p;
    for (auto& e : q.positions) e = (e + 1e-3 * Eigen::Vector3d(gauss(rng), gauss(rng), gauss(rng))).normalized();
    best = std::min(best, criterion_value(q, *parse_criterion("D")));
  }
  EXPECT_LT(best, d0 * (1 - 1e-9)) << "no descent direction found: not a saddle";
}

}  // namespace
}  // namespace scalcal
