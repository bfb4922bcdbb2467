// Program equivalence: the expected answers come from how the programs are built (an image under a
// known map, a known perturbation), never from the algorithm. Random programs are generic: no
// non-trivial symmetry maps one onto another of a different seed, and no signed permutation maps a
// random rotation of one onto itself.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <random>

#include <Eigen/Geometry>

#include "numeric/criteria/registry.hpp"
#include "numeric/program/program_equivalence.hpp"

namespace scalcal {
namespace {

constexpr auto kOrthogonal = ProgramSymmetry::Orthogonal;
constexpr auto kSignedPermutations = ProgramSymmetry::SignedPermutations;

Program transformed(const Program& p, const Mat3& g) {
  Program q;
  for (const auto& e : p.positions) q.positions.push_back(g * e);
  return q;
}

Program shuffled(Program p, std::uint64_t seed) {
  std::mt19937_64 engine(seed);
  std::shuffle(p.positions.begin(), p.positions.end(), engine);
  return p;
}

// Each coordinate moved by up to amplitude; positions are not renormalised.
Program noisy(Program p, double amplitude, std::uint64_t seed) {
  SphereSampler s(seed);
  for (auto& e : p.positions) {
    const double dx = 2 * s.uniform() - 1, dy = 2 * s.uniform() - 1, dz = 2 * s.uniform() - 1;
    e += amplitude * Vec3(dx, dy, dz);
  }
  return p;
}

Mat3 random_rotation(std::uint64_t seed) {
  SphereSampler s(seed);
  const Vec3 axis = s();
  return Eigen::AngleAxisd(2 * M_PI * s.uniform(), axis).toRotationMatrix();
}

// Reflection through the plane orthogonal to a random unit normal.
Mat3 random_reflection(std::uint64_t seed) {
  SphereSampler s(seed);
  const Vec3 n = s();
  return Mat3::Identity() - 2 * n * n.transpose();
}

std::vector<Mat3> signed_permutation_matrices() {
  std::vector<Mat3> out;
  std::array<int, 3> perm = {0, 1, 2};
  do {
    for (int signs = 0; signs < 8; ++signs) {
      Mat3 g = Mat3::Zero();
      for (int i = 0; i < 3; ++i) g(i, perm[i]) = (signs >> i & 1) ? -1.0 : 1.0;
      out.push_back(g);
    }
  } while (std::next_permutation(perm.begin(), perm.end()));
  return out;
}

// The claim carried by a returned map, checked by brute force: g orthogonal, and every g a_i within
// tol of some b_j (the one-to-one part is checked by the multiplicity tests below).
void expect_map_is_valid(const Program& a, const Program& b, ProgramSymmetry symmetry, double tol) {
  const auto g = equivalence_map(a, b, symmetry, tol);
  ASSERT_TRUE(g.has_value());
  EXPECT_LT((g->transpose() * *g - Mat3::Identity()).norm(), 1e-9);
  for (const auto& e : a.positions) {
    double nearest = 1e300;
    for (const auto& f : b.positions) nearest = std::min(nearest, (*g * e - f).norm());
    EXPECT_LE(nearest, tol);
  }
}

TEST(ProgramEquivalence, SymmetryOfEachCriterion) {
  EXPECT_EQ(symmetry_of(CriterionKind::D), kOrthogonal);
  EXPECT_EQ(symmetry_of(CriterionKind::A), kSignedPermutations);
  EXPECT_EQ(symmetry_of(CriterionKind::E), kSignedPermutations);
  EXPECT_EQ(symmetry_of(CriterionKind::S), kSignedPermutations);
}

TEST(ProgramEquivalence, RotatedShuffledNoisyProgramIsOrthogonalButNotSignedPermutationEquivalent) {
  for (int n : {9, 18, 30, 60})
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
      const Program p = Program::random(n, seed);
      const Program q = noisy(shuffled(transformed(p, random_rotation(100 + seed)), seed), 1e-9, 200 + seed);
      EXPECT_TRUE(equivalent(p, q, kOrthogonal)) << "N " << n << " seed " << seed;
      EXPECT_TRUE(equivalent(q, p, kOrthogonal)) << "N " << n << " seed " << seed;
      EXPECT_FALSE(equivalent(p, q, kSignedPermutations)) << "N " << n << " seed " << seed;
      expect_map_is_valid(p, q, kOrthogonal, 1e-6);
    }
}

TEST(ProgramEquivalence, NoiseNearTheToleranceIsStillEquivalent) {
  // Each coordinate moved by up to 5e-7 moves a position by at most 8.7e-7 < tol = 1e-6, so the
  // rotation itself is a valid map; a map estimated from two noisy positions alone often is not.
  // N = 500 also moves nearest-neighbour distances by nearly their slack of 2 tol.
  for (int n : {18, 30, 500})
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
      const Program p = Program::random(n, seed);
      const Program q = noisy(shuffled(transformed(p, random_rotation(300 + seed)), seed), 5e-7, 400 + seed);
      EXPECT_TRUE(equivalent(p, q, kOrthogonal, 1e-6)) << "N " << n << " seed " << seed;
    }
}

