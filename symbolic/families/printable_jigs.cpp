// printable_jigs: the twelve polyhedral jigs jig:NAME (one position per face: its outer normal),
// each with the parameter orientation, how the meter sits in the jig (symbolic/jigs.hpp).
#include <cmath>

#include "numeric/io/input_error.hpp"
#include "symbolic/family.hpp"
#include "symbolic/jigs.hpp"
#include "symbolic/octahedral_orbits.hpp"

namespace scalcal::symbolic {

using GiNaC::ex;

namespace {

std::vector<WeightedPoint> axes() { return axis_orbit(); }
// The octahedral family's order of points, so jig:rhombicuboctahedron is octahedral-1-1-1.
std::vector<WeightedPoint> edges() { return edge_orbit(); }
std::vector<WeightedPoint> diagonals() { return diagonal_orbit(); }

// The icosahedron whose vertices point along dodecahedral_points() (0, +-1, +-phi) has its faces
// along (+-1, +-1, +-1) and (0, +-phi, +-1/phi) cyclic, over sqrt 3: the mirror image of the
// icosahedral-20 program's frame, needed where both kinds of faces sit on one solid.
std::vector<WeightedPoint> icosahedron_faces_dual_frame() {
  const ex phi = (1 + GiNaC::sqrt(ex(5))) / 2, inv_phi = phi - 1, d = GiNaC::sqrt(ex(3)) / 3;
  std::vector<WeightedPoint> pts = diagonals();
  for (int c = 0; c < 3; ++c)
    for (int s1 : {1, -1})
      for (int s2 : {1, -1}) {
        Point v;
        v[c] = 0;
        v[(c + 1) % 3] = s1 * phi * d;
        v[(c + 2) % 3] = s2 * inv_phi * d;
        pts.push_back({1, v});
      }
  return pts;
}

// The icosahedron's 30 edge midpoints: the axes and (1/2, 1/(2 phi), phi/2) cyclic with all signs.
std::vector<WeightedPoint> icosahedron_edge_midpoints() {
  const ex phi = (1 + GiNaC::sqrt(ex(5))) / 2;
  const ex base[3] = {ex(1) / 2, (phi - 1) / 2, phi / 2};
  std::vector<WeightedPoint> pts = axes();
  for (int c = 0; c < 3; ++c)
    for (int s1 : {1, -1})
      for (int s2 : {1, -1})
        for (int s3 : {1, -1}) {
          Point v;
          v[c] = s1 * base[0];
          v[(c + 1) % 3] = s2 * base[1];
          v[(c + 2) % 3] = s3 * base[2];
          pts.push_back({1, v});
        }
  return pts;
}

std::vector<WeightedPoint> joined(std::vector<WeightedPoint> a, const std::vector<WeightedPoint>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

Family jig_family(const JigSolid& solid) {
  Family f;
  f.name = "jig:" + solid.name;
  f.summary = solid.name + " jig: " + std::to_string(solid.normals.size()) + " faces (" + solid.faces + "), " +
              solid.symmetry + " symmetry";
  f.pattern = f.name;
  f.group = "jig";
  f.source = "printable jig";
  f.params = {{"orientation", "identity",
               "how the meter sits in the jig: identity, aa:X,Y,Z,DEG, q:W,X,Y,Z or rows:R11,...,R33",
               orientation_matrix,
               // A symbolic rotation puts its symbols in every position: two took 4 s, three over 30 s.
               2}};
  f.points = [normals = solid.normals](const ParamMap& p) {
    return oriented(GiNaC::ex_to<GiNaC::matrix>(p.at("orientation")), normals);
  };
  return f;
}

}  // namespace

const std::vector<JigSolid>& printable_jigs() {
  static const std::vector<JigSolid> all = {
      {"cube", "6 squares", "octahedral", axes()},
      {"octahedron", "8 triangles", "octahedral", diagonals()},
      {"dodecahedron", "12 pentagons", "icosahedral", dodecahedral_points()},
      {"icosahedron", "20 triangles", "icosahedral", icosahedral_points()},
      {"cuboctahedron", "6 squares + 8 triangles", "octahedral", joined(axes(), diagonals())},
      {"truncated-octahedron", "6 squares + 8 hexagons", "octahedral", joined(axes(), diagonals())},
      {"truncated-cube", "6 octagons + 8 triangles", "octahedral", joined(axes(), diagonals())},
      {"rhombicuboctahedron", "18 squares + 8 triangles", "octahedral", joined(joined(axes(), edges()), diagonals())},
      {"rhombic-dodecahedron", "12 rhombi", "octahedral", edges()},
      {"icosidodecahedron", "12 pentagons + 20 triangles", "icosahedral",
       joined(dodecahedral_points(), icosahedron_faces_dual_frame())},
      {"truncated-icosahedron", "12 pentagons + 20 hexagons", "icosahedral",
       joined(dodecahedral_points(), icosahedron_faces_dual_frame())},
      {"rhombic-triacontahedron", "30 rhombi", "icosahedral", icosahedron_edge_midpoints()},
  };
  return all;
}

std::vector<WeightedPoint> oriented(const GiNaC::matrix& O, const std::vector<WeightedPoint>& normals) {
  std::vector<WeightedPoint> out;
  out.reserve(normals.size());
  for (const auto& n : normals) {
    Point v;
    // Not canonical(): the dodecahedron's 1/sqrt(1 + phi^2) is a nested radical canonical() cannot
    // rationalise; products of two coordinates (all H^T H needs) square it away.
    for (int r = 0; r < 3; ++r) v[r] = GiNaC::expand(O(r, 0) * n.eta[0] + O(r, 1) * n.eta[1] + O(r, 2) * n.eta[2]);
    out.push_back({n.weight, v});
  }
  return out;
}

GiNaC::matrix orientation_matrix(const std::string& text, GiNaC::parser& reader) {
  auto fail = [&](const std::string& why) {
    return InputError("--param", 0, "orientation=" + display_name(text) + ": " + why);
  };
  auto components = [&](std::size_t from, std::size_t count) {
    std::vector<ex> v;
    std::size_t start = from;
    for (;;) {
      const std::size_t comma = text.find(',', start);
      const std::string part = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
      try {
        v.push_back(reader(part));
        // q: and rows: components and aa:'s axis are exact (exact_decimals); aa:'s angle keeps its
        // float, reduced exactly modulo 360 below.
        if (!(text.rfind("aa:", 0) == 0 && v.size() == 4)) v.back() = exact_decimals(v.back());
      } catch (const std::exception& e) {
        throw fail("'" + display_name(part) + "' is not an expression (" + e.what() + ")");
      }
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
    if (v.size() != count) throw fail("expected " + std::to_string(count) + " comma-separated components");
    return v;
  };
  auto numeric_value = [](const ex& e) -> std::optional<double> {
    const ex v = GiNaC::evalf(e);
    if (!GiNaC::is_a<GiNaC::numeric>(v) || !GiNaC::ex_to<GiNaC::numeric>(v).is_real()) return std::nullopt;
    return GiNaC::ex_to<GiNaC::numeric>(v).to_double();
  };
  GiNaC::matrix O(3, 3);
  if (text == "identity") {
    for (int i = 0; i < 3; ++i) O(i, i) = 1;
    return O;
  }
  if (text.rfind("aa:", 0) == 0) {
    const auto c = components(3, 4);
    const ex n2 = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
    if (auto n = numeric_value(n2); n && *n == 0) throw fail("the axis is zero");
    // Reduced exactly modulo 360 before it becomes radians: a float of 1e20 degrees times pi/180 keeps
    // 17 digits of a number whose remainder sits in its 21st.
    const ex degrees = reduced_degrees(c[3], text.substr(text.rfind(',') + 1));
    const ex theta = degrees * GiNaC::Pi / 180, cs = GiNaC::cos(theta), sn = GiNaC::sin(theta), n = GiNaC::sqrt(n2);
    // Rodrigues: R = cos I + sin [a]x + (1 - cos) a a^T; the rows of O = R^T are R's columns.
    const ex a[3] = {c[0] / n, c[1] / n, c[2] / n};
    const ex cross[3][3] = {{0, -a[2], a[1]}, {a[2], 0, -a[0]}, {-a[1], a[0], 0}};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        O(j, i) = canonical((i == j ? cs : ex(0)) + sn * cross[i][j] + (1 - cs) * c[i] * c[j] / n2);
    return O;
  }
  if (text.rfind("q:", 0) == 0) {
    const auto q = components(2, 4);
    const ex &w = q[0], &x = q[1], &y = q[2], &z = q[3];
    const ex n2 = w * w + x * x + y * y + z * z;
    if (auto n = numeric_value(n2); n && *n == 0) throw fail("the quaternion is zero");
    const ex R[3][3] = {{w * w + x * x - y * y - z * z, 2 * (x * y - w * z), 2 * (x * z + w * y)},
                        {2 * (x * y + w * z), w * w - x * x + y * y - z * z, 2 * (y * z - w * x)},
                        {2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z}};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) O(j, i) = canonical(R[i][j] / n2);
    return O;
  }
  if (text.rfind("rows:", 0) == 0) {
    const auto r = components(5, 9);
    double worst = 0;
    bool all_numbers = true;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) O(i, j) = r[3 * i + j];
    for (int i = 0; i < 3 && all_numbers; ++i)
      for (int j = 0; j < 3; ++j) {
        const auto d = numeric_value(O(i, 0) * O(j, 0) + O(i, 1) * O(j, 1) + O(i, 2) * O(j, 2));
        if (!d) {
          all_numbers = false;
          break;
        }
        worst = std::max(worst, std::abs(*d - (i == j ? 1.0 : 0.0)));
      }
    if (all_numbers) {
      if (worst > 1e-9) throw fail("the rows are not orthonormal (|O O^T - I| = " + std::to_string(worst) + ")");
      const auto det = numeric_value(O.determinant());
      if (det && *det < 0) throw fail("a reflection (det -1), not a rotation: a meter cannot be mounted mirrored");
    }
    return O;
  }
  throw fail("expected identity, aa:X,Y,Z,DEG, q:W,X,Y,Z or rows:R11,R12,R13,R21,R22,R23,R31,R32,R33");
}

std::vector<Family> printable_jigs_families() {
  std::vector<Family> out;
  for (const auto& solid : printable_jigs()) out.push_back(jig_family(solid));
  return out;
}

}  // namespace scalcal::symbolic
