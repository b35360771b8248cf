#!/usr/bin/env python3
"""Fails when a C++ function under the given folders is longer than the limit (60 lines by default), printing
file:line, its name and its length; a function that does one job reads in one screen (the project's standard).

A function's length runs from the first line of its signature to its closing brace. The scan strips comments,
string and character literals and preprocessor lines, then follows the braces: at namespace or class level a
brace whose head (the text since the last ';', '{' or '}') ends in a parameter list, with optional qualifiers or a
trailing return type, opens a function body (a lambda assigned at namespace scope is one too), which is measured
as a whole, lambdas and local classes included; any other brace (a namespace, a class, an initialiser) is entered.

Usage: function_length_test.py [--max N] SOURCE_DIR FOLDER...   (folders relative to SOURCE_DIR)
"""
import argparse
import pathlib
import re
import sys

HEAD_IS_FUNCTION = re.compile(
    r"\)\s*(?:const\b|noexcept\b(?:\s*\([^()]*\))?|override\b|final\b|mutable\b|&&|&|\s)*(?:->[^;{}]*)?$")
NAME = re.compile(r"([~\w:]+(?:<[^()]*>)?|operator\s*[^\s(]+)\s*\($")


def blank_out(text):
    """`text` with comments, literals and preprocessor lines replaced by spaces, newlines kept."""
    out = []
    i, n = 0, len(text)
    at_line_start = True
    while i < n:
        c = text[i]
        if at_line_start and c == "#":  # a preprocessor line, with its continuations
            while i < n and text[i] != "\n":
                i += 2 if text[i] == "\\" and i + 1 < n else 1
                out.append(" ")
            continue
        if text.startswith("//", i):
            while i < n and text[i] != "\n":
                out.append(" ")
                i += 1
            continue
        if text.startswith("/*", i):
            end = text.find("*/", i + 2)
            end = n if end < 0 else end + 2
            out.extend(ch if ch == "\n" else " " for ch in text[i:end])
            i = end
            continue
        raw = re.match(r'R"([^(\s]*)\(', text[i:i + 20])
        if raw and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            end = text.find(")" + raw.group(1) + '"', i)
            end = n if end < 0 else end + len(raw.group(1)) + 2
            out.extend(ch if ch == "\n" else " " for ch in text[i:end])
            i = end
            continue
        if c in "\"'" and not (c == "'" and i > 0 and text[i - 1].isalnum()):  # 1'000 is a digit separator
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            out.append(c)
            out.extend(" " for _ in range(i + 1, min(j, n)))
            out.append(c if j < n else "")
            i = j + 1
            continue
        out.append(c)
        at_line_start = c == "\n" or (at_line_start and c in " \t")
        i += 1
    return "".join(out)


def long_functions(path, limit):
    """(line, name, length) of each function of `path` longer than `limit` lines."""
    code = blank_out(path.read_text(encoding="utf-8"))
    line_of = [0] * (len(code) + 1)
    line = 1
    for k, ch in enumerate(code):
        line_of[k] = line
        line += ch == "\n"
    found = []
    head_start = 0
    i = 0
    while i < len(code):
        ch = code[i]
        if ch in ";}":
            head_start = i + 1
        elif ch == "{":
            head = code[head_start:i].strip()
            if HEAD_IS_FUNCTION.search(head):
                depth, j = 0, i
                while j < len(code):
                    depth += (code[j] == "{") - (code[j] == "}")
                    if depth == 0:
                        break
                    j += 1
                first = head_start + len(code[head_start:i]) - len(code[head_start:i].lstrip())
                length = line_of[min(j, len(code) - 1)] - line_of[first] + 1
                name = NAME.search(head[: head.rfind(")")].rsplit("(", 1)[0] + "(") if "(" in head else None
                if length > limit:
                    found.append((line_of[first], name.group(1) if name else head.split("\n")[0][:40], length))
                i = j
            head_start = i + 1
        i += 1
    return found


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--max", type=int, default=60, help="the longest a function may be, in lines")
    parser.add_argument("source_dir", type=pathlib.Path)
    parser.add_argument("folders", nargs="+")
    args = parser.parse_args()
    failures = checked = 0
    for folder in args.folders:
        root = args.source_dir / folder
        if not root.is_dir():
            print(f"{root}: no such folder", file=sys.stderr)
            return 2
        for path in sorted(p for p in root.rglob("*") if p.suffix in (".cpp", ".hpp", ".h")):
            checked += 1
            for line, name, length in long_functions(path, args.max):
                print(f"{path.relative_to(args.source_dir)}:{line}: {name} is {length} lines (at most {args.max})")
                failures += 1
    print(f"{checked} files under {', '.join(args.folders)}: {failures} functions over {args.max} lines")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
