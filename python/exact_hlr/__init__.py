"""exact-hlr: hidden lines and surfaces of polyhedra, computed exactly.

    >>> import exact_hlr
    >>> d = exact_hlr.render(([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]],
    ...                       [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]), view="iso")
    >>> d.save("tetra.pdf", page="A4")

render() takes files, in-memory meshes and scene dicts, and every option of `hlr render` as a
keyword (`--plan-depth 2` is `plan_depth=2`, `--no-overhead` is `no_overhead=True`) with the
command line's defaults and messages. The drawing gives its pieces as numpy arrays (`arrays()`),
as exact Fractions (`segments`, `piece(i)`), its visible surfaces, strokes and the CLI's file
text in every format (`plot()`, `svg()`, `json()`, `save()`); in Jupyter it shows itself.

Numbers: in meshes and scene dicts, ints, Fractions and Decimals are exact and a float is its
exact binary value (0.1 is 3602879701896397/36028797018963968); in options (view=(1, 2, 0.5),
section="z<1.2") a number is the text it prints as, read as the command line reads it (0.1 is
1/10).
"""
from __future__ import annotations

import json
import os
from decimal import Decimal
from fractions import Fraction
from typing import Any, Dict, Iterable, List, Optional, Sequence, Tuple, Union

from . import _core
from ._core import BodyError, Error, InputError, NumberError, OptionError, OutputError, __version__

__all__ = [
    "render", "raster", "explain", "clip", "Drawing", "Image", "option_names", "LINE_KINDS", "Error", "InputError",
    "NumberError", "BodyError", "OptionError", "OutputError", "__version__",
]

#: The names of the line kinds, by the number in `Drawing.arrays()["kind"]`.
LINE_KINDS: Tuple[str, ...] = tuple(_core.line_kinds())

# Options of `hlr render` that a Python call has its own way for: the output file and format
# (save(), plot()), messages on standard error, tiles (a command-line split), polyline files
# (lines=[...] in memory).
_COMMAND_ONLY = {"help", "o", "format", "progress", "quiet", "timings", "tile", "lines", "stats"}
_KINDS: Dict[str, str] = {n.replace("-", "_"): k for n, k in _core.option_names(False) if n not in _COMMAND_ONLY}
_OUTPUT = {n.replace("-", "_") for n, _ in _core.option_names(True)} - _COMMAND_ONLY
_RENDER_ONLY = set(_KINDS) - _OUTPUT


def option_names(output_only: bool = False) -> List[str]:
    """The keywords render() takes (those of `hlr render`), or the output ones plot() and save() take."""
    return sorted(_OUTPUT if output_only else _KINDS)


def _text(value: Any, name: str) -> str:
    if isinstance(value, str):
        return value
    if isinstance(value, bool):
        raise OptionError(f"{name}: True/False is for flags, not a value")
    if isinstance(value, Fraction):
        return f"{value.numerator}/{value.denominator}"
    if isinstance(value, Iterable):  # a vector: (1, 2, 3), a list, a numpy array
        return ",".join(_text(x, name) for x in value)
    if isinstance(value, (int, float, Decimal)) or hasattr(value, "__index__") or hasattr(value, "__float__"):
        return str(value.item() if hasattr(value, "item") else value)  # numpy scalars as Python numbers
    raise OptionError(f"{name}: cannot read {value!r}")


def _args(options: Dict[str, Any], allowed: Iterable[str], caller: str) -> List[str]:
    allowed = set(allowed)
    out: List[str] = []
    for name, value in options.items():
        if name == "through":  # the inverse of --no-through
            name, value = "no_through", not value
        if name not in allowed:
            hint = " (an option of the render itself: give it to render())" if name in _RENDER_ONLY else ""
            raise TypeError(f"{caller}() got an unexpected keyword argument '{name}'{hint}")
        if value is None:
            continue
        flag = "--" + name.replace("_", "-")
        kind = _KINDS[name]
        if kind == "flag":
            if value:
                out.append(flag)
        elif kind == "list":
            for v in [value] if isinstance(value, str) else value:
                out.append(f"{flag}={_text(v, name)}")
        else:
            out.append(f"{flag}={_text(value, name)}")
    return out


