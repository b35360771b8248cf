#include "experiments/inputs/sym3/families.hpp"

#include "theory/linalg/symmetric.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <numbers>
#include <sstream>

namespace affinterp::sym3 {

namespace {

/// A standard normal draw (Box–Muller on two uniform draws; platform-independent).
double gaussian(Rng& rng) {
  const double u1 = 1.0 - rng.uniform(0.0, 1.0);  // in (0, 1]
  const double u2 = rng.uniform(0.0, 1.0);
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

/// Draws `count` matrices Q diag(spectrum(rng)) Qᵀ with a fresh random rotation Q for each.
template <class Spectrum>
std::vector<Mat3> rotated(std::uint64_t seed, std::size_t count, Spectrum spectrum) {
  Rng rng(seed);
  std::vector<Mat3> out;
  out.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    const Vec3 lambda = spectrum(rng);
    out.push_back(with_spectrum(lambda, random_rotation(rng)));
  }
  return out;
}

std::vector<Mat3> draw_thesis(const Family&, std::uint64_t seed, std::size_t count) {
  return thesis_distribution(seed, count);
}

std::vector<Mat3> draw_spread(const Family&, std::uint64_t seed, std::size_t count) {
  return rotated(seed, count, [](Rng& rng) { return Vec3(rng.uniform(0, 3), rng.uniform(0, 3), rng.uniform(0, 3)); });
}

/// λ, λ + gap and a free eigenvalue, all in [0, 3].
std::vector<Mat3> draw_pair(const Family& family, std::uint64_t seed, std::size_t count) {
  const double gap = *family.gap;
  return rotated(seed, count, [gap](Rng& rng) {
    const double lambda = rng.uniform(0, 3 - gap);
    return Vec3(lambda, lambda + gap, rng.uniform(0, 3));
  });
}

/// λ, λ + gap, λ + 2 gap, all in [0, 3].
std::vector<Mat3> draw_triple(const Family& family, std::uint64_t seed, std::size_t count) {
  const double gap = *family.gap;
  return rotated(seed, count, [gap](Rng& rng) {
    const double lambda = rng.uniform(0, 3 - 2 * gap);
    return Vec3(lambda, lambda + gap, lambda + 2 * gap);
  });
}

/// λmax = s ∈ [1, 3], λmin = 10⁻¹² s, and one eigenvalue log-uniform in between.
std::vector<Mat3> draw_wide(const Family&, std::uint64_t seed, std::size_t count) {
  return rotated(seed, count, [](Rng& rng) {
    const double s = rng.uniform(1, 3);
    return Vec3(1e-12 * s, s * std::pow(10.0, rng.uniform(-12, 0)), s);
  });
}

std::vector<Mat3> draw_large(const Family&, std::uint64_t seed, std::size_t count) {
  return rotated(seed, count,
                 [](Rng& rng) { return Vec3(rng.uniform(-700, 700), rng.uniform(-700, 700), rng.uniform(-700, 700)); });
}

std::vector<Mat3> draw_diagonal(const Family&, std::uint64_t seed, std::size_t count) {
  Rng rng(seed);
  std::vector<Mat3> out(count, Mat3::Zero());
  for (Mat3& S : out)
    for (int i = 0; i < 3; ++i) S(i, i) = rng.uniform(0, 3);
  return out;
}

/// A diagonal in [0.01, 2.99] plus symmetric off-diagonal entries of size up to 10⁻⁸ (Gershgorin keeps
/// the spectrum inside [0, 3]).
std::vector<Mat3> draw_nearly_diagonal(const Family&, std::uint64_t seed, std::size_t count) {
  Rng rng(seed);
  std::vector<Mat3> out(count, Mat3::Zero());
  for (Mat3& S : out) {
    for (int i = 0; i < 3; ++i) S(i, i) = rng.uniform(0.01, 2.99);
    for (int i = 0; i < 3; ++i)
      for (int j = i + 1; j < 3; ++j) S(i, j) = S(j, i) = rng.uniform(-1e-8, 1e-8);
  }
  return out;
}

std::vector<Mat3> draw_scalar(const Family&, std::uint64_t seed, std::size_t count) {
  Rng rng(seed);
  std::vector<Mat3> out;
  out.reserve(count);
  for (std::size_t i = 0; i < count; ++i) out.push_back(rng.uniform(0, 3) * Mat3::Identity());
  return out;
}

std::vector<Mat3> draw_zero(const Family&, std::uint64_t, std::size_t count) {
  return std::vector<Mat3>(count, Mat3::Zero());
}

/// ±(1 + m) 2^e with the sign, the 52-bit mantissa m and the exponent e in [lo, hi] drawn separately
/// (rounded once, by ldexp, where 2^e is subnormal).
double across_range(Rng& rng, int lo, int hi) {
  const double mantissa = 1.0 + static_cast<double>(rng.bits() >> 12) * 0x1p-52;
  const double sign = rng.integer(0, 1) ? -1.0 : 1.0;
  return sign * std::ldexp(mantissa, static_cast<int>(rng.integer(lo, hi)));
}

/// The symmetric matrix of the six entries (xx, yy, zz, xy, xz, yz) with its coordinates permuted.
Mat3 permuted(Rng& rng, const std::array<double, 6>& e) {
  Mat3 S;
  S << e[0], e[3], e[4], e[3], e[1], e[5], e[4], e[5], e[2];
  std::array<int, 3> p{0, 1, 2};
  for (int i = 2; i > 0; --i) std::swap(p[i], p[rng.integer(0, i)]);
  Mat3 P;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) P(i, j) = S(p[i], p[j]);
  return P;
}

/// One matrix of six kinds, drawn with equal probability: (0) tiny and subnormal entries, 2^e with e in
/// [−1074, −30] and a spread of 60 binades within the matrix; (1) mixed scales: a diagonal entry
/// −(1 + m) 2^e, e in [30, 1023], beside a 2×2 block with moderate diagonal and off-diagonal entries down
/// to subnormal, coupled by entries of 2^[−1074, −500] or 0; (2) spectra whose largest eigenvalue is in
/// [705, 711], around exp's overflow at 709.78 (the others in [−1000, λmax]), random basis; (3) the
/// same in [−760, −700], where exp S is subnormal; (4) entries whose squares overflow with exp S finite:
/// [[−a, ±ac], [±ac, −a]] with a = (1 + m) 2^e, e in [512, 1022], c in [0, 1] (c = 1: an exact zero
/// eigenvalue beside −2a), and a moderate third diagonal entry; (5) all six entries with sign, mantissa
/// and exponent in [−1074, 1023] drawn separately (exp S mostly overflows: the error must say so).
Mat3 draw_across_range(Rng& rng) {
  const auto kind = rng.integer(0, 5);
  switch (kind) {
    case 0: {
      const int e = static_cast<int>(rng.integer(-1074, -30));
      std::array<double, 6> entries;
      for (double& x : entries) x = across_range(rng, e - 60, e);
      return permuted(rng, entries);
    }
    case 1: {
      const double huge = -std::abs(across_range(rng, 30, 1023));
      const double coupling1 = rng.integer(0, 1) ? across_range(rng, -1074, -500) : 0.0;
      const double coupling2 = rng.integer(0, 1) ? across_range(rng, -1074, -500) : 0.0;
      return permuted(
          rng, {huge, rng.uniform(-5, 5), rng.uniform(-5, 5), coupling1, coupling2, across_range(rng, -1074, 2)});
    }
    case 2:
    case 3: {
      const bool high = kind == 2;
      const double top = high ? rng.uniform(705, 711) : rng.uniform(-760, -700);
      const double bottom = high ? -1000.0 : -800.0;
      const Vec3 lambda(top, rng.uniform(bottom, top), rng.uniform(bottom, top));
      return with_spectrum(lambda, random_rotation(rng));
    }
    case 4: {
      const double a = std::abs(across_range(rng, 512, 1022));
      const double c = static_cast<double>(rng.integer(0, 1 << 20)) * 0x1p-20;
      const double off = (rng.integer(0, 1) ? -1.0 : 1.0) * (a * c);
      return permuted(rng, {-a, -a, rng.uniform(-5, 5), off, 0.0, 0.0});
    }
    default: {
      std::array<double, 6> entries;
      for (double& x : entries) x = across_range(rng, -1074, 1023);
      return permuted(rng, entries);
    }
  }
}

std::vector<Mat3> draw_full_range(const Family&, std::uint64_t seed, std::size_t count) {
  Rng rng(seed);
  std::vector<Mat3> out;
  out.reserve(count);
  for (std::size_t i = 0; i < count; ++i) out.push_back(draw_across_range(rng));
  return out;
}

/// λmax − λmid > 709: λmax uniform in [700, 712] (across exp's overflow, log DBL_MAX ≈ 709.78, which a
/// spread eigenvector lifts by up to log 3), λmid = λmax − u with u uniform in [709.5, 1100], λmin uniform
/// in [λmid − 400, λmid]. e^{λmid}/e^{λmax} is below the smallest normal double.
std::vector<Mat3> draw_far_apart(const Family&, std::uint64_t seed, std::size_t count) {
  return rotated(seed, count, [](Rng& rng) {
    const double top = rng.uniform(700, 712);
    const double middle = top - rng.uniform(709.5, 1100);
    return Vec3(rng.uniform(middle - 400, middle), middle, top);
  });
}

std::string gap_name(double gap) {
  if (gap == 0) return "0";
  std::ostringstream name;
  name << gap;
  return name.str();
}

}  // namespace

