#!/usr/bin/env python3
"""scripts/check_layers.py on small trees in a temporary directory: each wrong include is reported
with its file, its line and both units' layers, and a tree that keeps to its layers passes."""
import pathlib
import subprocess
import sys
import tempfile
import unittest

CHECKER = pathlib.Path(__file__).resolve().parent.parent / "scripts" / "check_layers.py"


class Tree:
    """A repository of a few files: {relative path: text}."""

    def __init__(self, files):
        self.directory = tempfile.TemporaryDirectory()
        self.root = pathlib.Path(self.directory.name)
        for relative, text in files.items():
            path = self.root / relative
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text(text)

    def check(self):
        run = subprocess.run([sys.executable, str(CHECKER), "--root", str(self.root)], capture_output=True, text=True)
        return run.returncode, run.stdout.splitlines()

    def close(self):
        self.directory.cleanup()


TWO_LAYERS = "# lowest first\nlow: first second\nhigh: top\n"


class LayeringCheck(unittest.TestCase):
    def check(self, files):
        tree = Tree(files)
        self.addCleanup(tree.close)
        return tree.check()

    def test_a_tree_that_keeps_to_its_layers_passes(self):
        status, lines = self.check({
            "core/layers.txt": TWO_LAYERS,
            "core/first/a.hpp": "#pragma once\n",
            "core/second/b.hpp": '#include "first/a.hpp"\n#include "second/c.hpp"\n#include <vector>\n',
            "core/second/c.hpp": "#pragma once\n",
            "core/top/d.cpp": '#include "first/a.hpp"\n#include "second/b.hpp"\n',
        })
        self.assertEqual(status, 0, lines)

    def test_an_include_of_a_layer_above_is_named_by_file_line_and_both_layers(self):
        status, lines = self.check({
            "core/layers.txt": TWO_LAYERS,
            "core/first/a.cpp": '#include "first/a.hpp"\n\n#include "top/d.hpp"\n',
            "core/first/a.hpp": "#pragma once\n",
            "core/second/b.hpp": "#pragma once\n",
            "core/top/d.hpp": "#pragma once\n",
        })
        self.assertEqual(status, 1)
        self.assertEqual(lines, ["core/first/a.cpp:3: first (layer low) includes top/d.hpp, of top (layer high), a layer above"])

    def test_an_include_of_a_unit_later_in_the_same_layer_is_a_circle_and_reported(self):
        status, lines = self.check({
            "core/layers.txt": TWO_LAYERS,
            "core/first/a.hpp": '#pragma once\n#include "second/b.hpp"\n',
            "core/second/b.hpp": "#pragma once\n",
            "core/top/d.hpp": "#pragma once\n",
        })
        self.assertEqual(status, 1)
        self.assertEqual(lines, ["core/first/a.hpp:2: first (layer low) includes second/b.hpp, of second (layer low), "
                                 "listed after first in their layer"])

    def test_core_including_qt_vtk_the_viewer_or_the_app_is_reported(self):
        status, lines = self.check({
            "core/layers.txt": TWO_LAYERS,
            "core/first/a.cpp": '#include <QWidget>\n#include <vtkActor.h>\n#include "gui/window.hpp"\n'
                                '#include "scene_source.hpp"\n',
            "core/second/b.hpp": "#pragma once\n",
            "core/top/d.hpp": "#pragma once\n",
            "viewer/gui/window.hpp": "#pragma once\n",
            "app/scene_source.hpp": "#pragma once\n",
        })
        self.assertEqual(status, 1)
        self.assertEqual(lines, [
            "core/first/a.cpp:1: first (layer low) includes <QWidget>: core is free of Qt and VTK",
            "core/first/a.cpp:2: first (layer low) includes <vtkActor.h>: core is free of Qt and VTK",
            "core/first/a.cpp:3: first (layer low) includes gui/window.hpp, of viewer/: core stands alone",
            "core/first/a.cpp:4: first (layer low) includes scene_source.hpp, of app/: core stands alone",
        ])

    def test_the_viewer_including_the_app_is_reported(self):
        status, lines = self.check({
            "core/layers.txt": TWO_LAYERS,
            "core/first/a.hpp": "#pragma once\n",
            "core/second/b.hpp": "#pragma once\n",
            "core/top/d.hpp": "#pragma once\n",
            "viewer/gui/window.cpp": '#include "first/a.hpp"\n#include "measure_command.hpp"\n',
            "app/measure_command.hpp": "#pragma once\n",
        })
        self.assertEqual(status, 1)
        self.assertEqual(lines, ["viewer/gui/window.cpp:2: viewer includes measure_command.hpp, of app/: "
                                 "the app uses the viewer, not back"])

    def test_a_folder_in_no_layer_and_a_unit_of_no_folder_are_reported(self):
        status, lines = self.check({
            "core/layers.txt": TWO_LAYERS,
            "core/first/a.hpp": "#pragma once\n",
            "core/second/b.hpp": "#pragma once\n",
            "core/stray/e.hpp": '#include "first/a.hpp"\n',
        })
        self.assertEqual(status, 1)
        self.assertEqual(lines, ["core/stray: in no layer of core/layers.txt",
                                 "core/layers.txt: top is no folder or file of core/"])


if __name__ == "__main__":
    unittest.main()
