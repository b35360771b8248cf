#include "theory/certified/ball.hpp"

#include "theory/certified/arb_balls.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace affinterp::certified {

namespace detail {

Ball to_ball(arb_srcptr x) {
  if (!arb_is_finite(x)) return {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()};
  Ball out;
  out.mid = arf_get_d(arb_midref(x), ARF_RND_NEAR);
  if (!std::isfinite(out.mid)) return {out.mid, std::numeric_limits<double>::infinity()};
  // |x − mid| ≤ |exact mid − mid| + rad: computed exactly in arf, then rounded up.
  arf_t gap, mid;
  arf_init(gap);
  arf_init(mid);
  arf_set_d(mid, out.mid);
  arf_sub(gap, arb_midref(x), mid, ARF_PREC_EXACT, ARF_RND_DOWN);
  arf_abs(gap, gap);
  arf_t r;
  arf_init(r);
  arf_set_mag(r, arb_radref(x));
  arf_add(gap, gap, r, 64, ARF_RND_UP);
  out.rad = arf_get_d(gap, ARF_RND_UP);
  arf_clear(r);
  arf_clear(gap);
  arf_clear(mid);
  return out;
}

}  // namespace detail

double Ball::lower() const { return std::nextafter(mid - rad, -std::numeric_limits<double>::infinity()); }
double Ball::upper() const { return std::nextafter(mid + rad, std::numeric_limits<double>::infinity()); }

Balls::Balls() : impl_(std::make_shared<Impl>(0, 0)) {}
Balls::Balls(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}

int Balls::rows() const { return static_cast<int>(arb_mat_nrows(impl_->m)); }
int Balls::cols() const { return static_cast<int>(arb_mat_ncols(impl_->m)); }

namespace {
arb_srcptr at(const Balls::Impl& impl, int i, int j) {
  if (i < 0 || j < 0 || i >= arb_mat_nrows(impl.m) || j >= arb_mat_ncols(impl.m))
    throw std::out_of_range("certified::Balls: index out of range");
  return arb_mat_entry(impl.m, i, j);
}
}  // namespace

Ball Balls::entry(int i, int j) const { return detail::to_ball(at(*impl_, i, j)); }

double Balls::mid(int i, int j) const { return arf_get_d(arb_midref(at(*impl_, i, j)), ARF_RND_NEAR); }

namespace {
/// A mag_t as a double, rounded up (mag_get_d stops at 2⁻¹⁰⁰⁰ for tiny values; this goes down to the
/// smallest subnormal).
double up(const mag_t m) {
  arf_t x;
  arf_init(x);
  arf_set_mag(x, m);
  const double out = arf_get_d(x, ARF_RND_UP);
  arf_clear(x);
  return out;
}
}  // namespace

double Balls::radius(int i, int j) const {
  arb_srcptr x = at(*impl_, i, j);
  if (!arb_is_finite(x)) return std::numeric_limits<double>::infinity();
  return up(arb_radref(x));
}

double Balls::max_radius() const {
  double worst = 0;
  for (int i = 0; i < rows(); ++i)
    for (int j = 0; j < cols(); ++j) worst = std::fmax(worst, radius(i, j));
  return worst;
}

double Balls::frobenius_radius() const {
  arb_t sum, r;
  arb_init(sum);
  arb_init(r);
  bool finite = true;
  for (int i = 0; i < rows(); ++i)
    for (int j = 0; j < cols(); ++j) {
      arb_srcptr x = arb_mat_entry(impl_->m, i, j);
      finite = finite && arb_is_finite(x);
      arf_set_mag(arb_midref(r), arb_radref(x));
      arb_addmul(sum, r, r, 64);
    }
  arb_sqrtpos(sum, sum, 64);
  arf_t u;
  arf_init(u);
  arb_get_ubound_arf(u, sum, 64);
  const double out = finite ? arf_get_d(u, ARF_RND_UP) : std::numeric_limits<double>::infinity();
  arf_clear(u);
  arb_clear(sum);
  arb_clear(r);
  return out;
}

Ball Balls::frobenius_norm() const {
  arb_t sum, t;
  arb_init(sum);
  arb_init(t);
  for (int i = 0; i < rows(); ++i)
    for (int j = 0; j < cols(); ++j) {
      arb_sqr(t, arb_mat_entry(impl_->m, i, j), 128);
      arb_add(sum, sum, t, 128);
    }
  arb_sqrtpos(sum, sum, 128);
  const Ball out = detail::to_ball(sum);
  arb_clear(sum);
  arb_clear(t);
  return out;
}

double Balls::relative_radius() const {
  const double radius = frobenius_radius();
  if (radius == 0) return 0;
  const double norm = frobenius_norm().lower();
  return norm > 0 ? radius / norm : std::numeric_limits<double>::infinity();
}

std::string Balls::mid_string(int i, int j, int digits) const {
  char* text = arf_get_str(arb_midref(at(*impl_, i, j)), digits);
  std::string out(text);
  flint_free(text);
  return out;
}

std::string Balls::to_string(int i, int j, int digits) const {
  char* text = arb_get_str(at(*impl_, i, j), digits, 0);
  std::string out(text);
  flint_free(text);
  return out;
}

bool Balls::finite() const {
  for (int i = 0; i < rows(); ++i)
    for (int j = 0; j < cols(); ++j)
      if (!arb_is_finite(arb_mat_entry(impl_->m, i, j))) return false;
  return true;
}

}  // namespace affinterp::certified
