#!/usr/bin/env python3
"""Fails, naming the file and the line, on a raw string literal of more than 20 lines in a C++ file
of viewer/ or core/: shader code lives in viewer/render/glsl/*.glsl, one file per concept, embedded
by the build (docs/ARCHITECTURE.md). `--root DIR` checks another tree (the test of this check)."""
import argparse
import pathlib
import re
import sys

MAX_LINES = 20
RAW_STRING = re.compile(r'R"([^()\\ ]{0,16})\((.*?)\)\1"', re.S)


def long_raw_strings(root):
    for folder in ("viewer", "core"):
        for path in sorted((root / folder).rglob("*.[ch]pp")):
            text = path.read_text(encoding="utf-8", errors="replace")
            for match in RAW_STRING.finditer(text):
                lines = match.group(2).count("\n") + 1
                if lines > MAX_LINES:
                    line = text.count("\n", 0, match.start()) + 1
                    yield f"{path.relative_to(root)}:{line}: a raw string of {lines} lines (at most {MAX_LINES}): " \
                          "put shader code in viewer/render/glsl/<concept>.glsl"


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--root", type=pathlib.Path, default=pathlib.Path(__file__).resolve().parent.parent)
    found = list(long_raw_strings(parser.parse_args().root))
    for problem in found:
        print(problem)
    if not found:
        print(f"no raw string of more than {MAX_LINES} lines in viewer/ or core/")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
