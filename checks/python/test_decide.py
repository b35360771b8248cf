"""affinterp.decide with QEPCAD B and Z3 (label proof): the verdicts of `affinterp decide`."""
from fractions import Fraction

import affinterp


def test_printed_theorem_2_2_2_is_not_equivalent_with_an_exact_counterexample():
    out = affinterp.decide("x + y >= x*y + 1 or (2*x*y <= x + y and x + y < 2) or (2 <= x + y and x + y < 2*x*y)",
                           "svd", "area")
    assert out["verdict"] == "not-equivalent", out
    c = out["counterexample"]
    assert c["condition"] is True and c["property"] is False, c
    x, y = Fraction(c["x"]), Fraction(c["y"])
    d0, d1 = x + y - 2, 2 * x * y - (x + y)  # det((1-t)I + tD)' changes sign on [0, 1]
    assert (d0 < 0 < d1) or (d1 < 0 < d0), c


def test_corrected_condition_is_equivalent():
    out = affinterp.decide("(2*det <= tr <= 2) or (2 <= tr <= 2*det)", "svd", "area")
    assert out == {"verdict": "equivalent", "counterexample": None}, out
