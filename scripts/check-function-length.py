#!/usr/bin/env python3
"""Fails when a C++ function of the project is longer than LIMIT lines (its signature to its
closing brace): long functions are split at their own headings into named steps
(docs/architecture.md).

A function is found as its outermost body: a brace whose preceding text ends in a parameter list
(with qualifiers, a trailing return type or a constructor's initialisers), at namespace or class
level, not a control statement's. Lambdas and local classes count as part of the function they
are in. Generated code (the build trees) is not looked at.

Usage: check-function-length.py [--root DIR] [--limit N]
"""

import re
import sys
from pathlib import Path

LIMIT = 100
SKIPPED = ("build", ".git")
SUFFIXES = (".cpp", ".hpp")
NOT_A_FUNCTION = re.compile(r"\b(if|for|while|switch|catch|do|else|try|namespace|class|struct|"
                            r"union|enum)\b[^)]*$|=\s*$|\breturn\b")
STRING = re.compile(r'R"(\w*)\((?:.|\n)*?\)\1"|"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])*\'')
COMMENT = re.compile(r"//[^\n]*|/\*(?:.|\n)*?\*/")


def blanked(text):
    """`text` with comments and literals replaced by spaces, newlines kept (so lines count)."""
    def keep_lines(match):
        return re.sub(r"[^\n]", " ", match.group(0))
    pattern = re.compile(f"{COMMENT.pattern}|{STRING.pattern}")
    return pattern.sub(keep_lines, text)


def functions(text):
    """(name, first line, line count) of each outermost function body in `text`."""
    code = blanked(text)
    found = []
    # What each open brace is: "scope" (namespace, class...), "function", or "inner" (a brace
    # inside a function: a block, a lambda, a local class).
    stack = []
    head_start = 0  # where the text before the next brace began
    function_start = None
    line = 1
    head_line = 1
    for i, c in enumerate(code):
        if c == "\n":
            line += 1
            continue
        if c == ";" and "function" not in stack:
            head_start, head_line = i + 1, line
        elif c == "{":
            if "function" in stack:
                stack.append("inner")
            else:
                head = code[head_start:i].strip()
                is_function = bool(re.search(r"\)[\w\s:&*<>,()\[\]\-]*$", head)) and \
                    not NOT_A_FUNCTION.search(head.split("(")[0] + "(") and \
                    not re.match(r"^(namespace|class|struct|enum|union|extern)\b", head)
                if is_function:
                    stack.append("function")
                    function_start = (name_of(head),
                                      head_line + leading_newlines(code[head_start:i]))
                else:
                    stack.append("scope")
                head_start, head_line = i + 1, line
        elif c == "}":
            kind = stack.pop() if stack else "scope"
            if kind == "function":
                name, first = function_start
                found.append((name, first, line - first + 1))
            if "function" not in stack:
                head_start, head_line = i + 1, line
    return found


def name_of(head):
    """The first name followed by a parameter list outside any brackets: the function's."""
    depth = 0
    for match in re.finditer(r"[\w:~]+(?=\s*\()|[()<>]", head):
        token = match.group(0)
        if token in "(<":
            depth += 1
        elif token in ")>":
            depth -= 1
        elif depth == 0:
            return token
    return "?"


def leading_newlines(text):
    stripped = text.lstrip()
    return text[:len(text) - len(stripped)].count("\n")


def main():
    root = Path(__file__).resolve().parent.parent
    limit = LIMIT
    if "--root" in sys.argv:
        root = Path(sys.argv[sys.argv.index("--root") + 1]).resolve()
    if "--limit" in sys.argv:
        limit = int(sys.argv[sys.argv.index("--limit") + 1])
    problems = []
    for path in sorted(root.rglob("*")):
        rel = path.relative_to(root)
        if path.suffix not in SUFFIXES or any(p.startswith(SKIPPED) for p in rel.parts):
            continue
        for name, first, count in functions(path.read_text(errors="replace")):
            if count > limit:
                problems.append(f"{rel}:{first}: {name} is {count} lines (at most {limit})")
    for p in problems:
        print(p)
    if problems:
        print(f"functions: {len(problems)} longer than {limit} lines")
        return 1
    print(f"functions: none longer than {limit} lines")
    return 0


if __name__ == "__main__":
    sys.exit(main())