def _exact(value: Any) -> Any:
    """Scene dict values for the scene reader: exact numbers as text, arrays as lists."""
    if isinstance(value, bool) or value is None or isinstance(value, str):
        return value
    if isinstance(value, dict):
        return {str(k): _exact(v) for k, v in value.items()}
    if hasattr(value, "tolist") and not isinstance(value, (int, float)):
        value = value.tolist()
    if isinstance(value, (list, tuple)):
        return [_exact(v) for v in value]
    if isinstance(value, int):
        return value
    if isinstance(value, (float, Fraction, Decimal)) or hasattr(value, "as_integer_ratio"):
        n, d = value.as_integer_ratio()
        return n if d == 1 else f"{n}/{d}"
    if hasattr(value, "__index__"):
        return int(value)
    raise OptionError(f"scene: cannot read {value!r}")


def _is_mesh_pair(x: Any) -> bool:
    return isinstance(x, tuple) and len(x) == 2 and not isinstance(x[0], (str, os.PathLike))


def _items(inputs: Any) -> List[tuple]:
    """The inputs as the compiled core takes them: files, meshes, scene texts."""
    if isinstance(inputs, (str, os.PathLike, dict)) or _is_mesh_pair(inputs) or hasattr(inputs, "faces"):
        inputs = [inputs]
    items: List[tuple] = []
    meshes = 0
    for x in inputs:
        if isinstance(x, (str, os.PathLike)):
            items.append(("file", os.fspath(x)))
            continue
        if isinstance(x, dict) and "bodies" in x:
            # a scene file's text (JSON) under a scene file's name: its view, lights and sections count
            items.append(("scene", json.dumps(_exact(x), indent=1), "<scene dict>.json"))
            continue
        meshes += 1
        if isinstance(x, dict) and "vertices" in x and "faces" in x:
            v, f, name = x["vertices"], x["faces"], x.get("name")
        elif _is_mesh_pair(x):
            (v, f), name = x, None
        elif hasattr(x, "vertices") and hasattr(x, "faces"):
            v, f = x.vertices, x.faces
            name = getattr(x, "name", None) or (getattr(x, "metadata", None) or {}).get("name")
        else:
            raise InputError(f"input {len(items) + 1}: {type(x).__name__} is not a file name, a mesh (vertices, faces) or a scene dict")
        items.append(("mesh", v, f, str(name) if name else f"mesh{meshes}"))
    if not items:
        raise InputError("render() needs at least one input")
    if sum(1 for i in items if i[0] == "mesh") == 1:  # one mesh is "mesh", as one file is its stem
        items = [i if i[0] != "mesh" or i[3] != "mesh1" else i[:3] + ("mesh",) for i in items]
    return items


_EXTENSIONS = {".svg": "svg", ".pdf": "pdf", ".png": "png", ".dxf": "dxf", ".json": "json"}


class Drawing:
    """An exact drawing: one view, or a sheet of views (`views`, `view(name)`)."""

    def __init__(self, core: "_core.Drawing", options: Dict[str, Any]):
        self._core = core
        self._options = options
        self._views: Optional[Dict[str, "Drawing"]] = None

    # -- what the render is
    @property
    def views(self) -> Dict[str, "Drawing"]:
        """A sheet's views by name (`views="front,top,iso"`); {} for one view."""
        if self._views is None:
            self._views = {n: Drawing(self._core.view(n), self._options) for n in self._core.views}
        return self._views

    @property
    def bodies(self) -> List[str]:
        """Body names, in drawing order."""
        return self._core.bodies

    @property
    def notes(self) -> List[str]:
        """What the render did that the drawing says (repairs, splits, a model's tessellation)."""
        return self._core.notes

    @property
    def method(self) -> str:
        return self._core.method

    # -- the pieces
    def __len__(self) -> int:
        return self._core.piece_count()

    def arrays(self) -> Dict[str, Any]:
        """Every piece as numpy arrays, in the JSON's order (made once, in C++): start, end (n x 2:
        picture coordinates, float64), start3, end3 (n x 3: world), t (n x 2), body, body2 (-1 for
        edges), edge (n x 2 vertex numbers, -1 for intersections), segment, kind (LINE_KINDS),
        visible, self_hidden, through, behind_eye, clipped."""
        return self._core.arrays()

    @property
    def segments(self) -> List[Dict[str, Any]]:
        """Every piece with its exact values (Fractions): kind, body and edge or bodies, visible,
        from, to, t, self_hidden, through, behind_eye, clipped. Made once."""
        return self._core.segments

    def piece(self, i: int) -> Dict[str, Any]:
        """Piece i of `segments` (made on its first use only)."""
        return self._core.piece(i)

    @property
    def surfaces(self) -> Optional[List[Dict[str, Any]]]:
        """With surfaces=True: per face seen, its side, shade, exact area and visible polygons."""
        return self._core.surfaces

    @property
    def priority(self) -> Optional[List[Dict[str, Any]]]:
        """With method='priority': the painter's list back to front."""
        return self._core.priority

    # -- output: the CLI's output stage
    def _output(self, overrides: Dict[str, Any], caller: str) -> List[str]:
        _args(overrides, _OUTPUT, caller)  # only output options here
        return _args({**self._options, **overrides}, _KINDS, caller)

    def strokes(self, **output: Any) -> Dict[str, List[Any]]:
        """The plotting 2D stage's strokes per layer in pen order: n x 2 numpy arrays (a closed
        stroke repeats its first point). hidden="dashed" adds the hidden layers."""
        return self._core.strokes(self._output(output, "strokes"))

    def plot(self, format: str = "svg", **output: Any) -> bytes:
        """The file `hlr render` writes (svg, pdf, png, dxf or json), with the render's output
        options and these (page="A4", scale="1:10", hidden="dashed", layers=..., ...)."""
        return self._core.text(format, self._output(output, "plot"))

    def svg(self, **output: Any) -> str:
        return self.plot("svg", **output).decode()

    def json(self, **output: Any) -> str:
        """The exact JSON of `hlr render -o x.json` (docs/output-format.md)."""
        return self.plot("json", **output).decode()

    def save(self, path: Union[str, os.PathLike], format: Optional[str] = None, **output: Any) -> None:
        """Writes the file (format from the extension: .svg .pdf .png .dxf .json), atomically."""
        path = os.fspath(path)
        if format is None:
            ext = os.path.splitext(path)[1].lower()
            if ext not in _EXTENSIONS:
                raise OptionError(f"cannot write '{path}': unknown output format '{ext}' (known: {', '.join(_EXTENSIONS)}; or give format=)")
            format = _EXTENSIONS[ext]
        self._core.save(path, format, self._output(output, "save"))

    def _repr_svg_(self) -> str:
        return self.svg()

    def __repr__(self) -> str:
        what = f"sheet of {', '.join(self._core.views)}" if self._core.is_sheet else f"{len(self)} pieces"
        return f"<exact_hlr.Drawing: {what}>"


