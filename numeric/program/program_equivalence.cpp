// When two programs are the same program up to a criterion's symmetry (program_equivalence.hpp).
#include "numeric/program/program_equivalence.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>

#include <Eigen/Geometry>
#include <Eigen/SVD>

namespace scalcal {
namespace {

using Positions = PositionsT<double>;
using Pairing = std::vector<int>;  // pairing[i] = index in b of the partner of a_i

// --- one-to-one matching -------------------------------------------------------------------------

// Kuhn's augmenting path: a greedy nearest match can pair a_i with the wrong one of two b positions
// lying within 2 tol of each other and then leave a later a_k without a partner.
bool augment(int i, const std::vector<std::vector<int>>& near, std::vector<int>& owner, std::vector<char>& visited) {
  for (int j : near[i]) {
    if (visited[j]) continue;
    visited[j] = 1;
    if (owner[j] < 0 || augment(owner[j], near, owner, visited)) {
      owner[j] = i;
      return true;
    }
  }
  return false;
}

std::optional<Pairing> match(const Positions& a, const Positions& b, const Mat3& g, double tol) {
  const int n = static_cast<int>(a.size());
  const double tol2 = tol * tol;
  std::vector<std::vector<int>> near(n);
  for (int i = 0; i < n; ++i) {
    const Vec3 image = g * a[i];
    for (int j = 0; j < n; ++j)
      if ((image - b[j]).squaredNorm() <= tol2) near[i].push_back(j);
    if (near[i].empty()) return std::nullopt;  // most wrong maps stop here, after a few positions
  }
  std::vector<int> owner(n, -1);
  std::vector<char> visited(n);
  for (int i = 0; i < n; ++i) {
    std::fill(visited.begin(), visited.end(), 0);
    if (!augment(i, near, owner, visited)) return std::nullopt;
  }
  Pairing pairing(n);
  for (int j = 0; j < n; ++j) pairing[owner[j]] = j;
  return pairing;
}

// --- cheap necessary conditions --------------------------------------------------------------------

double max_norm(const Positions& p) {
  double m = 0;
  for (const auto& v : p) m = std::max(m, v.norm());
  return m;
}

std::vector<double> norms(const Positions& p) {
  std::vector<double> out;
  for (const auto& v : p) out.push_back(v.norm());
  return out;
}

std::vector<double> gram_entries(const Positions& p) {
  std::vector<double> out;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t k = i + 1; k < p.size(); ++k) out.push_back(p[i].dot(p[k]));
  return out;
}

// The distance from each position to its nearest other position: a rotation keeps it, and moving each
// position by at most tol moves it by at most 2 tol. Only N numbers to sort, where the Gram entries
// are N^2 / 2 (at N = 1000 their sort was 40 ms a program, 85 % of a D multistart). Found by a sweep
// along x: a position closer than the best so far is closer in x too, so each scan stops early.
std::vector<double> nearest_distances(const Positions& p) {
  const std::size_t n = p.size();
  if (n < 2) return {};
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return p[a].x() < p[b].x(); });
  std::vector<double> out(n);
  for (std::size_t t = 0; t < n; ++t) {
    const Vec3& v = p[order[t]];
    double best = std::numeric_limits<double>::infinity();
    auto scan = [&](std::size_t s) {
      const double dx = p[order[s]].x() - v.x();
      if (dx * dx > best) return false;
      best = std::min(best, (p[order[s]] - v).squaredNorm());
      return true;
    };
    for (std::size_t s = t + 1; s < n && scan(s); ++s) {
    }
    for (std::size_t s = t; s-- > 0 && scan(s);) {
    }
    out[t] = std::sqrt(best);
  }
  return out;
}