TEST(ProgramEquivalence, ReflectionsAreOrthogonalEquivalent) {
  const Program p = Program::random(20, 3);
  const Program mirror_x = transformed(p, Vec3(-1, 1, 1).asDiagonal().toDenseMatrix());
  EXPECT_TRUE(equivalent(p, shuffled(mirror_x, 1), kOrthogonal));
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const Mat3 g = random_rotation(seed) * random_reflection(50 + seed);  // det -1
    const Program q = shuffled(transformed(p, g), seed);
    EXPECT_TRUE(equivalent(p, q, kOrthogonal)) << "seed " << seed;
    EXPECT_FALSE(equivalent(p, q, kSignedPermutations)) << "seed " << seed;
    expect_map_is_valid(p, q, kOrthogonal, 1e-6);
  }
}

TEST(ProgramEquivalence, EverySignedPermutationImageIsEquivalentUnderBothSymmetries) {
  const Program p = Program::random(15, 11);
  std::uint64_t seed = 0;
  for (const Mat3& g : signed_permutation_matrices()) {
    ++seed;
    const Program q = noisy(shuffled(transformed(p, g), seed), 1e-9, seed);
    EXPECT_TRUE(equivalent(p, q, kSignedPermutations)) << g;
    EXPECT_TRUE(equivalent(p, q, kOrthogonal)) << g;
    expect_map_is_valid(p, q, kSignedPermutations, 1e-6);
  }
}

TEST(ProgramEquivalence, DifferentRandomProgramsAreNotEquivalent) {
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    const Program p = Program::random(18, seed), q = Program::random(18, seed + 100);
    EXPECT_FALSE(equivalent(p, q, kOrthogonal));
    EXPECT_FALSE(equivalent(p, q, kSignedPermutations));
  }
}

TEST(ProgramEquivalence, MovingOnePositionBy1e3BreaksEquivalenceAtTol1e6) {
  const Program p = Program::random(18, 5);
  const Mat3 rotation = random_rotation(9);
  for (int k : {0, 7, 17}) {
    Program q = transformed(p, rotation);
    const Vec3 sideways = q.positions[k].unitOrthogonal();
    q.positions[k] = (q.positions[k] + 1e-3 * sideways).normalized();
    q = shuffled(q, k);
    EXPECT_FALSE(equivalent(p, q, kOrthogonal, 1e-6)) << "k " << k;
    // The rotation itself maps p within 1e-3 of q, so a coarse tol accepts it.
    EXPECT_TRUE(equivalent(p, q, kOrthogonal, 1e-2)) << "k " << k;
  }
  Program r = p;
  r.positions[3] = (r.positions[3] + 1e-3 * r.positions[3].unitOrthogonal()).normalized();
  EXPECT_FALSE(equivalent(p, r, kSignedPermutations, 1e-6));
  EXPECT_TRUE(equivalent(p, r, kSignedPermutations, 1e-2));
}

TEST(ProgramEquivalence, Classic18IsMappedOntoItselfByAQuarterTurn) {
  const Program p = Program::classic18();
  const Program quarter = transformed(p, Eigen::AngleAxisd(M_PI / 2, Vec3::UnitZ()).toRotationMatrix());
  EXPECT_TRUE(equivalent(p, quarter, kSignedPermutations));
  EXPECT_TRUE(equivalent(p, quarter, kOrthogonal));
  // An eighth turn takes the axis positions to edge positions and (e, 0, e) to (1/2, 1/2, e): a
  // different program for A, E, S, the same for D.
  const Program eighth = transformed(p, Eigen::AngleAxisd(M_PI / 4, Vec3::UnitZ()).toRotationMatrix());
  EXPECT_FALSE(equivalent(p, eighth, kSignedPermutations));
  EXPECT_TRUE(equivalent(p, eighth, kOrthogonal));
}

