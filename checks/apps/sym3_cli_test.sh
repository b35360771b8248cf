#!/usr/bin/env bash
# `affinterp exp3` / `affinterp eig3` on good and bad input: outputs, error messages and exit codes.
# Usage: sym3_cli_test.sh path/to/affinterp
set -u
affinterp="$1"
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# expect_run NAME EXPECTED_STATUS EXPECTED_STDOUT STDERR_PATTERN INPUT ARGS...
expect_run() {
  local name="$1" status="$2" stdout="$3" stderr_pattern="$4" input="$5"
  shift 5
  local out err code
  out=$(printf '%b' "$input" | "$affinterp" "$@" 2>/tmp/affinterp_cli_test_err.$$)
  code=$?
  err=$(cat /tmp/affinterp_cli_test_err.$$)
  rm -f /tmp/affinterp_cli_test_err.$$
  [[ $code == "$status" ]] || fail "$name: exit status $code, expected $status (stderr: $err)"
  [[ "$out" == "$stdout" ]] || fail "$name: stdout '$out', expected '$stdout'"
  [[ "$err" =~ $stderr_pattern ]] || fail "$name: stderr '$err' does not match '$stderr_pattern'"
}

# Good input: exp of a diagonal matrix and of zero, eigenvalues ascending; blank lines are skipped.
expect_run "exp3 diagonal" 0 \
  "1 0 0 0 1 0 0 0 1"$'\n'"1 0 0 0 1 0 0 0 1" "^$" "0 0 0 0 0 0 0 0 0\n\n  0 0 0  0 0 0  0 0 0\n" exp3
# Ours: ascending, to within a few units of roundoff.
out=$(printf '5 0 0 0 -1 0 0 0 2\n' | "$affinterp" eig3)
awk -v l="$out" 'BEGIN { split(l, x, " "); exit !(length(x) == 3 && (x[1] + 1) ^ 2 + (x[2] - 2) ^ 2 + (x[3] - 5) ^ 2 < 1e-28) }' ||
  fail "eig3 ascending: got '$out'"
expect_run "eig3 eigen-qr" 0 "-1 2 5" "^$" "5 0 0 0 -1 0 0 0 2\n" eig3 --algorithm eigen-qr
# exp of diag(0, 0, 700) has 17 significant digits of e^700.
out=$(printf '0 0 0 0 0 0 0 0 700\n' | "$affinterp" exp3 | awk '{print $9}')
[[ "$out" =~ ^1\.014232054735004[0-9]e\+304$ ]] || fail "exp3 e^700: got '$out'"

# Bad input: the lines before the bad one are written, the error names the line, status 1.
expect_run "not a number" 1 "0 0 0" "line 2: 'x' is not a number" "0 0 0 0 0 0 0 0 0\n1 2 x 2 1 0 0 0 1\n" eig3
expect_run "not symmetric" 1 "" "line 1: not symmetric" "1 2 3 4 5 6 7 8 9\n" exp3
expect_run "not finite" 1 "" "line 1: 'inf' is not finite" "1 0 0 0 1 0 0 0 inf\n" exp3
expect_run "overflow" 1 "" "line 1: '1e999' is not finite" "1 0 0 0 1 0 0 0 1e999\n" eig3
expect_run "overflowing exp" 1 "1 0 0 0 1 0 0 0 1" \
  "^affinterp: line 2: exp S overflows double: its largest eigenvalue 1e\\+200 exceeds log\\(DBL_MAX\\) = 709\\.78" \
  "0 0 0 0 0 0 0 0 0\n1e200 0 0 0 -1e200 0 0 0 0\n" exp3
expect_run "just above log(DBL_MAX)" 1 "" "^affinterp: line 1: exp S overflows double: its largest eigenvalue 709\\.9 exceeds" \
  "709.9 0 0 0 0 0 0 0 0\n" exp3
expect_run "a peer's failure is not an overflow" 1 "" \
  "^affinterp: line 1: thesis-improved-sd gives a non-finite result although exp S is finite \\(largest eigenvalue 3e-160," \
  "1e-160 2e-160 0 2e-160 1e-160 0 0 0 3e-160\n" exp3 --algorithm thesis-improved-sd

# The whole double range: subnormal entries (exp S = I + S, rounded), 10^±300 beside each
# other, entries whose squares overflow, a spectrum just below exp's overflow.
out=$(printf '1e-310 1e-310 0  1e-310 1e-310 0  0 0 1e-310\n' | "$affinterp" exp3)
awk -v l="$out" 'BEGIN { n = split(l, x, " "); d = x[2] * 1e300 - 1e-10; exit !(n == 9 && x[1] == 1 && x[5] == 1 &&
  x[9] == 1 && x[2] == x[4] && d * d < 1e-44 && x[3] == 0 && x[6] == 0) }' || fail "exp3 subnormal entries (I + S): got '$out'"
expect_run "mixed scales" 0 "0 0 0 0 1 0 0 0 7.3890560989306504" "^$" "-1e300 0 0 0 1e-300 0 0 0 2\n" exp3
expect_run "squares overflow" 0 "0.5 0.5 0 0.5 0.5 0 0 0 1" "^$" "-1e200 1e200 0 1e200 -1e200 0 0 0 0\n" exp3
out=$(printf '709.7 0 0 0 709.7 0 0 0 709.7\n' | "$affinterp" exp3 | awk '{print $1}')
[[ "$out" =~ ^1\.6[0-9]*e\+308$ ]] || fail "exp3 e^709.7: got '$out'"
expect_run "too few" 1 "" "line 1: expected 9 numbers" "1 0 0 0 1 0 0 0\n" exp3
expect_run "too many" 1 "" "line 1: expected 9 numbers" "1 0 0 0 1 0 0 0 1 1\n" exp3

# Usage errors: status 2.
expect_run "unknown algorithm" 2 "" "unknown algorithm 'nope'" "" exp3 --algorithm nope
expect_run "unknown eig algorithm" 2 "" "unknown algorithm 'nope'" "" eig3 --algorithm nope
list=$("$affinterp" exp3 --list)
[[ "$list" == *affinterp* && "$list" == *eigen-pade* && "$list" == *thesis-sd-printed* ]] || fail "exp3 --list: '$list'"

if ((failures > 0)); then
  echo "$failures failure(s)"
  exit 1
fi
echo "all exp3/eig3 CLI checks passed"
