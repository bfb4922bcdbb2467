// Hand rotations: the start, the weighted Levenberg-Marquardt fit, the variance components and the
// misfit (hand_rotations.hpp).
#include "numeric/gyro/hand_rotations.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <Eigen/Dense>

#include "numeric/gyro/grouped_least_squares.hpp"
#include "numeric/io/input_error.hpp"

namespace scalcal::gyro {
namespace {

using Params = Eigen::Matrix<double, 12, 1>;

Params pack(const Mat3& C, const Vec3& o) {
  Params p;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) p(3 * a + b) = C(a, b);
  p.tail<3>() = o;
  return p;
}
Mat3 matrix_of(const Params& p) {
  Mat3 C;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) C(a, b) = p(3 * a + b);
  return C;
}

// Two unit vectors spanning the plane perpendicular to g: the residual's two components (the third,
// along g, is second order for unit vectors and carries no information).
Eigen::Matrix<double, 2, 3> tangent_basis(const Vec3& g) {
  int k = 0;
  g.cwiseAbs().minCoeff(&k);
  const Vec3 e1 = g.cross(Vec3::Unit(k)).normalized();
  Eigen::Matrix<double, 2, 3> E;
  E.row(0) = e1.transpose();
  E.row(1) = g.cross(e1).transpose();
  return E;
}

struct Rest {
  Vec3 mean = Vec3::Zero();
  Vec3 sd = Vec3::Ones();  // one sample's standard deviation per axis
  int samples = 0;
};

// The data every evaluation shares, and the predicted noise of each residual.
struct Problem {
  const RawLog& log;
  const std::vector<GyroPose>& poses;
  std::vector<Rest> rests;
  std::vector<double> pair_sigma;  // predicted std of one residual component of each pair (rad)
  bool use_rests = true;

  int pairs() const { return static_cast<int>(poses.size()) - 1; }
  int rows() const { return 2 * pairs() + (use_rests ? 3 * static_cast<int>(rests.size()) : 0); }
};

Rest rest_of(const RawLog& log, const GyroPose& p) {
  Rest r;
  Vec3 s = Vec3::Zero(), s2 = Vec3::Zero();
  for (int i = p.begin; i <= p.end; ++i) {
    if (!log.finite(i)) continue;
    const Vec3& w = log.samples[static_cast<std::size_t>(i)];
    s += w;
    s2 += w.cwiseProduct(w);
    ++r.samples;
  }
  r.mean = s / r.samples;
  const Vec3 var = (s2 / r.samples - r.mean.cwiseProduct(r.mean)) * r.samples / std::max(1, r.samples - 1);
  r.sd = var.cwiseMax(0.0).cwiseSqrt();
  return r;
}

// Residuals (pairs' two components, then rests' three) divided by their predicted noise, and their
// Jacobian in the packed parameters.
void evaluate(const Problem& P, const Params& p, Eigen::VectorXd& r, Eigen::MatrixXd* J) {
  const Mat3 C = matrix_of(p);
  const Vec3 o = p.tail<3>();
  r.resize(P.rows());
  if (J) J->setZero(P.rows(), 12);
  for (int k = 0; k < P.pairs(); ++k) {
    const GyroPose &a = P.poses[static_cast<std::size_t>(k)], &b = P.poses[static_cast<std::size_t>(k) + 1];
    const RotationIntegral I = integrate_rotation(P.log.samples, P.log.t, a.end, b.begin, C, o, J != nullptr);
    const Vec3 pred = I.R.transpose() * a.gravity;
    const Eigen::Matrix<double, 2, 3> E = tangent_basis(b.gravity);
    const double w = 1 / P.pair_sigma[static_cast<std::size_t>(k)];
    r.segment<2>(2 * k) = w * E * (pred - b.gravity);
    if (J) J->block<2, 12>(2 * k, 0) = w * E * skew(pred) * I.D;  // d pred / d theta = [pred]x
  }
  if (!P.use_rests) return;
  for (std::size_t j = 0; j < P.rests.size(); ++j) {
    const Rest& s = P.rests[j];
    const int row = 2 * P.pairs() + 3 * static_cast<int>(j);
    for (int c = 0; c < 3; ++c) {
      const double w = std::sqrt(static_cast<double>(s.samples)) / std::max(s.sd(c), 1e-300);
      r(row + c) = w * (s.mean(c) - o(c));
      if (J) (*J)(row + c, 9 + c) = -w;
    }
  }
}

double cost(const Problem& P, const Params& p) {
  Eigen::VectorXd r;
  evaluate(P, p, r, nullptr);
  return r.squaredNorm();
}

