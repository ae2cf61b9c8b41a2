#!/usr/bin/env python3
"""Fails when a class or struct declared in ui/**/*.h has more public member functions than the
limit (issue 31: no god objects in the editor). A line-based reader of the project's own style, not
a C++ parser: comments and string literals are dropped, template arguments removed, and a member
function is a declaration at the class's own brace depth, in a public section, whose first '('
comes before any '=' and names something other than the class (constructors, destructors and
'= delete' lines do not count). Prints one line per class over the limit: file:line: Class: N public
member functions (limit L).

    python3 scripts/check-ui-class-size.py <source tree> [--limit 30] [--list]
"""
import pathlib
import re
import sys

DECL = re.compile(r"^[^=(]*?(~?\b\w+|operator\s*\S+?)\s*\(")
CLASS = re.compile(r"^\s*(?:template\s*<[^>]*>\s*)?(class|struct)\s+(\w+)\b(?!\s*;)([^;]*)$")
ACCESS = re.compile(r"^\s*(public|private|protected)\s*:")


def strip(line):
    line = re.sub(r'"(?:\\.|[^"\\])*"', '""', line)
    line = re.sub(r"'(?:\\.|[^'\\])*'", "''", line)
    return line.split("//", 1)[0]


def without_templates(text):
    while True:
        shorter = re.sub(r"<[^<>()]*>", "", text)
        shorter = re.sub(r"<[^<>]*\([^<>]*\)[^<>]*>", "", shorter)  # std::function<void()>
        if shorter == text:
            return text
        text = shorter


def classes(path):
    """Yields (class name, line, public member function count) for each class of `path`."""
    depth = 0
    parens = 0
    stack = []  # [name, line, body depth, access, count]
    pending = None  # a class head whose '{' is still to come
    in_block_comment = False
    for number, raw in enumerate(path.read_text(errors="replace").splitlines(), 1):
        line = raw
        if in_block_comment:
            if "*/" not in line:
                continue
            line = line.split("*/", 1)[1]
            in_block_comment = False
        line = re.sub(r"/\*.*?\*/", "", line)
        if "/*" in line:
            line, in_block_comment = line.split("/*", 1)[0], True
        line = strip(line)
        if line.lstrip().startswith("#"):
            continue
        head = CLASS.match(line)
        if head and parens == 0 and not line.strip().startswith("enum"):
            pending = [head.group(2), number, depth + 1, "public" if head.group(1) == "struct" else "private", 0]
        elif stack and parens == 0 and depth == stack[-1][2]:
            current = stack[-1]
            access = ACCESS.match(line)
            if access:
                current[3] = access.group(1)
                line = line[access.end():]
            text = without_templates(line)
            match = DECL.match(text)
            if (current[3] == "public" and match and not text.lstrip().startswith(("using", "typedef", "friend", "return"))
                    and match.group(1).lstrip("~") != current[0] and "= delete" not in text):
                current[4] += 1
        for char in line:
            if char == "(":
                parens += 1
            elif char == ")":
                parens = max(0, parens - 1)
            elif char == "{":
                depth += 1
                if pending and depth == pending[2]:
                    stack.append(pending)
                    pending = None
            elif char == "}":
                if stack and depth == stack[-1][2]:
                    done = stack.pop()
                    yield done[0], done[1], done[4]
                depth -= 1
        if pending and line.rstrip().endswith(";"):
            pending = None  # a declaration, not a definition


def main(argv):
    root = pathlib.Path(argv[1])
    limit = int(argv[argv.index("--limit") + 1]) if "--limit" in argv else 30
    over = []
    for header in sorted((root / "ui").rglob("*.h")):
        for name, line, count in classes(header):
            where = f"{header.relative_to(root)}:{line}: {name}: {count} public member functions (limit {limit})"
            if "--list" in argv:
                print(where)
            if count > limit:
                over.append(where)
    for where in over:
        print(where)
    return 1 if over else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