// The k-th smallest |coordinate| of a position is unchanged by a signed permutation and moves by at
// most the Euclidean distance under a perturbation.
std::vector<double> sorted_abs_coordinate(const Positions& p, int k) {
  std::vector<double> out;
  for (const auto& v : p) {
    std::array<double, 3> c = {std::abs(v.x()), std::abs(v.y()), std::abs(v.z())};
    std::sort(c.begin(), c.end());
    out.push_back(c[k]);
  }
  return out;
}

// |g a.g a' - b.b'| <= tol (|a| + |b'|) when |g a - b| <= tol and |g a' - b'| <= tol; the margin
// covers rounding.
double dot_slack(double tol, double scale) { return tol * (2 * scale + tol) + 1e-14 * scale * scale; }

// Two multisets related by a pairing that moves each element by at most slack agree element by
// element within it once sorted.
bool sorted_within(const std::vector<double>& a, const std::vector<double>& b, double slack) {
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k)
    if (std::abs(a[k] - b[k]) > slack) return false;
  return true;
}

// Multisets of numbers that the group leaves unchanged (Orthogonal: lengths, nearest-neighbour
// distances, then pairwise dot products; SignedPermutations: the sorted |coordinates|), each sorted
// once per program. A multistart with 64 distinct optima at N = 18 makes about 2000 comparisons,
// almost all rejected here. The dot products are sorted only when the cheap lists agree: distinct
// optima at large N differ in their nearest distances already.
class SortedInvariants {
 public:
  SortedInvariants(const Positions& p, ProgramSymmetry symmetry)
      : positions_(&p), symmetry_(symmetry), scale_(max_norm(p)) {
    if (symmetry == ProgramSymmetry::Orthogonal)
      lists_ = {norms(p), nearest_distances(p)};
    else
      for (int k = 0; k < 3; ++k) lists_.push_back(sorted_abs_coordinate(p, k));
    for (auto& l : lists_) std::sort(l.begin(), l.end());
  }

  // A necessary condition for a map within tol.
  bool may_equal(const SortedInvariants& other, double tol) const {
    const double scale = std::max(scale_, other.scale_);
    const double rounding = 1e-14 * scale;
    for (std::size_t l = 0; l < lists_.size(); ++l) {
      const double slack = symmetry_ == ProgramSymmetry::SignedPermutations ? tol
                           : l == 0                                         ? tol + rounding
                                                                            : 2 * tol + rounding;
      if (!sorted_within(lists_[l], other.lists_[l], slack)) return false;
    }
    return symmetry_ != ProgramSymmetry::Orthogonal || sorted_within(dots(), other.dots(), dot_slack(tol, scale));
  }

 private:
  const std::vector<double>& dots() const {
    if (!dots_) {
      dots_ = gram_entries(*positions_);
      std::sort(dots_->begin(), dots_->end());
    }
    return *dots_;
  }

  const Positions* positions_;  // outlives this: both live for one comparison or one classification
  ProgramSymmetry symmetry_;
  double scale_;
  std::vector<std::vector<double>> lists_;
  mutable std::optional<std::vector<double>> dots_;
};

// --- signed permutations -------------------------------------------------------------------------

const std::array<Mat3, 48>& signed_permutations() {
  static const std::array<Mat3, 48> group = [] {
    std::array<Mat3, 48> out;
    std::array<int, 3> perm = {0, 1, 2};
    int k = 0;
    do {
      for (int signs = 0; signs < 8; ++signs) {
        Mat3 g = Mat3::Zero();
        for (int i = 0; i < 3; ++i) g(i, perm[i]) = (signs >> i & 1) ? -1.0 : 1.0;
        out[k++] = g;
      }
    } while (std::next_permutation(perm.begin(), perm.end()));
    return out;
  }();
  return group;
}

// Both maps below assume the sorted invariants agree (see mapped_after_invariants).
std::optional<Mat3> signed_permutation_map(const Positions& a, const Positions& b, double tol) {
  for (const Mat3& g : signed_permutations())
    if (match(a, b, g, tol)) return g;
  return std::nullopt;
}

