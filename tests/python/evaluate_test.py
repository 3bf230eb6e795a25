"""shadowlab.evaluate on a two-worker LocalCluster gives the serial run's table: the same rows
(scene, method, resolution, camera path) with the same numbers, timings aside.

    evaluate_test.py SCENE... (with the package on PYTHONPATH)"""
import sys

import pandas as pd

from shadowlab import corpus

METHODS = ["focused", "lispsm", "volumes"]  # two map methods and a technique (no map: no resolution, no path)
RESOLUTIONS = [128, 256]
PATHS = [corpus.STILL, "translate"]


def run(scenes, scheduler):
    return corpus.evaluate(scenes, METHODS, RESOLUTIONS, PATHS, size=(160, 90), frames=3, scheduler=scheduler)


def main(scenes):
    serial = run(scenes, "synchronous")
    expected_rows = len(scenes) * (2 * len(RESOLUTIONS) * len(PATHS) + 1)
    assert len(serial) == expected_rows, (len(serial), expected_rows)
    still = serial[serial.path == corpus.STILL]
    assert still.misclassified.notna().all() and (still.misclassified > 0).any(), still
    moving = serial[serial.path == "translate"]
    assert (moving.transitions > 0).all(), moving
    parallel = run(scenes, None)  # LocalCluster(n_workers=2, threads_per_worker=1, processes=True)
    measured = corpus.KEYS + corpus.MEASURED
    pd.testing.assert_frame_equal(parallel[measured], serial[measured], check_exact=True)
    print(f"{len(serial)} rows, equal on two workers and serially")


if __name__ == "__main__":
    main(sys.argv[1:])