// The 48 signed permutations of the axes: the gyro's axes may be labelled differently from the
// accelerometer's.
std::vector<Mat3> signed_permutations() {
  std::vector<Mat3> out;
  std::array<int, 3> perm = {0, 1, 2};
  do {
    for (int s = 0; s < 8; ++s) {
      Mat3 M = Mat3::Zero();
      for (int a = 0; a < 3; ++a) M(a, perm[static_cast<std::size_t>(a)]) = (s >> a & 1) ? -1 : 1;
      out.push_back(M);
    }
  } while (std::next_permutation(perm.begin(), perm.end()));
  return out;
}

// A start without a user's guess: o the poses' mean output; the gain from the tilt each motion makes
// against the integrated raw output (a lower bound per pair, the median a fair guess), the axes'
// labelling by the least misfit, then the gain on a grid around its guess.
Params find_start(const Problem& P) {
  Vec3 o = Vec3::Zero();
  for (const Rest& s : P.rests) o += s.mean;
  o /= static_cast<double>(P.rests.size());
  std::vector<double> ratio;
  for (int k = 0; k < P.pairs(); ++k) {
    const GyroPose &a = P.poses[static_cast<std::size_t>(k)], &b = P.poses[static_cast<std::size_t>(k) + 1];
    const double tilt = std::atan2(a.gravity.cross(b.gravity).norm(), a.gravity.dot(b.gravity));
    Vec3 integral = Vec3::Zero();
    for (int i = a.end; i < b.begin; ++i)
      integral += (P.log.samples[static_cast<std::size_t>(i)] - o) *
                  (P.log.t[static_cast<std::size_t>(i) + 1] - P.log.t[static_cast<std::size_t>(i)]);
    if (integral.norm() > 0 && tilt > 0.05) ratio.push_back(tilt / integral.norm());
  }
  double gain = 1;
  if (!ratio.empty()) {
    std::nth_element(ratio.begin(), ratio.begin() + static_cast<std::ptrdiff_t>(ratio.size() / 2), ratio.end());
    gain = ratio[ratio.size() / 2];
  }
  // Each motion as one rotation about its integrated raw output, exp[C u_k] (exact for a motion about
  // one axis, fair for a hand's): cheap enough to score every labelling of the axes at every gain on
  // a grid; the few best are then scored with the true integration.
  std::vector<Vec3> u;
  for (int k = 0; k < P.pairs(); ++k) {
    const GyroPose &a = P.poses[static_cast<std::size_t>(k)], &b = P.poses[static_cast<std::size_t>(k) + 1];
    Vec3 sum = Vec3::Zero();
    for (int i = a.end; i < b.begin; ++i)
      sum += 0.5 *
             (P.log.samples[static_cast<std::size_t>(i)] + P.log.samples[static_cast<std::size_t>(i) + 1] - 2 * o) *
             (P.log.t[static_cast<std::size_t>(i) + 1] - P.log.t[static_cast<std::size_t>(i)]);
    u.push_back(sum);
  }
  auto cheap = [&](const Mat3& C) {
    double c = 0;
    for (int k = 0; k < P.pairs(); ++k)
      c +=
          (rotation_exp(C * u[static_cast<std::size_t>(k)]).transpose() * P.poses[static_cast<std::size_t>(k)].gravity -
           P.poses[static_cast<std::size_t>(k) + 1].gravity)
              .squaredNorm();
    return c;
  };
  struct Candidate {
    double score;
    Mat3 C;
  };
  std::vector<Candidate> candidates;
  for (const Mat3& M : signed_permutations())
    for (int s = -12; s <= 36; ++s) {  // an octave below the guess to three above, 1/12 octave apart
      const Mat3 C = gain * std::pow(2.0, s / 12.0) * M;
      candidates.push_back({cheap(C), C});
    }
  std::partial_sort(candidates.begin(), candidates.begin() + 4, candidates.end(),
                    [](const Candidate& x, const Candidate& y) { return x.score < y.score; });
  Problem Q = P;
  Q.use_rests = false;
  Mat3 best_C = candidates[0].C;
  double best = INFINITY;
  for (int k = 0; k < 4; ++k) {
    const double c = cost(Q, pack(candidates[static_cast<std::size_t>(k)].C, o));
    if (c < best) best = c, best_C = candidates[static_cast<std::size_t>(k)].C;
  }
  return pack(best_C, o);
}

}  // namespace

