"""The Python module against the CLI: docs/python_example.py's numbers equal `shadowlab measure
--json`'s, its Camera view equals `shadowlab render`'s PNG, the per-pixel arrays agree with the
numbers, and errors carry the CLI's one-line messages.

    python_example_test.py --cli build/app/shadowlab --example docs/python_example.py --scene S
(with the package on PYTHONPATH and an X display)."""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile

import numpy as np

import shadowlab

METHOD, RESOLUTION, SIZE = "lispsm", 512, "320x180"
#: Wall times: they differ from run to run.
TIMINGS = {"setup_ms", "raster_ms", "prefilter_ms", "lookup_ms", "lookup_ns_per_pixel"}


def differences(a, b, where=""):
    """Where two JSON values differ, timings aside."""
    if isinstance(a, dict) and isinstance(b, dict):
        if a.keys() != b.keys():
            return [f"{where}: keys {sorted(a.keys() ^ b.keys())}"]
        return [d for key in a if key not in TIMINGS for d in differences(a[key], b[key], f"{where}.{key}")]
    if isinstance(a, list) and isinstance(b, list) and len(a) == len(b):
        return [d for i, (x, y) in enumerate(zip(a, b)) for d in differences(x, y, f"{where}[{i}]")]
    return [] if a == b else [f"{where}: {a!r} != {b!r}"]


def cli(o, *args):
    """stdout of the CLI; its stderr's last line on failure."""
    done = subprocess.run([o.cli, *args], capture_output=True, text=True)
    return done.returncode, done.stdout, done.stderr.strip().splitlines()[-1] if done.stderr.strip() else ""


def check_example_against_cli(o, tmp):
    numbers_file, image_file, png = (os.path.join(tmp, n) for n in ("numbers.json", "camera.npy", "camera.png"))
    subprocess.run([sys.executable, o.example, o.scene, "--method", METHOD, "--resolution", str(RESOLUTION),
                    "--size", SIZE, "--json", numbers_file, "--render", image_file], check=True)
    code, out, err = cli(o, "measure", o.scene, "--method", METHOD, "--resolution", str(RESOLUTION), "--size", SIZE,
                         "--json")
    assert code == 0, err
    expected = json.loads(out)
    with open(numbers_file) as f:
        numbers = json.load(f)
    assert numbers["receiver_pixels"] > 0 and numbers["diagnosis"]["causes"], "nothing measured"
    problems = differences(numbers, expected)
    assert not problems, "the example's numbers differ from measure --json's:\n" + "\n".join(problems)

    code, _, err = cli(o, "render", o.scene, "--method", METHOD, "--view", "camera", "--size", SIZE, "--resolution",
                       str(RESOLUTION), "--out", png)
    assert code == 0, err
    image, expected_image = np.load(image_file), shadowlab.read_png(png)
    assert image.shape == expected_image.shape, (image.shape, expected_image.shape)
    assert image.std() > 10, "the Camera view is flat"
    assert np.array_equal(image, expected_image), f"{(image != expected_image).any(axis=2).sum()} pixels differ"
    print(f"example = measure --json ({len(numbers)} keys), render = the CLI's PNG {image.shape}")


def check_arrays_against_numbers(o):
    scene = shadowlab.load_scene(o.scene)
    width, height = (int(n) for n in SIZE.split("x"))
    run = shadowlab.measure(scene, METHOD, resolution=RESOLUTION, size=(width, height), diagnose=False)
    n, a = run.numbers, run.arrays
    assert a["verdicts"].shape == tuple(reversed(n["image"])), (a["verdicts"].shape, n["image"])
    receivers = a["verdicts"] != shadowlab.VERDICTS.index("none")
    assert receivers.sum() == n["receiver_pixels"] > 0
    for verdict in ("false_shadow", "false_light"):
        share = (a["verdicts"] == shadowlab.VERDICTS.index(verdict)).sum() / receivers.sum()
        assert math.isclose(share, n[verdict], rel_tol=1e-12), (verdict, share, n[verdict])
    wrong = np.isin(a["verdicts"], [shadowlab.VERDICTS.index("false_shadow"), shadowlab.VERDICTS.index("false_light")])
    assert wrong.any(), "no misclassified pixel: the causes go unchecked"
    assert np.array_equal(a["causes"] != 0, wrong), "a cause where no pixel is wrong, or none where one is"
    assert math.isclose(a["m"].max(), n["m"]["max"], rel_tol=1e-6), (a["m"].max(), n["m"]["max"])
    measured = a["m"] > 0
    assert np.allclose(a["m_perspective"][measured] * a["m_projection"][measured], a["m"][measured], rtol=1e-5)
    assert (a["lit"] <= a["visible"]).all() and a["lit"].any() and (a["visible"] & ~a["lit"]).any()
    setup = shadowlab.compute(scene, METHOD, resolution=RESOLUTION)
    assert setup.maps and setup.maps[0]["world_to_uvz"].shape == (4, 4)
    assert setup.depth.shape == (RESOLUTION, RESOLUTION) and 0.0 < (setup.depth < 1.0).mean() < 1.0
    assert any(isinstance(v, np.ndarray) for step in setup.steps for v in step["values"].values())
    print(f"arrays agree with the numbers: {receivers.sum()} receivers, {wrong.sum()} wrong")


def check_errors_as_the_cli(o):
    """Each error raises the Python exception with the line the CLI prints after 'shadowlab: '."""
    missing = os.path.join(os.path.dirname(o.scene), "no_such_scene.json")
    cases = [(lambda: shadowlab.load_scene(missing), shadowlab.SceneError, ("measure", missing)),
             (lambda: shadowlab.measure(shadowlab.load_scene(o.scene), "no_such_method", size=(64, 36)), ValueError,
              ("measure", o.scene, "--method", "no_such_method", "--size", "64x36")),
             (lambda: shadowlab.compute(shadowlab.load_scene(o.scene), "focused", settings={"filter": "blurry"}),
              ValueError, ("inspect", o.scene, "--set", "filter=blurry"))]
    for call, kind, args in cases:
        code, _, line = cli(o, *args)
        assert code == 1 and line.startswith("shadowlab: "), (args, code, line)
        try:
            call()
        except kind as error:
            assert str(error) == line[len("shadowlab: "):], (str(error), line)
        else:
            raise AssertionError(f"no {kind.__name__} for {args}")
    print(f"{len(cases)} errors raised with the CLI's messages")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--cli", required=True)
    parser.add_argument("--example", required=True)
    parser.add_argument("--scene", required=True)
    o = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        check_example_against_cli(o, tmp)
    check_arrays_against_numbers(o)
    check_errors_as_the_cli(o)


if __name__ == "__main__":
    main()
