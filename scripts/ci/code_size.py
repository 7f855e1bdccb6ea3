#!/usr/bin/env python3
"""The workspace's size limits (issue 21): no Rust file over 700 lines and at
most 3 functions over 100 lines (from the `fn` line to its closing brace).

    python3 scripts/ci/code_size.py [--max-file 700] [--max-fn 100] [--allowed 3]

Prints every file and function over the limits and exits 1 when a limit is
broken. Braces inside strings, characters and comments are skipped; raw
strings (r"...", r#"..."#) are skipped as strings.
"""

import argparse
import re
import sys
from pathlib import Path

ROOTS = ["crates", "src", "tests", "examples", "benches", "fuzz/fuzz_targets"]
FN = re.compile(r"^\s*(pub(\([^)]*\))?\s+)?(const\s+)?(async\s+)?(unsafe\s+)?(extern\s+\"[^\"]*\"\s+)?fn\s+(\w+)")


def code_only(text):
    """`text` with strings, characters and comments blanked (newlines kept)."""
    out = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            i = j
            continue
        if text.startswith("/*", i):
            depth, j = 1, i + 2
            while j < n and depth:
                if text.startswith("/*", j):
                    depth, j = depth + 1, j + 2
                elif text.startswith("*/", j):
                    depth, j = depth - 1, j + 2
                else:
                    j += 1
            out.append("\n" * text.count("\n", i, j))
            i = j
            continue
        raw = re.match(r'(b?r)(#*)"', text[i:])
        if raw and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            end = '"' + raw.group(2)
            j = text.find(end, i + len(raw.group(0)))
            j = n if j < 0 else j + len(end)
            out.append("\n" * text.count("\n", i, j))
            i = j
            continue
        if c == '"':
            j = i + 1
            while j < n and text[j] != '"':
                j += 2 if text[j] == "\\" else 1
            out.append("\n" * text.count("\n", i, j + 1))
            i = j + 1
            continue
        if c == "'":
            # A character literal, not a lifetime: 'x', '\n', '\u{..}'.
            m = re.match(r"'(\\.[^']*|[^'\\])'", text[i:])
            if m:
                i += len(m.group(0))
                continue
        out.append(c)
        i += 1
    return "".join(out)


def functions(path):
    """(name, first line, lines) of every function with a body in `path`."""
    lines = code_only(path.read_text(encoding="utf-8")).split("\n")
    found = []
    for start, line in enumerate(lines):
        match = FN.match(line)
        if not match:
            continue
        depth, opened = 0, False
        for end in range(start, len(lines)):
            for ch in lines[end]:
                if ch == "{":
                    depth, opened = depth + 1, True
                elif ch == "}":
                    depth -= 1
                elif ch == ";" and not opened and depth == 0:
                    break  # a declaration without a body
            else:
                if opened and depth == 0:
                    found.append((match.group(7), start + 1, end - start + 1))
                    break
                continue
            break
    return found


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--max-file", type=int, default=700)
    parser.add_argument("--max-fn", type=int, default=100)
    parser.add_argument("--allowed", type=int, default=3)
    args = parser.parse_args()
    root = Path(__file__).resolve().parents[2]
    files = sorted(
        path
        for folder in ROOTS
        for path in (root / folder).rglob("*.rs")
        if "target" not in path.relative_to(root).parts
    )
    long_files = []
    long_fns = []
    for path in files:
        count = path.read_text(encoding="utf-8").count("\n")
        name = path.relative_to(root)
        if count > args.max_file:
            long_files.append((name, count))
        long_fns += [
            (name, fn, line, length)
            for fn, line, length in functions(path)
            if length > args.max_fn
        ]
    for name, count in long_files:
        print(f"file over {args.max_file} lines: {name} ({count})")
    for name, fn, line, length in long_fns:
        print(f"function over {args.max_fn} lines: {name}:{line} {fn} ({length})")
    print(
        f"{len(files)} files: {len(long_files)} over {args.max_file} lines, "
        f"{len(long_fns)} functions over {args.max_fn} lines (at most {args.allowed})"
    )
    return 1 if long_files or len(long_fns) > args.allowed else 0


if __name__ == "__main__":
    sys.exit(main())
