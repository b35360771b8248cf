#pragma once
// The local theory (Kaji §3 and Appendix; thesis §2.2) in one include: the affine map of a triangle
// pair, rotations, the polar and rotation-only singular value decompositions, and the four homotopies.
#include "theory/local/affine_map.hpp"
#include "theory/local/exp_log_homotopy.hpp"
#include "theory/local/linear_homotopy.hpp"
#include "theory/local/polar_from_svd.hpp"
#include "theory/local/polar_homotopy.hpp"
#include "theory/local/svd_homotopy.hpp"