GravityMisfit gravity_misfit(const RawLog& gyro, const std::vector<GyroPose>& poses, const Mat3& C, const Vec3& o) {
  GravityMisfit m;
  double sa = 0, sc = 0;
  for (std::size_t k = 0; k + 1 < poses.size(); ++k) {
    const GyroPose &a = poses[k], &b = poses[k + 1];
    const Mat3 R = integrate_rotation(gyro.samples, gyro.t, a.end, b.begin, C, o, false).R;
    const Vec3 pred = R.transpose() * a.gravity;
    PairMisfit pm;
    pm.from = static_cast<int>(k);
    pm.angle = std::atan2(pred.cross(b.gravity).norm(), pred.dot(b.gravity));
    pm.chord = (pred - b.gravity).norm();
    pm.seconds = gyro.t[static_cast<std::size_t>(b.begin)] - gyro.t[static_cast<std::size_t>(a.end)];
    sa += pm.angle * pm.angle;
    sc += pm.chord * pm.chord;
    m.pairs.push_back(pm);
  }
  if (!m.pairs.empty()) {
    m.angle_rms = std::sqrt(sa / static_cast<double>(m.pairs.size()));
    m.chord_rms = std::sqrt(sc / static_cast<double>(m.pairs.size()));
  }
  return m;
}

HandRotationCalibration calibrate_hand_rotations(const RawLog& gyro, const std::vector<GyroPose>& poses,
                                                 const HandRotationOptions& options) {
  if (poses.size() < 4)
    throw InputError(gyro.file, 0,
                     "found " + std::to_string(poses.size()) +
                         " still poses; hand rotations need at least 4 (12 unknowns: the gyro's matrix and offset)");
  for (const GyroPose& p : poses)
    if (p.begin < 0 || p.end >= gyro.size() || p.end < p.begin)
      throw InputError(gyro.file, 0, "a still pose lies outside the gyro's log (the two logs must have the same rows)");
  Problem P{gyro, poses, {}, {}, options.bias_from_rests};
  for (const GyroPose& p : poses) P.rests.push_back(rest_of(gyro, p));

  P.pair_sigma.assign(static_cast<std::size_t>(P.pairs()), 1.0);  // unweighted while searching for a start
  Params p = find_start(P);
  if (options.start_matrix || options.start_offset)
    p = pack(options.start_matrix.value_or(matrix_of(p)), options.start_offset.value_or(Vec3(p.tail<3>())));
  // Predicted noise of a pair: the gyro's white noise integrated over the motion (an angle random
  // walk, at the start's gain) and both gravity directions' scatter.
  std::vector<double> sd;
  for (const Rest& s : P.rests) sd.push_back(s.sd.mean());
  std::nth_element(sd.begin(), sd.begin() + static_cast<std::ptrdiff_t>(sd.size() / 2), sd.end());
  const double rate_sd = matrix_of(p).norm() / std::sqrt(3.0) * sd[sd.size() / 2];
  P.pair_sigma.clear();
  for (int k = 0; k < P.pairs(); ++k) {
    const GyroPose &a = poses[static_cast<std::size_t>(k)], &b = poses[static_cast<std::size_t>(k) + 1];
    double walk = 0;
    for (int i = a.end; i < b.begin; ++i) {
      const double dt = gyro.t[static_cast<std::size_t>(i) + 1] - gyro.t[static_cast<std::size_t>(i)];
      walk += dt * dt;
    }
    const double v = rate_sd * rate_sd * walk + a.gravity_std * a.gravity_std + b.gravity_std * b.gravity_std;
    P.pair_sigma.push_back(std::sqrt(std::max(v, 1e-24)));
  }

  GroupedProblem G;
  G.parameters = 12;
  G.groups = 2;
  G.row_group.assign(static_cast<std::size_t>(P.rows()), 1);
  std::fill(G.row_group.begin(), G.row_group.begin() + 2 * P.pairs(), 0);
  G.evaluate = [&P](const Eigen::VectorXd& q, Eigen::VectorXd& r, Eigen::MatrixXd* J) { evaluate(P, q, r, J); };
  const GroupedFit fit = fit_grouped(G, p, options.max_iterations);
  HandRotationCalibration out;
  p = fit.p;
  out.covariance = fit.covariance;
  out.standard_error = fit.standard_error;
  out.predicted_std = fit.predicted_std;
  out.rotation_scale = fit.scale[0];
  out.rotation_chi_square = fit.chi_square[0];
  out.rotation_dof = fit.dof[0];
  if (P.use_rests) {
    out.rest_scale = fit.scale[1];
    out.rest_chi_square = fit.chi_square[1];
    out.rest_dof = fit.dof[1];
  }
  out.iterations = fit.iterations;
  out.summary = fit.summary;
  out.matrix = matrix_of(p);
  out.offset = p.tail<3>();
  out.misfit = gravity_misfit(gyro, poses, out.matrix, out.offset);
  return out;
}

}  // namespace scalcal::gyro
