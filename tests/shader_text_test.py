#!/usr/bin/env python3
"""The shader-text check (scripts/check_shader_text.py) fails on a raw string of 21 lines in a
viewer file, naming it, and passes one of 20 lines: it can fail."""
import pathlib
import subprocess
import sys
import tempfile

CHECK = pathlib.Path(__file__).resolve().parent.parent / "scripts" / "check_shader_text.py"


def run_on(lines):
    with tempfile.TemporaryDirectory() as root:
        (pathlib.Path(root) / "core").mkdir()
        (pathlib.Path(root) / "viewer" / "render").mkdir(parents=True)
        body = "\n".join(f"float f{i};" for i in range(lines))
        (pathlib.Path(root) / "viewer" / "render" / "pass.cpp").write_text(f'const char* k = R"({body})";\n')
        return subprocess.run([sys.executable, str(CHECK), "--root", root], capture_output=True, text=True)


too_long, at_limit = run_on(21), run_on(20)
failures = []
if too_long.returncode == 0 or "viewer/render/pass.cpp:1: a raw string of 21 lines" not in too_long.stdout:
    failures.append(f"21 lines went unreported: {too_long.stdout!r}")
if at_limit.returncode != 0:
    failures.append(f"20 lines were refused: {at_limit.stdout!r}")
print("\n".join(failures) or "the check fails at 21 lines and passes at 20")
sys.exit(1 if failures else 0)