// --- orthogonal maps -----------------------------------------------------------------------------

double sine_between(const Vec3& x, const Vec3& y) {
  const double nx = x.norm(), ny = y.norm();
  if (nx == 0 || ny == 0) return 0;
  return x.cross(y).norm() / (nx * ny);
}

struct AnchorPair {
  int p = 0, q = 0;
  double sine = 0;  // of the angle between a_p and a_q: the conditioning of the frame they span
};

AnchorPair most_orthogonal_pair(const Positions& a) {
  AnchorPair best;
  for (int p = 0; p < static_cast<int>(a.size()); ++p)
    for (int q = p + 1; q < static_cast<int>(a.size()); ++q) {
      const double s = sine_between(a[p], a[q]);
      if (s > best.sine) best = {p, q, s};
    }
  return best;
}

int longest(const Positions& a) {
  int best = 0;
  for (int i = 1; i < static_cast<int>(a.size()); ++i)
    if (a[i].squaredNorm() > a[best].squaredNorm()) best = i;
  return best;
}

// Orthonormal columns: x's direction, y's part orthogonal to it, their cross product.
Mat3 frame(const Vec3& x, const Vec3& y) {
  Mat3 f;
  f.col(0) = x.normalized();
  f.col(1) = (y - y.dot(f.col(0)) * f.col(0)).normalized();
  f.col(2) = f.col(0).cross(f.col(1));
  return f;
}

// A frame whose first column is along x; the other two are arbitrary (the twist is free).
Mat3 frame_about(const Vec3& x) {
  const Vec3 axis = x.norm() > 0 ? Vec3(x.normalized()) : Vec3::UnitX();
  Mat3 f;
  f.col(0) = axis;
  f.col(1) = axis.unitOrthogonal();
  f.col(2) = axis.cross(f.col(1));
  return f;
}

// The g in O(3) maximising sum b_pi(i) . g a_i (orthogonal Procrustes; no det constraint, the
// reflections belong to the group).
Mat3 procrustes(const Positions& a, const Positions& b, const Pairing& pairing) {
  Mat3 h = Mat3::Zero();
  for (std::size_t i = 0; i < a.size(); ++i) h += b[pairing[i]] * a[i].transpose();
  Eigen::JacobiSVD<Mat3> svd(h, Eigen::ComputeFullU | Eigen::ComputeFullV);
  return svd.matrixU() * svd.matrixV().transpose();
}

// A candidate g built from two positions carries their errors into the other positions, amplified
// by the conditioning of the anchor; if g matches within that looser radius, the least-squares
// refit on the pairing found is tried against the strict tol.
std::optional<Mat3> verified(const Mat3& g, const Positions& a, const Positions& b, double tol, double loose_tol) {
  if (match(a, b, g, tol)) return g;
  const auto pairing = match(a, b, g, loose_tol);
  if (!pairing) return std::nullopt;
  const Mat3 refit = procrustes(a, b, *pairing);
  if (match(a, b, refit, tol)) return refit;
  return std::nullopt;
}

std::optional<Mat3> collinear_map(const Positions& a, const Positions& b, double tol) {
  const Mat3 fa = frame_about(a[longest(a)]), fb = frame_about(b[longest(b)]);
  for (double along : {1.0, -1.0})
    for (double handedness : {1.0, -1.0}) {
      const Mat3 g = fb * Vec3(along, 1.0, handedness).asDiagonal() * fa.transpose();
      if (auto found = verified(g, a, b, tol, 8 * tol)) return found;
    }
  return std::nullopt;
}

