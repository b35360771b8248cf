#!/usr/bin/env bash
# The layers of the project (README.md, "Layout"), from the bottom: each folder may include only the
# folders listed for it; a project include anywhere else fails this test, naming the file and the line.
# Usage: layers_test.sh SOURCE_DIR
set -euo pipefail
cd "$1"

# folder: the folders its files may include ("theory" alone for theory/ except that only theory/origin may
# include theory/origin, only theory/certified theory/certified: the components on GiNaC and Arb).
declare -A allowed=(
  [theory]="theory"
  [plots]="theory plots"
  [experiments/support]="experiments/support"
  [experiments/inputs]="theory experiments/support experiments/inputs"
  [experiments/bench]="experiments/support experiments/bench"
  [experiments/proofs]="theory experiments/support experiments/proofs"
  [experiments/claims]="theory plots experiments/support experiments/inputs experiments/bench experiments/proofs experiments/claims"
  [experiments/measurements]="theory plots experiments/support experiments/bench experiments/claims experiments/measurements"
  [reports]="experiments/support experiments/measurements reports"
  [experiments/python]="theory experiments/support experiments/inputs experiments/proofs experiments/python"
  [experiments/apps]="theory reports plots experiments/support experiments/inputs experiments/bench experiments/proofs experiments/claims experiments/measurements experiments/apps"
)

failures=0
for folder in "${!allowed[@]}"; do
  while IFS=: read -r file line include; do
    target=$(sed -E 's/.*#include "([^"]+)".*/\1/' <<<"$include")
    ok=0
    for prefix in ${allowed[$folder]}; do
      [[ $target == "$prefix"/* ]] && ok=1
    done
    if [[ $target == theory/origin/* && $file != theory/origin/* && $folder == theory ]]; then
      ok=0  # affinterp::theory must build without GiNaC
    fi
    if [[ $target == theory/certified/* && $file != theory/certified/* && $folder == theory ]]; then
      ok=0  # affinterp::theory must build without Arb
    fi
    if ((!ok)); then
      echo "$file:$line: includes $target, above its layer ($folder may include: ${allowed[$folder]})"
      failures=$((failures + 1))
    fi
  done < <(grep -rnE '^\s*#\s*include "' "$folder" --include='*.hpp' --include='*.cpp' || true)
done
if ((failures)); then
  echo "$failures include(s) point up a layer"
  exit 1
fi
echo "every include points down or sideways within its layer"
