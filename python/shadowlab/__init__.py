"""ShadowLab from Python: load a scene, list the methods, compute a method's setup, measure it
against the exact reference and render any view, with the numbers of the ``shadowlab`` CLI.

    import shadowlab
    scene = shadowlab.load_scene("data/scenes/default.json")
    run = shadowlab.measure(scene, "focused", resolution=1024, size=(640, 360))
    run.numbers["misclassified"]          # as `shadowlab measure --json` prints it
    run.arrays["verdicts"]                # per pixel, named by shadowlab.VERDICTS

Corpus-scale runs on Dask: :func:`evaluate` (shadowlab.corpus). Errors raise ValueError (bad
input: an unknown method, a setting out of range; SceneError for a scene the loader refuses) or
RuntimeError (no X display to render on) with the CLI's one-line messages.
"""
import json
from dataclasses import dataclass, field

from . import _shadowlab
from ._shadowlab import Reference, Scene, SceneError, methods, read_png, views

__all__ = ["Scene", "SceneError", "Reference", "Setup", "Measurement", "load_scene", "methods", "views",
           "compute", "measure", "shimmer", "render", "read_png", "evaluate", "VERDICTS", "CAUSES"]

#: The verdict of each code of Measurement.arrays["verdicts"].
VERDICTS = tuple(_shadowlab.verdict_names())
#: The cause of each code of Measurement.arrays["causes"] (0: none, not misclassified).
CAUSES = tuple(_shadowlab.cause_names())


def _texts(settings):
    """Settings as the CLI's --set reads them: key -> text."""
    return {str(key): str(value) for key, value in (settings or {}).items()}


def _bias(bias):
    """A constant bias in world units (the CLI's --bias), or -1 for the settings' own."""
    return -1.0 if bias is None else float(bias)


def _arrays(value):
    """A JSON number list (a vector, a matrix's rows) as a NumPy array; anything else as it is."""
    import numpy as np  # on first use: the package imports without it (a python3 that lacks NumPy)
    if isinstance(value, list) and value and all(isinstance(v, (int, float, list)) for v in value):
        try:
            return np.array(value, dtype=float)
        except ValueError:  # ragged: not one array
            return value
    return value


def load_scene(file, camera_index=0, light_index=0):
    """The scene of ``file`` (scene JSON, glTF or a lone mesh) with its camera and light of those
    indices, as every command loads it. Raises SceneError with the loader's message."""
    return Scene(str(file), camera_index, light_index)


@dataclass
class Setup:
    """A method's result on a scene: ``inspect --json``'s object as ``json``; for a map method its
    ``maps`` (each a dict: projection, world_to_uvz as a 4x4 array of the column-vector matrix,
    viewport, ...) and ``selection``; ``steps`` with their values as NumPy arrays (vectors, 4x4
    matrices); ``notes`` (fallbacks or limits, as {kind, message}); and, when rasterized, ``depth``:
    every map drawn into its tile of one resolution x resolution texture (d in [0, 1], row v = 0 first)."""
    json: dict
    depth: object = None  # a NumPy array

    @property
    def maps(self):
        return [{key: _arrays(value) for key, value in m.items()} for m in self.json.get("maps", [])]

    @property
    def selection(self):
        return self.json.get("selection")

    @property
    def steps(self):
        return [dict(step, values={name: _arrays(value) for name, value in step["values"].items()})
                for step in self.json["steps"]]

    @property
    def notes(self):
        return self.json.get("fallbacks", self.json.get("limits", []))


def compute(scene, method, settings=None, resolution=1024, bias=None, rasterize=True):
    """The setup ``method`` computes for ``scene`` with ``settings`` (key -> value, as --set), as
    ``shadowlab inspect --json`` prints it, and its maps rasterized at ``resolution`` texels a side."""
    text, depth = _shadowlab.compute(scene, method, _texts(settings), int(resolution), _bias(bias), bool(rasterize))
    return Setup(json=json.loads(text), depth=depth)


@dataclass
class Measurement:
    """One method measured against the exact reference: ``numbers`` is ``measure --json``'s object
    (the same keys and values; timings differ from run to run); ``arrays`` the per-pixel images,
    height x width, row 0 at the top: ``verdicts`` (codes of VERDICTS), ``causes`` (codes of CAUSES,
    where the run judged them), ``m``, ``m_perspective``, ``m_projection`` (float32, 0 where not
    measured; maps only), and the reference's ``visible``, ``lit``, ``object`` and, for an area
    light, ``visibility``."""
    numbers: dict
    arrays: dict = field(default_factory=dict)


def measure(scene, method, resolution=1024, size=(1280, 720), bias=None, settings=None, diagnose=True,
            reference=None):
    """``shadowlab measure`` from Python: ``method`` at ``resolution`` on the camera image of
    ``size`` (width, height; the camera's aspect within it). ``diagnose``: the causes' remedies
    measured too (``numbers["diagnosis"]``). ``reference``: a Reference of the scene traced before
    (reused; ``size`` is then its own)."""
    reference = reference or Reference(scene, int(size[0]), int(size[1]))
    text, arrays = _shadowlab.measure(reference, method, int(resolution), _bias(bias), _texts(settings),
                                      bool(diagnose))
    arrays.update(reference.arrays)
    return Measurement(numbers=json.loads(text), arrays=arrays)


def shimmer(scene, method, path="translate", frames=60, step=0.0, resolution=1024, size=(640, 360),
            settings=None, reference=None):
    """``shadowlab shimmer``'s numbers: the camera moved along ``path`` (translate, rotate, dolly)
    for ``frames`` frames, the share of fixed receiver points' verdicts that flip between frames:
    a dict of share, flips, transitions and summary."""
    reference = reference or Reference(scene, int(size[0]), int(size[1]))
    return _shadowlab.shimmer(reference, method, int(resolution), _texts(settings), path, int(frames), float(step))


def render(scene, method="focused", view="camera", size=(1280, 720), resolution=2048, bias=None, settings=None,
           **options):
    """``shadowlab render`` to an array: the view (see views()) drawn offscreen, height x width x 3
    uint8, row 0 at the top, the same pixels as the PNG the CLI writes. ``options`` are render's
    other options by name: step, aliasing, error, texture, light ("AZ,EL"), preset, overlay,
    scene_in_ppls. Needs an X display (xvfb-run)."""
    return _shadowlab.render(scene, method=method, view=view, width=int(size[0]), height=int(size[1]),
                             resolution=int(resolution), bias=_bias(bias), settings=_texts(settings), **options)


def evaluate(*args, **kwargs):
    """Corpus-scale runs on Dask: see shadowlab.corpus.evaluate (dask is imported on first use)."""
    from .corpus import evaluate as evaluate_on_dask
    return evaluate_on_dask(*args, **kwargs)
