#pragma once
// Internal to affinterp::certified (not installed): the Arb matrix behind Balls, and an arb_t with value
// semantics for the computations.
#include "theory/certified/ball.hpp"

#include <arb.h>
#include <arb_mat.h>

namespace affinterp::certified {

struct Balls::Impl {
  arb_mat_t m;
  Impl(int rows, int cols) { arb_mat_init(m, rows, cols); }
  ~Impl() { arb_mat_clear(m); }
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;
};

namespace detail {

/// An arb_t that can live in arrays and be copied.
class Num {
 public:
  Num() { arb_init(x_); }
  explicit Num(double d) : Num() { arb_set_d(x_, d); }
  Num(const Num& other) : Num() { arb_set(x_, other.x_); }
  Num& operator=(const Num& other) {
    arb_set(x_, other.x_);
    return *this;
  }
  ~Num() { arb_clear(x_); }
  arb_ptr get() { return x_; }
  arb_srcptr get() const { return x_; }
  arf_ptr mid() { return arb_midref(x_); }
  arf_srcptr mid() const { return arb_midref(x_); }

 private:
  arb_t x_;
};

/// A double ball from an Arb ball: mid rounded to nearest, rad covering the rest (rounded up).
Ball to_ball(arb_srcptr x);

}  // namespace detail
}  // namespace affinterp::certified
