#!/usr/bin/env bash
# The lemmas' Coq proofs (reports/proofs/coq/) compiled by coqc, whose kernel checks every proof term.
# Usage: coq_test.sh <source root>. Compiles a copy in a temporary folder (the tree stays clean), refuses an
# unfinished or assumed proof (Admitted, admit, Axiom, Parameter, Hypothesis, Conjecture), and prints
# `Print Assumptions` for every theorem MANIFEST.json lists, failing on any assumption
# outside Coq's standard Reals library and the classical logic and functional extensionality it rests on.
# Exits 77 (skipped) only when coqc is absent.
set -euo pipefail
root=${1:?usage: coq_test.sh <source root>}
src=$(cd "$root/reports/proofs/coq" && pwd)
command -v coqc >/dev/null || { echo "coqc not found: skipped"; exit 77; }
[ -f "$src/_CoqProject" ] || { echo "no $src/_CoqProject"; exit 1; }

# Every .v file of the folder is in _CoqProject, so none escapes the compile.
for f in "$src"/*.v; do
  grep -qx "$(basename "$f")" "$src/_CoqProject" || { echo "$(basename "$f") is not in _CoqProject"; exit 1; }
done
if grep -nwE 'Admitted|admit|Axiom|Axioms|Parameter|Parameters|Hypothesis|Hypotheses|Conjecture' "$src"/*.v; then
  echo "an unfinished proof or an assumed statement (above)"; exit 1
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# Each sentence with a certificate is stated in Coq exactly as smt2_to_coq.py reads the stored sentence.
python3 - "$src/MANIFEST.json" >"$work/sentences.tsv" <<'PY'
import json, sys
for s in json.load(open(sys.argv[1])).get("sentences", []):
    if s["status"] == "certificate":
        print("\t".join((s["claim"], s["sentence"], s["file"], s["theorem"])))
PY
while IFS=$'\t' read -r claim sentence file theorem; do
  stmt=$(python3 "$root/checks/proofs/smt2_to_coq.py" "$root/reports/proofs/$claim/$sentence" "$theorem")
  grep -qxF "$stmt" "$src/$file" || { echo "$file does not state $claim/$sentence as $theorem"; exit 1; }
done <"$work/sentences.tsv"
echo "$(wc -l <"$work/sentences.tsv") sentences' Coq statements match the stored sentences"

cp "$src"/_CoqProject "$src"/*.v "$work"/
cd "$work"
start=$(date +%s)
coq_makefile -f _CoqProject -o Makefile >/dev/null
make -s -j2 >make.log 2>&1 || { cat make.log; echo "coqc failed"; exit 1; }
echo "compiled $(ls *.v | wc -l) files in $(( $(date +%s) - start )) s"

# Per lemma, the theorems the manifest lists (all of a kernel-checked lemma, the checked parts of one not yet),
# bundled in one tuple; one `Print Assumptions` covers every lemma's bundle (each walk of the Reals library costs
# about 0.6 s, so one per lemma would cost seconds per lemma); with "per-lemma" one is printed per lemma, which
# the test does when an assumption falls outside the allowed ones, to name the lemma.
cat >gen_assumptions.py <<'PY'
import json, sys
per_lemma = len(sys.argv) > 2 and sys.argv[2] == "per-lemma"
lemmas = [l for l in json.load(open(sys.argv[1]))["lemmas"] if l.get("file")]
for lemma in lemmas:
    print("Require Affinterp.%s." % lemma["file"][:-2])
for lemma in lemmas:
    names = ["Affinterp.%s.%s" % (lemma["file"][:-2], t) for t in lemma["theorems"]]
    print('Definition %s_theorems := (%s).' % (lemma["id"], ", ".join(names)) if len(names) > 1 else
          'Definition %s_theorems := %s.' % (lemma["id"], names[0]))
    print('Goal True. idtac "== %s: %s". Abort.' % (lemma["id"], " ".join(lemma["theorems"])))
    if per_lemma:
        print("Print Assumptions %s_theorems." % lemma["id"])
if lemmas and not per_lemma:
    print("Definition lemmas := (%s)." % ", ".join("%s_theorems" % l["id"] for l in lemmas))
    print('Goal True. idtac "== the lemmas above". Abort.')
    print("Print Assumptions lemmas.")
sentences = [s for s in json.load(open(sys.argv[1])).get("sentences", []) if s["status"] == "certificate"]
if sentences:
    for f in sorted({s["file"][:-2] for s in sentences}):
        print("Require Affinterp.%s." % f)
    print("Definition sentences := (%s)." % ", ".join(
        "Affinterp.%s.%s" % (s["file"][:-2], s["theorem"]) for s in sentences))
    print('Goal True. idtac "== the %d sentences with a certificate". Abort.' % len(sentences))
    print("Print Assumptions sentences.")
manifest = json.load(open(sys.argv[1]))
claims = manifest.get("claims", []) + manifest.get("encodings", [])
if claims:
    for f in sorted({c["file"][:-2] for c in claims}):
        print("Require Affinterp.%s." % f)
    print("Definition claims := (%s)." % ", ".join(
        "Affinterp.%s.%s" % (c["file"][:-2], c["theorem"]) for c in claims))
    print('Goal True. idtac "== the claims and encodings %s". Abort.' % ", ".join(c.get("claim", c.get("encoding")) for c in claims))
    print("Print Assumptions claims.")
PY
python3 gen_assumptions.py "$src/MANIFEST.json" >Assumptions.v
grep -q '^Print Assumptions' Assumptions.v || { echo "MANIFEST.json lists no theorem"; exit 1; }
coqc -q -w -all -R . Affinterp Assumptions.v >assumptions.log 2>&1 || { cat assumptions.log; exit 1; }
cat assumptions.log
# Each assumption's name starts a line; the types continue indented.
allowed='ClassicalDedekindReals.sig_not_dec ClassicalDedekindReals.sig_forall_dec
FunctionalExtensionality.functional_extensionality_dep Classical_Prop.classic'
bad=$(awk '/^[^ \t]/ && !/^(== |Axioms:|Closed under the global context)/ {print $1}' assumptions.log |
      sort -u | grep -vxF -f <(tr ' ' '\n' <<<"$allowed") || true)
if [ -n "$bad" ]; then
  python3 gen_assumptions.py "$src/MANIFEST.json" per-lemma >Assumptions.v
  coqc -q -w -all -R . Affinterp Assumptions.v 2>&1 || true
  echo "assumptions outside the standard library's Reals axioms: $bad (per lemma above)"; exit 1
fi
echo "every listed theorem's assumptions within the standard Reals axioms"
