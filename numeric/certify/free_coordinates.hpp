// Which chart coordinates a certificate solves for and which it holds at 0, i.e. at the computed
// program (the rotation gauge, the surplus of a design): the full vector is (u0, v0, u1, v1, ...).
#pragma once
#include <vector>

#include <Eigen/Core>

namespace scalcal::certify_detail {

struct FreeCoordinates {
  std::vector<int> free;    // indices into the full vector, in solving order
  std::vector<int> column;  // full index -> position in `free`, or -1 when held at 0

  static FreeCoordinates all_but(int full_size, const std::vector<int>& fixed) {
    FreeCoordinates c;
    c.column.assign(full_size, 0);
    for (int k : fixed) c.column[k] = -1;
    for (int k = 0; k < full_size; ++k)
      if (c.column[k] >= 0) {
        c.column[k] = static_cast<int>(c.free.size());
        c.free.push_back(k);
      }
    return c;
  }

  int size() const { return static_cast<int>(free.size()); }

  template <class T>
  Eigen::Matrix<T, Eigen::Dynamic, 1> full(const Eigen::Matrix<T, Eigen::Dynamic, 1>& x) const {
    Eigen::Matrix<T, Eigen::Dynamic, 1> z(column.size());
    for (std::size_t k = 0; k < column.size(); ++k) z(k) = column[k] < 0 ? T(0) : x(column[k]);
    return z;
  }
};

}  // namespace scalcal::certify_detail
