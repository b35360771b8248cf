#include "theory/sym3/pade.hpp"

#include <unsupported/Eigen/MatrixFunctions>

namespace affinterp::sym3 {

Mat3 exp_eigen_pade(const Mat3& S) { return S.exp(); }

}  // namespace affinterp::sym3
