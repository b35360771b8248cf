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


def test_3d_polar_norm_one_sided_condition_fails_at_an_exact_point():
    out = affinterp.decide("l1 >= 1 and l2 >= 1", "polar", "norm", dim=3)
    assert out["verdict"] == "not-equivalent", out
    c = out["counterexample"]
    assert c["condition"] is True and c["property"] is False, c
    l = [Fraction(c[name]) for name in ("l1", "l2", "l3")]
    assert min(l) < 1 < max(l), c  # S - I indefinite (LEMMAS.md L15)


def test_3d_exp_log_volume_is_always_good():
    assert affinterp.decide("true", "exp-log", "volume", dim=3) == {"verdict": "equivalent", "counterexample": None}
