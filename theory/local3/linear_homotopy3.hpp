#pragma once
// The linear homotopy in 3D, A^L(t) = (1−t)I + tA (the 3D form of Kaji §3's A^L; it may pass through singular
// maps: det A^L(t) is a cubic in t).
#include "theory/local3/rotation3.hpp"

namespace affinterp::local3 {

template <class Scalar>
struct LinearHomotopy3 {
  Mat3<Scalar> A;

  Mat3<Scalar> operator()(const Scalar& t) const { return (Scalar(1) - t) * Mat3<Scalar>::Identity() + t * A; }
};

}  // namespace affinterp::local3
