// D at N = 14: the committed D3-symmetric design (proofs/designs/d3_14.csv, proof.d3_design) is proven
// to attain D through the closed-form fit, in any rotation or mirror image; a move must be covered by
// the radius; the optimiser's designs (a continuum on which the moment equations lose rank) are not.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "numeric/certify/certify.hpp"
#include "numeric/program/program_csv.hpp"
#include "numeric/synthesis/synthesize.hpp"

namespace scalcal {
namespace {

Program d3_design() { return read_program_csv(std::string(SCALCAL_SOURCE_DIR) + "/proofs/designs/d3_14.csv"); }

TEST(D3Design, TheCommittedDesignAttainsDProvenInAnyOrientation) {
  const CriterionKind d = *parse_criterion("D");
  const CertifyResult r = certify(d3_design(), d);
  ASSERT_EQ(r.status, CertifiedStatus::attained_proven) << r.reason;
  EXPECT_LT(std::stod(r.radius), 1e-15);
  EXPECT_NE(r.reason.find("proof.d3_design"), std::string::npos) << r.reason;
  // Rotated and mirrored (x -> -x), points shuffled: the same design.
  Program turned = d3_design();
  const Eigen::Matrix3d R = Eigen::AngleAxisd(2.1, Eigen::Vector3d(-1, 3, 2).normalized()).toRotationMatrix();
  for (auto& e : turned.positions) e = R * Eigen::Vector3d(-e(0), e(1), e(2));
  std::swap(turned.positions[0], turned.positions[9]);
  std::swap(turned.positions[3], turned.positions[12]);
  const CertifyResult t = certify(turned, d);
  ASSERT_EQ(t.status, CertifiedStatus::attained_proven) << t.reason;
  EXPECT_LT(std::stod(t.radius), 1e-14);
}

TEST(D3Design, AMoveIsCoveredByTheRadiusAndTheOptimisersDesignsStayNumerical) {
  const CriterionKind d = *parse_criterion("D");
  CertifyOptions loose;
  loose.attained_tolerance = 1e-2;
  Program moved = d3_design();
  moved.positions[5] = (moved.positions[5] + Eigen::Vector3d(0, 2e-5, 0)).normalized();
  const CertifyResult r = certify(moved, d, loose);
  ASSERT_EQ(r.status, CertifiedStatus::attained_proven) << r.reason;
  EXPECT_GT(std::stod(r.radius), 1e-5);
  EXPECT_LT(std::stod(r.radius), 2e-4);
  moved.positions[5] = (moved.positions[5] + Eigen::Vector3d(0, 1e-2, 0)).normalized();
  EXPECT_NE(certify(moved, d, loose).status, CertifiedStatus::attained_proven);

  SynthesisOptions o;
  o.positions = 14;
  o.criterion = d;
  o.seed = 1;
  o.starts = 8;
  o.threads = 1;
  const CertifyResult optimised = certify(synthesize(o).program, d);
  EXPECT_EQ(optimised.status, CertifiedStatus::attained_numerical);
  EXPECT_NE(optimised.reason.find("lose rank"), std::string::npos) << optimised.reason;
}

}  // namespace
}  // namespace scalcal
