#!/usr/bin/env python3
"""The Coq statement of a stored sentence (reports/proofs/<claim>/<name>.smt2): "the set is empty", i.e. for
all reals the asserted formula fails (its inner quantifiers over the reals kept). Usage: smt2_to_coq.py <file.smt2> <theorem name>.
The statement is printed on one line, so that coq_test.sh can check that a Coq file states exactly it."""
import re
import sys


def tokens(text):
    text = re.sub(r";[^\n]*", " ", text)
    return re.findall(r"\(|\)|[^\s()]+", text)


def parse(toks):
    """The s-expressions of the token list, as nested lists."""
    stack, out = [], []
    for t in toks:
        if t == "(":
            stack.append(out)
            out = []
        elif t == ")":
            done, out = out, stack.pop()
            out.append(done)
        else:
            out.append(t)
    return out


def term(e):
    if isinstance(e, str):
        if re.fullmatch(r"\d+(\.\d+)?", e):
            return e if "." not in e else "(%s)" % e
        return e
    op, args = e[0], [term(a) for a in e[1:]]
    if op == "+":
        return "(" + " + ".join(args) + ")"
    if op == "*":
        return "(" + " * ".join(args) + ")"
    if op == "/":
        return "(" + " / ".join(args) + ")"
    if op == "-":
        return "(- " + args[0] + ")" if len(args) == 1 else "(" + " - ".join(args) + ")"
    raise ValueError("unsupported term " + op)


def formula(e):
    op, args = e[0], e[1:]
    if op in ("and", "or"):
        return "(" + (" /\\ " if op == "and" else " \\/ ").join(formula(a) for a in args) + ")"
    if op in ("forall", "exists"):
        names = " ".join(b[0] for b in args[0])
        return "(%s %s : R, %s)" % (op, names, formula(args[1]))
    if op == "not":
        return "(~ " + formula(args[0]) + ")"
    if op in ("<", "<=", ">", ">=", "="):
        return "(%s %s %s)" % (term(args[0]), op, term(args[1]))
    raise ValueError("unsupported formula " + op)


def main(path, name):
    exprs = parse(tokens(open(path).read()))
    logic = [e[1] for e in exprs if e[0] == "set-logic"]
    if logic not in (["QF_NRA"], ["NRA"]):
        sys.exit("%s: not a sentence over the reals (%s)" % (path, logic))
    names = [e[1] for e in exprs if e[0] == "declare-const"]
    body = [formula(e[1]) for e in exprs if e[0] == "assert"]
    print("Theorem %s : forall %s : R, ~ (%s)." % (name, " ".join(names), " /\\ ".join(body)))


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: smt2_to_coq.py <file.smt2> <theorem name>")
    try:
        main(sys.argv[1], sys.argv[2])
    except (OSError, ValueError, IndexError) as err:
        sys.exit("smt2_to_coq.py: %s" % err)