MeshLike = Any  # (vertices, faces), {"vertices": ..., "faces": ...}, or an object with .vertices and .faces
Inputs = Union[str, os.PathLike, MeshLike, Dict[str, Any], Sequence[Any]]


def render(inputs: Inputs, *, lines: Optional[Sequence[Sequence[Sequence[Any]]]] = None, **options: Any) -> Drawing:
    """Renders files (mesh, model or scene), in-memory meshes and scene dicts, exactly.

    inputs: a path, a mesh ((vertices, faces) as lists or numpy arrays, a dict with "vertices"
    and "faces" and an optional "name", or any object with .vertices and .faces such as a
    trimesh), a scene dict with the scene file's keys ("bodies", "view", "lighting", ...), or a
    list of these (several bodies). options: those of `hlr render` by name (option_names()):
    view="iso" or (1, 2, 3), eye=, target=, up=, views="front,top,right,iso", method=, edges=,
    crease=, surfaces=True, shadows=True, hatch=True, section="z<1.2", plan=1200, page="A3",
    scale="1:50", hidden="dashed", ... lines=[[(x, y, z), ...], ...]: your own 3D polylines,
    hidden by the bodies.
    """
    items = _items(inputs)
    core = _core.render(items, _args(options, _KINDS, "render"), lines)
    return Drawing(core, options)


Image = _core.Image


def raster(inputs: Inputs, *, view: Any = None, eye: Any = None, target: Any = None, up: Any = None, up_axis: str = "y",
           algorithm: str = "zbuffer", width: int = 256, height: int = 256, shading: str = "flat", samples: int = 1,
           bounces: int = 0, threads: int = 0) -> "_core.Image":
    """The course's image-space algorithms (zbuffer, scanline, warnock, raytrace) with the exact
    face at every pixel centre: png(), faces(), centre(i, j), camera()."""
    text = lambda v: "" if v is None else _text(v, "view")
    return _core.raster(_items(inputs), [text(view), text(eye), text(target), text(up), up_axis], algorithm, width, height, shading,
                        samples, bounces, threads)


def explain(problem: Union[str, os.PathLike], *, lang: str = "en", format: str = "md") -> str:
    """Solves a problem file step by step (exam mode): Markdown, HTML or JSON text."""
    return _core.explain(os.fspath(problem), lang, format)


def clip(clipper: str, segment: Sequence[Any]) -> Dict[str, Any]:
    """Cyrus-Beck clip of a segment (x1, y1, z1, x2, y2, z2) to box:..., frustum:... or a convex mesh file."""
    return _core.clip(clipper, segment)
