#!/usr/bin/env python3
"""No two types of the library share a fully qualified name (ctest -R unique_type_names).

Two definitions of shadowkit::X in different files break the one-definition rule silently:
the linker keeps one, and code compiled against the other reads it wrongly. Types at
namespace scope start at column 0 (the project's format); types in anonymous namespaces are
private to their file and not counted.
"""
import collections
import pathlib
import re
import sys

OPEN = re.compile(r"^namespace(?:\s+([\w:]+))?\s*\{")
CLOSE = re.compile(r"^\}\s*//\s*namespace")
TYPE = re.compile(r"^(?:template\s*<[^>]*>\s*)?(?:struct|class|union|enum(?:\s+class)?)\s+(\w+)(?!\w|::)"
                  r"(?:\s+final)?\s*(?::[^;]*)?\{")
ALIAS = re.compile(r"^using\s+(\w+)\s*=")


def definitions(text):
    """(qualified name, line) of every named type defined at namespace scope."""
    scopes = []
    for number, line in enumerate(text.splitlines(), 1):
        if match := OPEN.match(line):
            scopes.append(match.group(1))
        elif CLOSE.match(line) and scopes:
            scopes.pop()
        elif (match := TYPE.match(line) or ALIAS.match(line)) and None not in scopes:
            yield "::".join(scopes + [match.group(1)]), number


def main():
    root = pathlib.Path(__file__).resolve().parent.parent
    where = collections.defaultdict(list)
    for folder in ("include", "src", "fuzz"):
        for path in sorted((root / folder).rglob("*")):
            if path.suffix not in (".h", ".cpp"):
                continue
            for name, number in definitions(path.read_text(encoding="utf-8")):
                where[name].append(f"{path.relative_to(root)}:{number}")
    clashes = {name: places for name, places in where.items() if len(places) > 1}
    for name, places in sorted(clashes.items()):
        print(f"{name} is defined in {len(places)} places: {', '.join(places)}")
    print(f"{len(where)} types, {len(clashes)} defined more than once")
    return 1 if clashes else 0


if __name__ == "__main__":
    sys.exit(main())
