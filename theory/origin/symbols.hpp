#pragma once
// The symbols of thesis §2.3: the origin o = (x, y) and the intermediate vertices v_1 … v_4.
// GiNaC tells symbols apart by identity, not by name, so every part of the study uses these instances.
#include <ginac/ginac.h>

namespace affinterp::origin {

struct Symbols {
  GiNaC::symbol x{"x"}, y{"y"};
  /// Column k − 1 is v_k = (v_kx, v_ky), the vertices of the intermediate configuration.
  GiNaC::matrix v{2, 4};
  /// v_1x, v_1y, …, v_4x, v_4y: the unknowns of the minimisation.
  GiNaC::lst unknowns;
};

const Symbols& symbols();

/// The column vector (a, b).
GiNaC::matrix column(const GiNaC::ex& a, const GiNaC::ex& b);

}  // namespace affinterp::origin
