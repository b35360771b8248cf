#!/usr/bin/env bash
# `affinterp decide` end to end with QEPCAD B and Z3 (label `proof`): the --json object (verdict, counterexample, seconds), a
# counterexample that is exact and small, and the text form.
# Usage: decide_cli_test.sh path/to/affinterp
set -u
affinterp=$1
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# Thm 2.2.2 as printed (the branch tr >= det + 1 is wrong): not equivalent, the condition true where D is not good.
json=$("$affinterp" decide --homotopy svd --notion area --json \
  --condition "x + y >= x*y + 1 or (2*x*y <= x + y and x + y < 2) or (2 <= x + y and x + y < 2*x*y)") ||
  fail "decide exited $?"
python3 - "$json" <<'PY' || fail "printed Thm 2.2.2: $json"
import json, sys
from fractions import Fraction
out = json.loads(sys.argv[1])
assert set(out) == {"verdict", "counterexample", "seconds"}, out
assert out["verdict"] == "not-equivalent", out
c = out["counterexample"]
assert set(c) == {"x", "y", "condition", "property"}, c
assert c["condition"] is True and c["property"] is False, c
x, y = Fraction(c["x"]), Fraction(c["y"])
assert x > 0 and y > 0 and x.denominator <= 8 and y.denominator <= 8, c
assert x + y >= x * y + 1  # the printed branch holds ...
d0, d1 = x + y - 2, 2 * x * y - (x + y)  # ... but det((1-t)I + tD)' changes sign on [0, 1]
assert (d0 < 0 < d1) or (d1 < 0 < d0), c
assert out["seconds"] < 60
PY

# The corrected condition: equivalent, in text form.
text=$("$affinterp" decide --homotopy svd --notion area --condition "(2*det <= tr <= 2) or (2 <= tr <= 2*det)")
[ "$(head -1 <<<"$text")" = "equivalent" ] || fail "corrected Thm 2.2.2: $text"

exit $((failures > 0))