TEST(ProgramEquivalence, SymmetricProgramsRotatedAtRandomStayOrthogonalEquivalent) {
  // Many ordered anchor pairs share the anchor's dot product here, so most candidates are wrong.
  const std::vector<Program> programs = {
      Program::classic18(),    Program::octahedral(1, 1, 1), Program::octahedral(2, 0, 1), Program::rotation(6),
      Program::dodecahedral(), Program::icosahedral(),       Program::nine_two_axes(),     Program::nine_three_axes()};
  for (std::size_t i = 0; i < programs.size(); ++i) {
    const Program q = shuffled(transformed(programs[i], random_rotation(i + 1)), i);
    EXPECT_TRUE(equivalent(programs[i], q, kOrthogonal)) << "program " << i;
    expect_map_is_valid(programs[i], q, kOrthogonal, 1e-6);
  }
  // Same N, different programs.
  EXPECT_FALSE(equivalent(Program::classic18(), Program::rotation(6), kOrthogonal));
  EXPECT_FALSE(equivalent(Program::nine_two_axes(), Program::nine_three_axes(), kOrthogonal));
  EXPECT_FALSE(equivalent(Program::octahedral(2, 0, 0), Program::octahedral(0, 1, 0), kOrthogonal));
}

TEST(ProgramEquivalence, CountDistinctFindsThreeClasses) {
  const std::vector<Program> bases = {Program::random(12, 1), Program::random(12, 2), Program::classic18()};
  std::vector<Program> rotated, permuted;
  const auto perms = signed_permutation_matrices();
  for (int member = 0; member < 4; ++member)
    for (std::size_t c = 0; c < bases.size(); ++c) {
      const std::uint64_t seed = 10 * member + c + 1;
      rotated.push_back(noisy(shuffled(transformed(bases[c], random_rotation(seed)), seed), 1e-9, seed));
      permuted.push_back(shuffled(transformed(bases[c], perms[(7 * seed) % 48]), seed));
    }
  EXPECT_EQ(count_distinct(rotated, kOrthogonal), 3);
  EXPECT_EQ(count_distinct(permuted, kSignedPermutations), 3);
  EXPECT_EQ(count_distinct(permuted, kOrthogonal), 3);
  // Under signed permutations the random rotations of a random base are all different programs
  // (classic18 turned at random is too), so every one of the 12 is its own class.
  EXPECT_EQ(count_distinct(rotated, kSignedPermutations), 12);
  const std::vector<int> labels = equivalence_classes(rotated, kOrthogonal);
  for (std::size_t i = 0; i < labels.size(); ++i) EXPECT_EQ(labels[i], static_cast<int>(i % 3));
  EXPECT_EQ(count_distinct({}, kOrthogonal), 0);
}

TEST(ProgramEquivalence, DifferentSizesAreNeverEquivalent) {
  const Program p = Program::random(11, 1);
  Program prefix = p;
  prefix.positions.pop_back();
  EXPECT_FALSE(equivalent(p, prefix, kOrthogonal));
  EXPECT_FALSE(equivalent(prefix, p, kSignedPermutations));
  Program doubled = Program::classic18();
  doubled.append(Program::classic18());
  EXPECT_FALSE(equivalent(Program::classic18(), doubled, kOrthogonal));
  EXPECT_TRUE(equivalent(Program{}, Program{}, kOrthogonal));
}

