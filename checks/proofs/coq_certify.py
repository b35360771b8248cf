#!/usr/bin/env python3
"""Tries micromega certificates for the stored sentences a proof needs to be empty, and writes what it found.

Usage: coq_certify.py SOURCE_DIR [CLAIM...]   (with claims named: only tries theirs and prints, writes nothing)
For every quantifier-free reports/proofs/<claim>/<name>.smt2 whose stored answer is empty (Z3 unsat or QEPCAD B
FALSE), states it in Coq (smt2_to_coq.py) and runs coqc with `intros; nra`, then `psatz R 2`, then `psatz R 3`
(60 s each), stopping at the first that closes it. Rewrites reports/proofs/coq/Sentences.v with the certified
ones and the `sentences` of MANIFEST.json with every attempt; entries proved by hand elsewhere (a `file` other
than Sentences.v) are kept. Slow (minutes): run it by hand after sentences change, then commit what it wrote."""
import glob
import json
import os
import re
import subprocess
import sys
import tempfile
import time

TACTICS = ("nra", "psatz R 2", "psatz R 3")
HEADER = """(* Stored quantifier-free sentences that a proof needs to be empty (reports/proofs/<claim>/<name>.smt2), each
   stated as "for all reals the asserted formula fails" (checks/proofs/smt2_to_coq.py prints the statement from
   the stored sentence; coq_test.sh checks that each theorem here states exactly that) and closed by a
   Positivstellensatz certificate that the micromega tactics find and Coq's kernel checks. Written by
   checks/proofs/coq_certify.py; MANIFEST.json records every sentence tried, with the attempts that failed. *)
Require Import Reals Psatz Lra.
Open Scope R_scope.
"""


def stored_empty(base):
    z3 = base + ".z3.out"
    qe = base + ".qepcad.out"
    return (os.path.exists(z3) and "unsat" in open(z3).read().split()) or \
           (os.path.exists(qe) and "FALSE" in open(qe).read())


def attempt(statement, tactic, seconds=60):
    with tempfile.TemporaryDirectory() as work:
        path = os.path.join(work, "T.v")
        with open(path, "w") as f:
            f.write("Require Import Reals Psatz Lra.\nOpen Scope R_scope.\n%s\nProof. Timeout %d (intros; %s). Qed.\n"
                    % (statement, seconds, tactic))
        start = time.monotonic()
        run = subprocess.run(["coqc", "-q", path], cwd=work, capture_output=True, text=True, timeout=seconds + 30)
        took = round(time.monotonic() - start, 1)
    if run.returncode == 0:
        return {"tactic": tactic, "seconds": took, "outcome": "certificate found"}
    reason = re.search(r"Error:\s*(.*)", run.stdout + run.stderr)
    return {"tactic": tactic, "seconds": took,
            "outcome": (reason.group(1).replace("Tactic failure:", "").strip() if reason else "failed")}


def main(root, claims):
    here = os.path.dirname(os.path.abspath(__file__))
    manifest_path = os.path.join(root, "reports/proofs/coq/MANIFEST.json")
    manifest = json.load(open(manifest_path))
    kept = [s for s in manifest.get("sentences", []) if s.get("file") not in (None, "Sentences.v")]
    kept_keys = {(s["claim"], s["sentence"]) for s in kept}
    entries, proofs = [], []
    for path in sorted(glob.glob(os.path.join(root, "reports/proofs/*/*.smt2"))):
        claim, sentence = path.split(os.sep)[-2], os.path.basename(path)
        if (claims and claim not in claims) or (claim, sentence) in kept_keys or "QF_NRA" not in open(path).read():
            continue
        if not stored_empty(path[:-5]):
            continue
        theorem = re.sub(r"\W", "_", claim) + "__" + re.sub(r"\W", "_", sentence[:-5])
        statement = subprocess.check_output([sys.executable, os.path.join(here, "smt2_to_coq.py"), path, theorem],
                                            text=True).strip()
        entry = {"claim": claim, "sentence": sentence, "attempts": []}
        for tactic in TACTICS:
            entry["attempts"].append(attempt(statement, tactic))
            if entry["attempts"][-1]["outcome"] == "certificate found":
                entry.update(file="Sentences.v", theorem=theorem, status="certificate", tactic=tactic,
                             seconds=entry["attempts"][-1]["seconds"])
                proofs.append("(* %s/%s *)\n%s\nProof. intros; %s. Qed.\n" % (claim, sentence, statement, tactic))
                break
        else:
            entry["status"] = "no certificate"
        print(claim, sentence, entry["status"], flush=True)
        entries.append(entry)
    if claims:
        return
    with open(os.path.join(root, "reports/proofs/coq/Sentences.v"), "w") as f:
        f.write(HEADER + "\n" + "\n".join(proofs))
    manifest["sentences"] = entries + kept
    with open(manifest_path, "w") as f:
        json.dump(manifest, f, indent=2, ensure_ascii=False)
        f.write("\n")


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit("usage: coq_certify.py SOURCE_DIR [CLAIM...]")
    main(sys.argv[1], set(sys.argv[2:]))
