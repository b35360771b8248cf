#include "experiments/claims/local/printed_conditions.hpp"

namespace affinterp::claims::local {

using logic::greater;
using logic::greater_equal;
using logic::less;
using logic::less_equal;

Formula thm_2_2_1_formula(const Polynomial& trace, const Polynomial& det) {
  const Polynomial two(2);
  return greater_equal(trace, det + Polynomial(1)) || (less_equal(two * det, trace) && less(trace, two)) ||
         (less_equal(two, trace) && less(trace, two * det));
}

Formula corrected_area_formula(const Polynomial& trace, const Polynomial& det) {
  const Polynomial two(2);
  return (less_equal(two * det, trace) && less_equal(trace, two)) ||
         (less_equal(two, trace) && less_equal(trace, two * det));
}

Formula thm_2_2_3_formula(const Polynomial& x, const Polynomial& y) {
  return (greater_equal(x, 1) && greater_equal(y, 1)) ||
         (greater(x, 0) && less_equal(x, 1) && greater(y, 0) && less_equal(y, 1));
}

Formula thm_2_2_5_formula(const Polynomial& x, const Polynomial& y, const Polynomial& h) {
  return greater_equal((x - Polynomial(1)) * (y - Polynomial(1)), h * h) &&
         (greater_equal(x + y, 2) || (greater(x, 0) && less_equal(x, 1) && greater(y, 0) && less_equal(y, 1)));
}

}  // namespace affinterp::claims::local
