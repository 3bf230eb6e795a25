"""Corpus-scale runs on Dask: every (scene, method, resolution, camera path) measured as one
independent task, on a LocalCluster of two single-threaded worker processes by default or on any
scheduler given, gathered into one pandas DataFrame (and a CSV)."""
import functools
import os

import dask
import pandas as pd

import shadowlab

#: A row's identity, then what is measured (bench.csv's columns, then a camera path's shimmer).
KEYS = ["scene", "method", "resolution", "path"]
MEASURED = ["misclassified", "false_shadow", "false_light", "m_max", "m_mean", "m_p95", "m_perspective_max",
            "m_perspective_mean", "m_perspective_p95", "fallback", "polygons", "fill_mean", "fill_max",
            "shimmer", "flips", "transitions"]
#: Wall times: they differ from run to run, so comparisons of runs leave them out.
TIMINGS = ["setup_ms", "raster_ms", "total_ms"]
COLUMNS = KEYS + MEASURED + TIMINGS
#: The path of a still camera: the measure of its one image.
STILL = "still"


@functools.lru_cache(maxsize=2)
def _reference(file, width, height):
    """A scene's reference, traced once per worker process (or the serial run) and reused by every
    task on that scene there."""
    return shadowlab.Reference(shadowlab.load_scene(file), width, height)


def _still_row(numbers):
    """measure --json's numbers as bench.csv's columns."""
    m, m_perspective = numbers["m"], numbers["m_perspective"]
    row = {"misclassified": numbers["misclassified"], "false_shadow": numbers["false_shadow"],
           "false_light": numbers["false_light"], "m_max": m["max"], "m_mean": m["mean"], "m_p95": m["p95"],
           "m_perspective_max": m_perspective["max"], "m_perspective_mean": m_perspective["mean"],
           "m_perspective_p95": m_perspective["p95"], "fallback": numbers["fallback"] or "",
           "setup_ms": numbers["setup_ms"], "raster_ms": numbers["raster_ms"],
           "total_ms": numbers["setup_ms"] + numbers["raster_ms"]}
    for key in ("polygons", "fill_mean", "fill_max"):
        row[key] = numbers.get(key)
    return row


def measure_task(file, method, resolution, path, size, frames):
    """One row: ``method`` at ``resolution`` on the scene of ``file``, from its still camera
    (measure's numbers, without the diagnosis) or along a camera path (shimmer's flips)."""
    reference = _reference(file, size[0], size[1])
    row = {"scene": os.path.splitext(os.path.basename(file))[0], "method": method, "resolution": resolution,
           "path": path}
    if path == STILL:
        run = shadowlab.measure(None, method, resolution, diagnose=False, reference=reference)
        row.update(_still_row(run.numbers))
    else:
        flips = shadowlab.shimmer(None, method, path, frames=frames, resolution=resolution, reference=reference)
        row.update(shimmer=flips["share"], flips=flips["flips"], transitions=flips["transitions"])
    return row


def tasks(scenes, methods=None, resolutions=(256, 512, 1024), paths=(STILL,)):
    """The independent runs, as (file, method, resolution, path): a geometric technique has no map,
    so it runs once per scene, from the still camera only."""
    registry = {m["name"]: m for m in shadowlab.methods()}
    names = list(methods) if methods else list(registry)
    for name in names:
        if name not in registry:
            raise ValueError(f"unknown method '{name}' (known: {', '.join(registry)})")
    for file in scenes:
        for name in names:
            if registry[name]["makes_maps"]:
                for resolution in resolutions:
                    for path in paths:
                        yield str(file), name, int(resolution), path
            elif STILL in paths:
                yield str(file), name, 0, STILL


def _compute(delayed_rows, scheduler, n_workers):
    """Runs the tasks: "synchronous" in this process, an address on that scheduler, None on a new
    LocalCluster of ``n_workers`` single-threaded processes."""
    if scheduler == "synchronous":
        return dask.compute(*delayed_rows, scheduler="synchronous")
    from dask.distributed import Client, LocalCluster
    if scheduler:
        with Client(scheduler) as client:
            return client.compute(delayed_rows, sync=True)
    with LocalCluster(n_workers=n_workers, threads_per_worker=1, processes=True, dashboard_address=None) as cluster, \
            Client(cluster) as client:
        return client.compute(delayed_rows, sync=True)


def evaluate(scenes, methods=None, resolutions=(256, 512, 1024), paths=(STILL,), size=(640, 360), frames=30,
             scheduler=None, n_workers=2, csv=None):
    """Every method (default: all) at every resolution on every scene file, from the still camera
    and along each camera path of ``paths`` (translate, rotate, dolly; ``frames`` frames), each run
    one Dask task; on a camera image of ``size``. ``scheduler``: None for a LocalCluster of
    ``n_workers`` processes, a scheduler's address ("tcp://host:8786"), or "synchronous" (serial,
    in this process). Returns a DataFrame of COLUMNS sorted by KEYS, written to ``csv`` if given."""
    runs = list(tasks(scenes, methods, resolutions, paths))
    if not runs:
        raise ValueError("evaluate: no run (no scene, or no method for the paths given)")
    measure = dask.delayed(measure_task, pure=True)
    rows = _compute([measure(*run, tuple(size), frames) for run in runs], scheduler, n_workers)
    table = pd.DataFrame(list(rows), columns=COLUMNS).sort_values(KEYS, ignore_index=True)
    if csv:
        table.to_csv(csv, index=False, float_format="%.17g")  # every double read back as it was
    return table
