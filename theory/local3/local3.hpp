#pragma once
// The local theory in 3D in one include: rotations by their axis-angle logarithm and its branches, the
// rotation-only SVD and the polar decomposition of A ∈ GL⁺(3), and the four homotopies between I and A.
#include "theory/local3/exp_log_homotopy3.hpp"
#include "theory/local3/linear_homotopy3.hpp"
#include "theory/local3/nearest_rotation3.hpp"
#include "theory/local3/polar_homotopy3.hpp"
#include "theory/local3/rotation_branch3.hpp"
#include "theory/local3/svd_homotopy3.hpp"
