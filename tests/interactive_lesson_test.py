#!/usr/bin/env python3
"""`shadowlab lesson --interactive` in a browser: for each method, writes the page and loads it in
headless Chromium (Debian's `chromium`, WebGL by SwiftShader) with ?selftest, which clicks every
step button and writes, into <pre id="selftest">, the step each click showed, what each of its
canvases drew and the errors the page met (web/src/self_test.js). Asserts: the page is one file
that loads nothing from elsewhere; no error recorded by the page and nothing written to the console
(Chromium's log: errors, uncaught exceptions, warnings); one button per
step of the method's trace (`inspect --json`), in order; each click shows that step alone; each
step has a canvas and every canvas draws (at least 1 % of its pixels are not the background);
the first canvas draws a different picture at every step; What goes wrong follows the steps.
Needs an X display for `shadowlab lesson` (run ctest under xvfb-run)."""
import argparse
import concurrent.futures
import html
import json
import os
import re
import subprocess
import sys
import tempfile

MIN_DRAWN_SHARE = 0.01


def run(command, **kwargs):
    result = subprocess.run(command, capture_output=True, text=True, **kwargs)
    if result.returncode != 0:
        sys.exit(f"failed ({result.returncode}): {' '.join(command)}\n{result.stderr}")
    return result


def trace_step_ids(shadowlab, scene, method):
    inspected = json.loads(run([shadowlab, "inspect", scene, "--method", method, "--json"]).stdout)
    return [step["id"] for step in inspected["steps"]]


def outside_references(page):
    """src= and href= that do not point into the page itself (a data: URI or a fragment)."""
    return [link for link in re.findall(r'(?:src|href)="([^"]*)"', page) if not link.startswith(("data:", "#"))]


def self_test(chromium, page_file):
    result = subprocess.run(
        [chromium, "--headless", "--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
         "--enable-logging=stderr", "--v=0", "--virtual-time-budget=20000", "--dump-dom",
         f"file://{page_file}?selftest"],
        capture_output=True, text=True, timeout=120)
    found = re.search(r'<pre id="selftest"[^>]*>(.*?)</pre>', result.stdout, re.S)
    if not found or not found.group(1).strip():
        sys.exit(f"{page_file}: the page wrote no self-test results\n{result.stderr[-3000:]}")
    # The page writes nothing to the console: any line there (an error, an uncaught exception, a
    # warning of three.js) is a problem, wherever on the page it came from.
    console = [line for line in result.stderr.splitlines() if ":CONSOLE" in line]
    return json.loads(html.unescape(found.group(1))), console


def check(method, step_ids, results, console, page):
    problems = []
    if outside_references(page):
        problems.append(f"the page loads from elsewhere: {outside_references(page)[:3]}")
    if '<section id="what-goes-wrong">' not in page:
        problems.append("the page has no What goes wrong section")
    if results["errors"] or console:
        problems.append(f"errors: {results['errors']}; console: {console}")
    steps = results["steps"]
    buttons = [step["button"] for step in steps]
    if not step_ids or buttons != step_ids:
        problems.append(f"buttons {buttons} are not the trace's steps {step_ids}")
    for step in steps:
        if step["shown"] != [step["button"]]:
            problems.append(f"clicking {step['button']} showed {step['shown']}")
        if not step["canvases"]:
            problems.append(f"step {step['button']} has no canvas")
        for i, canvas in enumerate(step["canvases"]):
            if canvas["drawn"] < MIN_DRAWN_SHARE * canvas["pixels"]:
                problems.append(f"step {step['button']} canvas {i}: {canvas['drawn']} of {canvas['pixels']} pixels drawn")
    first_pictures = {step["canvases"][0]["hash"] for step in steps if step["canvases"]}
    if len(first_pictures) != len(steps):
        problems.append(f"{len(steps)} steps drew {len(first_pictures)} different first pictures")
    drawn = [canvas["drawn"] for step in steps for canvas in step["canvases"]]
    print(f"{method}: {len(steps)} steps, {len(drawn)} canvases, {min(drawn, default=0)} to "
          f"{max(drawn, default=0)} pixels drawn, page {len(page) // 1024} KiB")
    return [f"{method}: {p}" for p in problems]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--shadowlab", required=True)
    parser.add_argument("--scene", required=True)
    parser.add_argument("--chromium", default="chromium")
    parser.add_argument("--methods", nargs="+", default=["lispsm", "xpsm"])
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as work:
        def lesson_in_browser(method):
            out = os.path.join(work, method)
            run([args.shadowlab, "lesson", args.scene, "--method", method, "--interactive", "--size", "320x200",
                 "--out", out])
            page_file = os.path.join(out, "index.html")
            with open(page_file, encoding="utf-8") as f:
                page = f.read()
            results, console = self_test(args.chromium, page_file)
            return check(method, trace_step_ids(args.shadowlab, args.scene, method), results, console, page)

        # The methods side by side: each waits mostly on one browser process.
        with concurrent.futures.ThreadPoolExecutor() as pool:
            problems = [p for found in pool.map(lesson_in_browser, args.methods) for p in found]
    for p in problems:
        print(p)
    print(f"{len(args.methods) - len({p.split(':')[0] for p in problems})} passed, "
          f"{len({p.split(':')[0] for p in problems})} failed")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
