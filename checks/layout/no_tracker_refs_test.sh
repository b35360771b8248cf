#!/usr/bin/env bash
# Comments and documents say why, the commit messages say when: no tracked file refers to an issue of a tracker
# that is not in the repository ("issue" and a number), and none carries a date (year-month-day). Each match
# fails this test, named as file:line. Not scanned: what the programs generate from runs, which is dated on
# purpose (the report, its per-claim pages, claims.json, the benchmark history, the figures, the deciders'
# transcripts). A date inside a string literal of a line of code is a test's data (a run's identifier or time
# stamp), not a date of the text; in a comment or a Markdown file every date counts.
# Usage: no_tracker_refs_test.sh SOURCE_DIR
set -euo pipefail
cd "$1"

generated='^reports/(REPORT\.md|claims/|claims\.json|bench/|figures/)|^reports/proofs/.*\.out$'
if git rev-parse --git-dir >/dev/null 2>&1; then
  mapfile -t files < <(git ls-files | grep -Ev "$generated")
else
  mapfile -t files < <(find . -type f -not -path './build*' -not -path './.git/*' | sed 's|^\./||' |
    grep -Ev "$generated")
fi

issues=$(grep -nIiE '\bissues? #?[0-9]+' -- "${files[@]}" 2>/dev/null || true)
date='20[0-9][0-9]-[01][0-9]-[0-3][0-9]'  # no {2}: mawk has no intervals
# Each date on a line counts unless the text before it is code with a string literal open: an odd number of
# quotes, the first before any //, on a line that is no comment.
dates=$(grep -nIE "$date" -- "${files[@]}" 2>/dev/null | awk -v date="$date" '
  {
    file = $0; sub(/:.*/, "", file)
    text = $0; sub(/^[^:]*:[^:]*:/, "", text)
    rest = text; before = ""; counts = 0
    while (match(rest, date)) {
      before = before substr(rest, 1, RSTART - 1)
      quotes = gsub(/"/, "\"", before)
      slash = index(before, "//"); first_quote = index(before, "\"")
      literal = file !~ /\.md$/ && before !~ /^[ \t]*(\/\/|#|\*|\/\*)/ && quotes % 2 == 1 &&
                (slash == 0 || first_quote < slash)
      if (!literal) counts = 1
      before = before substr(rest, RSTART, RLENGTH); rest = substr(rest, RSTART + RLENGTH)
    }
    if (counts) print
  }' || true)

if [ -n "$issues$dates" ]; then
  [ -z "$issues" ] || { echo "a tracker's issue number (say what it stood for instead):"; echo "$issues"; }
  [ -z "$dates" ] || { echo "a date (the commit message carries it):"; echo "$dates"; }
  exit 1
fi
echo "${#files[@]} files without issue numbers or dates"