// Every correspondence of the anchor pair (a_p, a_q) with an ordered pair (b_r, b_s) of the same
// lengths and dot product fixes g up to the reflection through their plane.
std::optional<Mat3> anchored_map(const Positions& a, const Positions& b, const AnchorPair& anchor, double tol) {
  const Vec3& ap = a[anchor.p];
  const Vec3& aq = a[anchor.q];
  const double scale = std::max(max_norm(a), max_norm(b));
  const double norm_slack = tol + 1e-14 * scale;
  const double slack = dot_slack(tol, scale);
  const double loose_tol = tol * (4 + 4 / anchor.sine);
  const Mat3 fa_t = frame(ap, aq).transpose();
  const int n = static_cast<int>(b.size());
  for (int r = 0; r < n; ++r) {
    if (std::abs(b[r].norm() - ap.norm()) > norm_slack) continue;
    for (int s = 0; s < n; ++s) {
      if (s == r || std::abs(b[s].norm() - aq.norm()) > norm_slack) continue;
      if (std::abs(b[r].dot(b[s]) - ap.dot(aq)) > slack) continue;
      const Mat3 fb = frame(b[r], b[s]);
      for (double handedness : {1.0, -1.0}) {
        const Mat3 g = fb * Vec3(1.0, 1.0, handedness).asDiagonal() * fa_t;
        if (auto found = verified(g, a, b, tol, loose_tol)) return found;
      }
    }
  }
  return std::nullopt;
}

std::optional<Mat3> orthogonal_map(const Positions& a, const Positions& b, double tol) {
  const AnchorPair anchor = most_orthogonal_pair(a);
  // Below this the second anchor's sideways part is noise of the size tol: it cannot orient a frame.
  const double collinear_sine = 10 * tol / std::max(max_norm(a), 1e-300);
  if (anchor.sine <= collinear_sine) return collinear_map(a, b, tol);
  return anchored_map(a, b, anchor, tol);
}

}  // namespace

namespace {

std::optional<Mat3> mapped_after_invariants(const Program& a, const Program& b, ProgramSymmetry symmetry,
                                            const SortedInvariants& ia, const SortedInvariants& ib, double tol) {
  if (a.size() != b.size()) return std::nullopt;
  if (a.size() == 0) return Mat3::Identity();
  if (!ia.may_equal(ib, tol)) return std::nullopt;
  return symmetry == ProgramSymmetry::Orthogonal ? orthogonal_map(a.positions, b.positions, tol)
                                                 : signed_permutation_map(a.positions, b.positions, tol);
}

}  // namespace

std::optional<Mat3> equivalence_map(const Program& a, const Program& b, ProgramSymmetry symmetry, double tol) {
  return mapped_after_invariants(a, b, symmetry, SortedInvariants(a.positions, symmetry),
                                 SortedInvariants(b.positions, symmetry), tol);
}

bool equivalent(const Program& a, const Program& b, ProgramSymmetry symmetry, double tol) {
  return equivalence_map(a, b, symmetry, tol).has_value();
}

std::vector<int> equivalence_classes(const std::vector<Program>& programs, ProgramSymmetry symmetry, double tol) {
  std::vector<int> labels;
  std::vector<std::size_t> representatives;  // index of the first member of each class
  std::vector<SortedInvariants> invariants;
  for (const auto& p : programs) invariants.emplace_back(p.positions, symmetry);
  for (std::size_t i = 0; i < programs.size(); ++i) {
    int label = -1;
    for (std::size_t c = 0; c < representatives.size() && label < 0; ++c) {
      const std::size_t r = representatives[c];
      if (mapped_after_invariants(programs[r], programs[i], symmetry, invariants[r], invariants[i], tol))
        label = static_cast<int>(c);
    }
    if (label < 0) {
      label = static_cast<int>(representatives.size());
      representatives.push_back(i);
    }
    labels.push_back(label);
  }
  return labels;
}

int count_distinct(const std::vector<Program>& programs, ProgramSymmetry symmetry, double tol) {
  const auto labels = equivalence_classes(programs, symmetry, tol);
  return labels.empty() ? 0 : *std::max_element(labels.begin(), labels.end()) + 1;
}

}  // namespace scalcal
