#!/usr/bin/env python3
"""No function in common/design over 60 lines (issue 23: a newcomer reads a function at once).

    python3 tests/layout/function_length.py [--limit N] [--show] [DIR...]

A function is a brace block opened right after a parameter list (`)`, possibly followed by
const, override, noexcept, a trailing return type or a constructor's initializer list) outside
any other function; its length is the lines from its signature's first line to its closing
brace, as a reader scrolls them. Lambdas and local classes inside a function count as part of
it. Comments and string literals are skipped when matching braces. Exit 1 and a line per
function over the limit; --show lists the longest ten either way.
"""

import argparse
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
CONTROL = {"if", "for", "while", "switch", "catch"}


def code_only(text):
    """`text` with comments and string/char literals blanked (newlines kept)."""
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif text.startswith('R"', i):
            m = re.match(r'R"([^(]*)\(', text[i:])
            end = text.find(")" + m.group(1) + '"', i) if m else -1
            j = n if end < 0 else end + len(m.group(1)) + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            out.append(" " * (j + 1 - i))
            i = j + 1
        else:
            out.append(c)
            i += 1
    return "".join(out)


def opens_function(before):
    """Whether a block whose opening brace follows `before` is a function body."""
    head = before.rstrip()
    # A constructor's initializer list: `) : a_(x), b_(y) {`: judge by the `)` before the `:`.
    head = re.sub(r"\)\s*:\s*[\w:<>,\s(){}.&*\[\]+-]*\)$", ")", head)
    head = re.sub(r"(\s*(const|override|final|noexcept|mutable))+$", "", head)
    head = re.sub(r"\s*->\s*[\w:<>,\s&*]+$", "", head)
    if not head.endswith(")"):
        return False
    depth, i = 0, len(head) - 1
    while i >= 0:  # back to the matching '('
        depth += head[i] == ")"
        depth -= head[i] == "("
        if depth == 0:
            break
        i -= 1
    word = re.search(r"(\w+)\s*$", head[:i])
    return not (word and word.group(1) in CONTROL)


def functions(path):
    """(name, first line, last line) of each function defined in `path`."""
    text = code_only(path.read_text())
    found, stack, last_end = [], [], 0
    for i, c in enumerate(text):
        if c in ";}":
            if c == "}" and stack:
                kind, start, name = stack.pop()
                if kind == "function":
                    found.append((name, start, text.count("\n", 0, i) + 1))
            if not any(k == "function" for k, _, _ in stack):
                last_end = i + 1
        elif c == "{":
            inside = any(k == "function" for k, _, _ in stack)
            before = text[last_end:i]
            if not inside and opens_function(before):
                lead = len(before) - len(before.lstrip())
                start = text.count("\n", 0, last_end + lead) + 1
                name = re.findall(r"([~\w:]+)\s*\(", before)
                stack.append(("function", start, name[0] if name else "?"))
            else:
                stack.append(("block", 0, ""))
            if not inside:
                last_end = i + 1
    return found


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--limit", type=int, default=60)
    parser.add_argument("--show", action="store_true")
    parser.add_argument("dirs", nargs="*", default=["common/design"])
    args = parser.parse_args()
    rows = []
    for d in args.dirs:
        for path in sorted((ROOT / d).rglob("*")):
            if path.suffix in (".cc", ".h"):
                for name, first, last in functions(path):
                    rows.append((last - first + 1, f"{path.relative_to(ROOT)}:{first}", name))
    rows.sort(reverse=True)
    over = [r for r in rows if r[0] > args.limit]
    for lines, where, name in rows[:10] if args.show else over:
        print(f"{where}: {name}: {lines} lines" + (" (over %d)" % args.limit if lines > args.limit else ""))
    print(f"{len(rows)} functions in {', '.join(args.dirs)}; {len(over)} over {args.limit} lines")
    return 1 if over else 0


if __name__ == "__main__":
    sys.exit(main())
