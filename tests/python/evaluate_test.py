"""shadowlab.evaluate on a two-worker LocalCluster gives the serial run's table: the same rows
(scene, method, resolution, camera path) with the same numbers, timings aside; and `shadowlab
bench --scheduler` writes the still camera's rows of it.

    evaluate_test.py CLI SCENE... (with the package on PYTHONPATH)"""
import os
import subprocess
import sys
import tempfile

import pandas as pd

from shadowlab import corpus

METHODS = ["focused", "lispsm", "volumes"]  # two map methods and a technique (no map: no resolution, no path)
RESOLUTIONS = [128, 256]
PATHS = [corpus.STILL, "translate"]


def run(scenes, scheduler):
    return corpus.evaluate(scenes, METHODS, RESOLUTIONS, PATHS, size=(160, 90), frames=3, scheduler=scheduler)


def check_cli(cli, scenes, serial, measured):
    """bench --scheduler synchronous: the same evaluate, through the CLI and python3 -m shadowlab.bench."""
    with tempfile.TemporaryDirectory() as out:
        subprocess.run([cli, "bench", *scenes, "--methods", ",".join(METHODS), "--resolutions",
                        ",".join(map(str, RESOLUTIONS)), "--size", "160x90", "--scheduler", "synchronous", "--out", out],
                       check=True, stderr=subprocess.DEVNULL)
        table = pd.read_csv(os.path.join(out, "bench.csv"), float_precision="round_trip")
    still = serial[serial.path == corpus.STILL].reset_index(drop=True)
    assert len(table) == len(still) > 0, (len(table), len(still))
    table.fallback = table.fallback.fillna("")
    pd.testing.assert_frame_equal(table[measured], still[measured], check_exact=True, check_dtype=False)


def main(cli, scenes):
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
    check_cli(cli, scenes, serial, measured)
    print(f"{len(serial)} rows, equal on two workers and serially; bench --scheduler wrote the still ones")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2:])
