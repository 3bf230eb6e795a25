#!/usr/bin/env python3
"""The layers the build enforces (docs/ARCHITECTURE.md, "Layers").

Reads core/layers.txt, the table core/CMakeLists.txt builds its libraries from, and checks every
#include of the tree against it:
  - in core/, a file includes only its own unit (a folder, or a file at core/'s top), the units
    listed before it in its layer, and the units of the layers below: never one that runs back up;
  - core/ includes nothing of Qt or VTK, and nothing of viewer/ or app/;
  - viewer/ includes nothing of app/.
Each include that breaks a rule is printed as `file:line: what`, naming both units and layers; the
exit status is 1 if there is any, else 0.

  check_layers.py [--root DIR]          check the tree at DIR (default: this script's repository)
  check_layers.py [--root DIR] --graph  list, for every unit of core/, the units its files include
"""
import argparse
import collections
import pathlib
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]')
SOURCE_SUFFIXES = {".hpp", ".cpp", ".h", ".inl"}
QT_OR_VTK = re.compile(r"^(Q[A-Z]\w*|Qt\w*/.*|vtk\w*(\.h)?)$")


class Table:
    """The layers, lowest first, and where each unit stands: (layer index, position in its layer)."""

    def __init__(self, path):
        self.path = path
        self.layers = []  # [(name, [unit, ...])]
        self.place = {}  # unit -> (layer index, position)
        for number, raw in enumerate(path.read_text().splitlines(), start=1):
            line = raw.split("#", 1)[0].strip()
            if not line:
                continue
            name, colon, units = line.partition(":")
            if not colon or not units.split():
                raise SystemExit(f"{path}:{number}: a layer is `name: units`, not {raw.strip()!r}")
            for position, unit in enumerate(units.split()):
                if unit in self.place:
                    raise SystemExit(f"{path}:{number}: {unit} is already in layer {self.layer_of(unit)}")
                self.place[unit] = (len(self.layers), position)
            self.layers.append((name.strip(), units.split()))

    def layer_of(self, unit):
        return self.layers[self.place[unit][0]][0]

    def shown(self, unit):
        return f"{unit} (layer {self.layer_of(unit)})"

    def problem(self, unit, target):
        """Why `unit` may not include `target`, or None when it may."""
        (layer, position), (target_layer, target_position) = self.place[unit], self.place[target]
        if target == unit or target_layer < layer or (target_layer == layer and target_position < position):
            return None
        if target_layer > layer:
            return "a layer above"
        return f"listed after {unit} in their layer"


def unit_of(relative):
    """The unit of a path relative to core/: its folder, or the file itself at core/'s top."""
    return relative.parts[0]


def sources(folder):
    return sorted(p for p in folder.rglob("*") if p.suffix in SOURCE_SUFFIXES and p.is_file())


def includes(path):
    for number, line in enumerate(path.read_text(errors="replace").splitlines(), start=1):
        match = INCLUDE.match(line)
        if match:
            yield number, match.group(1) == '"', match.group(2)


def check_core(root, table):
    core = root / "core"
    problems = []
    units = {p.name for p in core.iterdir() if p.is_dir() or p.suffix in SOURCE_SUFFIXES}
    for unit in sorted(units - table.place.keys()):
        problems.append(f"core/{unit}: in no layer of {table.path.relative_to(root)}")
    for unit in sorted(table.place.keys() - units):
        problems.append(f"{table.path.relative_to(root)}: {unit} is no folder or file of core/")
    for path in sources(core):
        unit = unit_of(path.relative_to(core))
        if unit not in table.place:
            continue  # reported above
        where = path.relative_to(root)
        for number, quoted, name in includes(path):
            if not quoted:
                if QT_OR_VTK.match(name):
                    problems.append(f"{where}:{number}: {table.shown(unit)} includes <{name}>: core is free of Qt and VTK")
                continue
            target_path = pathlib.PurePosixPath(name)
            if (core / target_path).is_file():
                target = unit_of(target_path)
                if target not in table.place:
                    continue  # a unit in no layer, reported above
                why = table.problem(unit, target)
                if why:
                    problems.append(f"{where}:{number}: {table.shown(unit)} includes {name}, of {table.shown(target)}, {why}")
            elif not (path.parent / target_path).is_file():
                for outside in ("viewer", "app"):
                    if (root / outside / target_path).is_file() or target_path.parts[0] == outside:
                        problems.append(f"{where}:{number}: {table.shown(unit)} includes {name}, of {outside}/: core stands alone")
    return problems


def check_viewer(root):
    viewer, app = root / "viewer", root / "app"
    problems = []
    for path in sources(viewer):
        where = path.relative_to(root)
        for number, quoted, name in includes(path):
            target = pathlib.PurePosixPath(name)
            seen_below = (path.parent / target).is_file() or (viewer / target).is_file() or (root / "core" / target).is_file()
            if quoted and not seen_below and ((app / target).is_file() or target.parts[0] == "app"):
                problems.append(f"{where}:{number}: viewer includes {name}, of app/: the app uses the viewer, not back")
    return problems


def graph(root, table):
    """For every unit of core/, the units its files include and how often."""
    core = root / "core"
    edges = collections.defaultdict(collections.Counter)
    for path in sources(core):
        unit = unit_of(path.relative_to(core))
        for _, quoted, name in includes(path):
            target = pathlib.PurePosixPath(name)
            if quoted and (core / target).is_file() and unit_of(target) != unit:
                edges[unit][unit_of(target)] += 1
    for name, units in table.layers:
        for unit in units:
            used = ", ".join(f"{t} ({n})" for t, n in sorted(edges[unit].items()))
            print(f"{name:>10}  {unit:<11} -> {used or '-'}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--root", type=pathlib.Path, default=pathlib.Path(__file__).resolve().parent.parent)
    parser.add_argument("--graph", action="store_true", help="list the units each unit of core/ includes")
    args = parser.parse_args()
    root = args.root.resolve()
    table = Table(root / "core" / "layers.txt")
    if args.graph:
        graph(root, table)
        return 0
    problems = check_core(root, table) + check_viewer(root)
    for problem in problems:
        print(problem)
    if problems:
        print(f"{len(problems)} include(s) against the layers of core/layers.txt", file=sys.stderr)
        return 1
    print(f"every include of core/ and viewer/ keeps to the {len(table.layers)} layers of core/layers.txt")
    return 0


if __name__ == "__main__":
    sys.exit(main())
