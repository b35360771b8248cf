#pragma once
// A peer: Eigen's unsupported MatrixExponential (Padé approximant with scaling and squaring).
#include "theory/sym3/algorithms.hpp"

namespace affinterp::sym3 {

Mat3 exp_eigen_pade(const Mat3& S);

}  // namespace affinterp::sym3
