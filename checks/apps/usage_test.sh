#!/usr/bin/env bash
# Usage: usage_test.sh path/to/affinterp
set -u
affinterp=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0

# expect STATUS DESCRIPTION -- command...: the command exits with STATUS.
expect() {
  local want=$1 what=$2
  shift 3
  "$@" >"$work/out" 2>"$work/err"
  local got=$?
  if [ "$got" -ne "$want" ]; then
    echo "FAIL: $what: exit $got, expected $want"; cat "$work/err"; failures=$((failures + 1))
  fi
}
# one_line_error: the last command's standard error is exactly one line.
one_line_error() {
  if [ "$(wc -l <"$work/err")" -ne 1 ]; then
    echo "FAIL: $1: error is not one line:"; cat "$work/err"; failures=$((failures + 1))
  fi
}

expect 0 "--help" -- "$affinterp" --help
expect 0 "claims --help" -- "$affinterp" claims --help
expect 0 "report --help" -- "$affinterp" report --help
for command in shapes interpolate view exp3 eig3 decide; do
  expect 0 "$command --help" -- "$affinterp" "$command" --help
done
expect 2 "view without a run" -- "$affinterp" view -o "$work/compare.html"
one_line_error "view without a run"
expect 2 "no command" -- "$affinterp"
one_line_error "no command"
expect 2 "unknown option" -- "$affinterp" claims --bogus
one_line_error "unknown option"
expect 2 "bad size" -- "$affinterp" claims --size huge
one_line_error "bad size"
expect 2 "unknown claim" -- "$affinterp" claims --only no.such.claim --out "$work/r"
one_line_error "unknown claim"
[ ! -e "$work/r/claims.json" ] || { echo "FAIL: a failed run wrote claims.json"; failures=$((failures + 1)); }

# decide: a bad expression is a one-line error with exit status 2, before any decider runs.
for condition in "x + y >= 2" "tr >= 2 and" "a^(1/2) > 0" "a^0.5 > 0" "(a > 0" "a $ 1" "tr/0 > 1" ""; do
  expect 2 "decide --condition '$condition'" -- "$affinterp" decide --homotopy linear --notion area --condition "$condition"
  one_line_error "decide --condition '$condition'"
done
expect 2 "decide: beta is no variable of the svd area" -- "$affinterp" decide --homotopy svd --notion area --condition "beta = 0"
one_line_error "decide: beta is no variable of the svd area"
expect 2 "decide: unknown homotopy" -- "$affinterp" decide --homotopy affine --notion area --condition "true"
one_line_error "decide: unknown homotopy"

expect 0 "claims --list" -- "$affinterp" claims --list
# A line per declared claim: ID, "implemented", where printed, statement (pinned_verdicts_test checks that
# every claim is there); no ID twice.
awk -F'\t' 'NF != 4 || $2 != "implemented" || seen[$1]++ { bad = 1 } END { exit bad || NR == 0 }' "$work/out" &&
  grep -q "^kaji.polar.det	" "$work/out" ||
  { echo "FAIL: --list does not list each claim once as ID, implemented, where, statement"; failures=$((failures + 1)); }

# A run, then a failed run: the first run's outputs stay as they were.
expect 0 "quick run" -- "$affinterp" claims --size quick --no-figures --only kaji.linear.collapse --out "$work/r"
cp "$work/r/claims.json" "$work/before.json"
expect 2 "failed run" -- "$affinterp" claims --only no.such.claim --out "$work/r"
cmp -s "$work/r/claims.json" "$work/before.json" || { echo "FAIL: a failed run changed claims.json"; failures=$((failures + 1)); }
expect 0 "report from claims.json" -- "$affinterp" report --in "$work/r/claims.json"
expect 1 "report from garbage" -- "$affinterp" report --in /dev/null
one_line_error "report from garbage"

echo "$failures failed"
[ "$failures" -eq 0 ]