TEST(ProgramEquivalence, RepeatedPositionsMatchOneToOne) {
  const Program p = Program::random(10, 4);
  Program repeated = p;
  repeated.positions[1] = repeated.positions[0];  // same N, position 0 twice, position 1 gone
  EXPECT_FALSE(equivalent(p, repeated, kOrthogonal));
  EXPECT_FALSE(equivalent(p, repeated, kSignedPermutations));
  EXPECT_TRUE(equivalent(repeated, shuffled(transformed(repeated, random_rotation(3)), 3), kOrthogonal));

  // Same support, different multiplicities: {x, x, y} against {x, y, y}. No signed permutation
  // relates them, but the mirror with normal x - y swaps x and y, so they are the same for D.
  const Vec3 x = Program::random(1, 7).positions[0], y = Program::random(1, 8).positions[0],
             z = Program::random(1, 9).positions[0];
  const Program xxy{{x, x, y}}, xyy{{x, y, y}};
  EXPECT_FALSE(equivalent(xxy, xyy, kSignedPermutations));
  EXPECT_TRUE(equivalent(xxy, xyy, kOrthogonal));
  EXPECT_TRUE(equivalent(xxy, Program{{y, x, x}}, kSignedPermutations));
  // With a third generic position no orthogonal map works: it would have to send the doubled x to
  // the doubled z and {y, z} to {x, y}, i.e. match three generic angles that all differ.
  EXPECT_FALSE(equivalent(Program{{x, x, y, z}}, Program{{x, y, z, z}}, kOrthogonal));
  EXPECT_FALSE(equivalent(Program{{x, x, y, z}}, Program{{x, y, z, z}}, kSignedPermutations));

  // A trap for nearest-first pairing (angles about z in units of tol): a = {0, -0.9}, b = {-0.2, 0.8}.
  // The nearest partner of a_0 is b_0, which leaves a_1 with none; the pairing a_0 -> b_1,
  // a_1 -> b_0 is within tol.
  const auto at = [](double t) { return Vec3(std::cos(t * 1e-6), std::sin(t * 1e-6), 0); };
  const Program a{{at(0), at(-0.9), Vec3::UnitZ()}}, b{{at(-0.2), at(0.8), Vec3::UnitZ()}};
  EXPECT_TRUE(equivalent(a, b, kSignedPermutations));
  EXPECT_TRUE(equivalent(a, b, kOrthogonal));
}

TEST(ProgramEquivalence, CollinearAndTinyProgramsDoNotCrash) {
  const Vec3 z = Vec3::UnitZ();
  const Program zz_minus{{z, z, -z}};
  const Mat3 rotation = random_rotation(4);
  EXPECT_TRUE(equivalent(zz_minus, transformed(zz_minus, rotation), kOrthogonal));
  EXPECT_TRUE(equivalent(zz_minus, noisy(transformed(zz_minus, rotation), 1e-9, 1), kOrthogonal));
  EXPECT_FALSE(equivalent(zz_minus, transformed(zz_minus, rotation), kSignedPermutations));
  EXPECT_TRUE(equivalent(zz_minus, Program{{-z, z, -z}}, kSignedPermutations));  // z -> -z
  const Vec3 x = Vec3::UnitX();
  EXPECT_TRUE(equivalent(zz_minus, Program{{x, -x, x}}, kSignedPermutations));
  EXPECT_FALSE(equivalent(zz_minus, Program{{z, z, z}}, kOrthogonal));
  EXPECT_FALSE(equivalent(zz_minus, Program{{z, z, Vec3::UnitX()}}, kOrthogonal));
  EXPECT_FALSE(equivalent(Program{{z, z, Vec3::UnitX()}}, zz_minus, kOrthogonal));

  const Program all_z{{z, z, z, z}};
  EXPECT_TRUE(equivalent(all_z, transformed(all_z, rotation), kOrthogonal));

  // One position: any unit vector is an orthogonal image of any other.
  const Program one{{Vec3::UnitX()}}, other = Program::random(1, 5);
  EXPECT_TRUE(equivalent(one, other, kOrthogonal));
  EXPECT_FALSE(equivalent(one, other, kSignedPermutations));
  // Two positions: decided by their angle.
  const Program right_angle{{x, Vec3::UnitY()}};
  EXPECT_TRUE(equivalent(right_angle, transformed(right_angle, rotation), kOrthogonal));
  EXPECT_FALSE(equivalent(right_angle, Program{{x, Vec3(1, 1, 0).normalized()}}, kOrthogonal));
  // A zero vector is not a position, but must not crash either.
  const Program with_zero{{Vec3::Zero(), Vec3::UnitX()}};
  EXPECT_TRUE(equivalent(with_zero, Program{{Vec3::UnitY(), Vec3::Zero()}}, kOrthogonal));
  EXPECT_FALSE(equivalent(with_zero, Program{{Vec3::UnitY(), Vec3::UnitX()}}, kOrthogonal));
}

}  // namespace
}  // namespace scalcal