std::vector<Mat3> thesis_distribution(std::uint64_t seed, std::size_t count) {
  Rng rng(seed);
  std::vector<Mat3> out;
  out.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    Mat3 M;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) M(r, c) = rng.uniform(-1, 1);
    out.push_back(linalg::outer_gram(M.transpose()));  // Mᵀ M, exactly symmetric
  }
  return out;
}

Mat3 random_rotation(Rng& rng) {
  Eigen::Quaterniond q(gaussian(rng), gaussian(rng), gaussian(rng), gaussian(rng));
  return q.normalized().toRotationMatrix();
}

Mat3 with_spectrum(const Vec3& lambda, const Mat3& Q) { return linalg::congruence(Q, lambda); }

const std::vector<double>& cluster_gaps() {
  static const std::vector<double> gaps = [] {
    std::vector<double> g;
    for (int e = 1; e <= 16; ++e) g.push_back(std::pow(10.0, -e));
    for (double near : {5e-7, 9e-7, 1.1e-6, 2e-6}) g.push_back(near);  // the thesis's threshold 10⁻⁶
    g.push_back(0);
    std::sort(g.begin(), g.end(), std::greater<>());
    return g;
  }();
  return gaps;
}

const std::vector<Family>& families() {
  static const std::vector<Family> all = [] {
    std::vector<Family> f = {
        {"thesis", "S = MᵀM, M uniform in [−1, 1] (thesis §3.4); spectrum in [0, 9]", {}, false, draw_thesis},
        {"spread", "eigenvalues uniform in [0, 3], random basis", {}, true, draw_spread},
        {"wide", "eigenvalues s·10⁻¹², s·10^u, s (ratio 10¹², s ∈ [1, 3]), random basis", {}, true, draw_wide},
        {"large", "eigenvalues uniform in [−700, 700], random basis", {}, false, draw_large},
        {"diagonal", "diagonal, entries uniform in [0, 3]", {}, true, draw_diagonal},
        {"nearly-diagonal",
         "diagonal in [0.01, 2.99] plus off-diagonal entries up to 10⁻⁸",
         {},
         true,
         draw_nearly_diagonal},
        {"scalar", "λI, λ uniform in [0, 3] (exact triple eigenvalue)", {}, true, draw_scalar},
        {"zero", "the zero matrix", {}, true, draw_zero},
    };
    for (double gap : cluster_gaps())
      f.push_back({"pair-gap-" + gap_name(gap),
                   "eigenvalues λ, λ + " + gap_name(gap) + " and a free one, in [0, 3], random basis", gap, true,
                   draw_pair});
    for (double gap : cluster_gaps())
      f.push_back({"triple-gap-" + gap_name(gap),
                   "eigenvalues λ, λ + " + gap_name(gap) + ", λ + 2·" + gap_name(gap) + ", in [0, 3], random basis",
                   gap, true, draw_triple});
    // Last, so that every family before them keeps its index (the claims seed each family by it).
    f.push_back({"full-range",
                 "the whole double range: subnormal and tiny entries, 10^±300 mixed scales, squares that overflow, "
                 "λmax around exp's overflow (709.78) and underflow (−745), random sign/mantissa/exponent entries",
                 {},
                 false,
                 draw_full_range,
                 true});
    f.push_back({"far-apart",
                 "λmax − λmid > 709: λmax in [700, 712] (across exp's overflow), λmid = λmax − [709.5, 1100], "
                 "λmin in [λmid − 400, λmid], random basis",
                 {},
                 false,
                 draw_far_apart,
                 true});
    return f;
  }();
  return all;
}

}  // namespace affinterp::sym3
