"""``python3 -m shadowlab.bench``: ``shadowlab bench --scheduler ADDR`` runs this, the same
evaluate as from Python, and writes OUT/bench.csv."""
import argparse
import os
import sys

from .corpus import STILL, evaluate


def main(argv=None):
    parser = argparse.ArgumentParser(prog="shadowlab bench --scheduler",
                                     description="every method at every resolution on every scene, as Dask tasks")
    parser.add_argument("scenes", nargs="+", help="scene files")
    parser.add_argument("--methods", default="", help="methods, comma-separated (default: all)")
    parser.add_argument("--resolutions", default="256,512,1024,2048,4096", help="map resolutions, comma-separated")
    parser.add_argument("--paths", default=STILL, help=f"camera paths, comma-separated: {STILL}, translate, "
                                                        "rotate, dolly")
    parser.add_argument("--frames", type=int, default=30, help="frames along each camera path")
    parser.add_argument("--size", default="640x360", help="camera image size WxH")
    parser.add_argument("--scheduler", default="local", help="a Dask scheduler's address (tcp://host:8786); local: a "
                                                             "LocalCluster of two worker processes; synchronous: "
                                                             "serial, in this process")
    parser.add_argument("--out", required=True, help="output directory")
    o = parser.parse_args(argv)
    try:
        width, height = (int(n) for n in o.size.split("x"))
    except ValueError:
        parser.error(f"--size: expected WxH, got '{o.size}'")
    os.makedirs(o.out, exist_ok=True)
    csv = os.path.join(o.out, "bench.csv")
    evaluate(o.scenes, methods=[m for m in o.methods.split(",") if m] or None,
             resolutions=[int(r) for r in o.resolutions.split(",")], paths=o.paths.split(","),
             size=(width, height), frames=o.frames, scheduler=None if o.scheduler == "local" else o.scheduler, csv=csv)
    print(f"wrote {csv}")


if __name__ == "__main__":
    try:
        main()
    except (ValueError, RuntimeError) as error:
        print(f"shadowlab: {error}", file=sys.stderr)
        sys.exit(1)
