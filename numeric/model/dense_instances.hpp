// The dense decompositions the numeric core runs on information matrices in double (P x P for the
// registered models' P = 3, 6, 9, 12, and dynamic): compiled once (dense_instances.cpp) and declared
// extern here, since each cost 1-3 s of compile time in every unit that used it (the 9 x 9
// eigen-solver alone in seven, its Cholesky in twelve). Same code, so the same bits; a model of
// another size simply compiles its own where it is used.
#pragma once
#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/Eigenvalues>

namespace scalcal::dense_instances {
template <int P>
using Mat = Eigen::Matrix<double, P, P>;
using MatX = Eigen::MatrixXd;
}  // namespace scalcal::dense_instances

#define SCALCAL_DENSE_EIGEN_SOLVER(prefix, M)                                                     \
  prefix template Eigen::SelfAdjointEigenSolver<M>& Eigen::SelfAdjointEigenSolver<M>::compute<M>( \
      const Eigen::EigenBase<M>&, int);
#define SCALCAL_DENSE_CHOLESKY(prefix, M) \
  prefix template Eigen::LLT<M, Eigen::Lower>& Eigen::LLT<M, Eigen::Lower>::compute<M>(const Eigen::EigenBase<M>&);
// Every instance: the eigen-solver where more than one unit needs it, the Cholesky factor for all.
#define SCALCAL_DENSE_INSTANCES(prefix)                                 \
  SCALCAL_DENSE_EIGEN_SOLVER(prefix, scalcal::dense_instances::Mat<6>)  \
  SCALCAL_DENSE_EIGEN_SOLVER(prefix, scalcal::dense_instances::Mat<9>)  \
  SCALCAL_DENSE_EIGEN_SOLVER(prefix, scalcal::dense_instances::Mat<12>) \
  SCALCAL_DENSE_EIGEN_SOLVER(prefix, scalcal::dense_instances::MatX)    \
  SCALCAL_DENSE_CHOLESKY(prefix, scalcal::dense_instances::Mat<3>)      \
  SCALCAL_DENSE_CHOLESKY(prefix, scalcal::dense_instances::Mat<6>)      \
  SCALCAL_DENSE_CHOLESKY(prefix, scalcal::dense_instances::Mat<9>)      \
  SCALCAL_DENSE_CHOLESKY(prefix, scalcal::dense_instances::Mat<12>)     \
  SCALCAL_DENSE_CHOLESKY(prefix, scalcal::dense_instances::MatX)
SCALCAL_DENSE_INSTANCES(extern)
