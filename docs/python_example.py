#!/usr/bin/env python3
"""ShadowLab from Python: a scene, the methods, a setup, a measurement, a view.

    PYTHONPATH=build/python /usr/bin/python3 docs/python_example.py data/scenes/default.json \
        --method focused --resolution 1024 --size 640x360 [--json numbers.json] [--render camera.npy]

prints what it finds; --json writes the measurement's numbers (measure --json's object), --render
draws the Camera view into a NumPy file (needs an X display: xvfb-run). The tests run it and hold
its numbers equal to `shadowlab measure --json`'s.
"""
import argparse
import json

import numpy as np

import shadowlab


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("scene")
    parser.add_argument("--method", default="focused")
    parser.add_argument("--resolution", type=int, default=1024)
    parser.add_argument("--size", default="640x360")
    parser.add_argument("--json", help="write the measurement's numbers here")
    parser.add_argument("--render", help="write the Camera view (height x width x 3) here, as .npy")
    o = parser.parse_args()
    width, height = (int(n) for n in o.size.split("x"))

    scene = shadowlab.load_scene(o.scene)
    print(scene, "- first objects:", ", ".join(scene.objects[:4]))

    method = next(m for m in shadowlab.methods() if m["name"] == o.method)
    print(f"{method['name']}: {method['title']}, {len(method['settings'])} settings:",
          ", ".join(f"{s['name']}={s['default']}" for s in method["settings"]))

    setup = shadowlab.compute(scene, o.method, resolution=o.resolution)
    for i, m in enumerate(setup.maps):
        print(f"map {i}: {m['projection']}, world_to_uvz =\n{m.get('world_to_uvz')}")
    for step in setup.steps:
        print(f"  step {step['id']}: {step['title']} ({len(step['values'])} values)")
    if setup.depth is not None:
        drawn = setup.depth < 1.0
        print(f"depth texture {setup.depth.shape}: {drawn.mean():.1%} of its texels drawn")

    run = shadowlab.measure(scene, o.method, resolution=o.resolution, size=(width, height))
    numbers = run.numbers
    verdicts = run.arrays["verdicts"]
    wrong = np.isin(verdicts, [shadowlab.VERDICTS.index("false_shadow"), shadowlab.VERDICTS.index("false_light")])
    print(f"misclassified {numbers['misclassified']:.3%} of {numbers['receiver_pixels']} receiver pixels "
          f"({wrong.sum()} pixels of the {verdicts.shape[1]}x{verdicts.shape[0]} image); m max {numbers['m']['max']:.3g}")
    if "causes" in run.arrays:
        codes, counts = np.unique(run.arrays["causes"][wrong], return_counts=True)
        print("causes:", ", ".join(f"{shadowlab.CAUSES[c]} {n}" for c, n in zip(codes, counts)))
    if o.json:
        with open(o.json, "w") as out:
            json.dump(numbers, out, indent=1)

    if o.render:
        image = shadowlab.render(scene, o.method, view="camera", size=(width, height), resolution=o.resolution)
        np.save(o.render, image)
        print(f"camera view {image.shape[1]}x{image.shape[0]}, mean grey {image.mean():.1f}")


if __name__ == "__main__":
    main()
