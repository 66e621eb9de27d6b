"""The package as a Python user meets it: installed, in-memory meshes, numpy out, every CLI
option as a keyword with the CLI's bytes, typed exceptions, notebooks."""
import json
import os
import subprocess
import sys
from decimal import Decimal
from fractions import Fraction

import numpy as np
import pytest

import exact_hlr

DATA = os.environ.get("HLR_DATA_DIR", os.path.join(os.path.dirname(__file__), "..", "..", "data"))
ROOT = os.path.abspath(os.path.join(DATA, ".."))
TETRA = ([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])


def path(name):
    return os.path.join(DATA, name)


def hlr(*args):
    exe = os.environ.get("HLR_BIN", "hlr")
    return subprocess.run([exe, *args], check=True, capture_output=True).stdout


def read_off(name):
    words = " ".join(line.split("#")[0] for line in open(path(name))).split()
    nv, nf = int(words[1]), int(words[2])
    v = [[Fraction(x) for x in words[4 + 3 * i: 7 + 3 * i]] for i in range(nv)]
    faces, at = [], 4 + 3 * nv
    for _ in range(nf):
        n = int(words[at])
        faces.append([int(x) for x in words[at + 1: at + 1 + n]])
        at += 1 + n
    return v, faces


@pytest.mark.skipif(not os.environ.get("HLR_EXPECT_INSTALLED"), reason="run by tests/python_package.sh on the installed package")
def test_the_installed_package_is_tested():
    assert exact_hlr.__file__.startswith(sys.prefix) and "site-packages" in exact_hlr.__file__
    assert hlr("--version").decode().strip() == "hlr " + exact_hlr.__version__
    stubs = os.path.join(os.path.dirname(exact_hlr.__file__), "_core.pyi")
    assert os.path.exists(stubs) and os.path.exists(os.path.join(os.path.dirname(stubs), "py.typed"))


def test_the_one_liner_and_its_cli_twin(tmp_path):
    # The tetrahedron of four vertices in memory, iso view: the CLI's bytes for the same OFF file.
    svg = exact_hlr.render(TETRA, view="iso").svg()
    off = tmp_path / "mesh.off"
    off.write_text("OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n")
    assert svg.encode() == hlr("render", str(off), "--view", "iso", "--quiet")
    assert exact_hlr.__version__.count(".") == 2


def test_every_form_of_mesh_draws_the_same():
    # The cube of data/cube.off handed over as lists of Fractions, numpy ints, numpy floats
    # (float64 and float32: exact binary values of small integers), a dict, an object with
    # .vertices and .faces: the same exact JSON pieces as the file.
    v, f = read_off("cube.off")
    want = json.loads(exact_hlr.render(path("cube.off"), view=(1, 2, 3), edges="all").json())["segments"]

    class Trimeshish:
        vertices = np.array(v, dtype=np.float64)
        faces = np.array(f, dtype=np.int64)

    forms = [(v, f), (np.array(v, dtype=np.int32), np.array(f, dtype=np.int32)), (np.array(v, dtype=np.float32), f),
             {"vertices": np.array(v, dtype=np.float64), "faces": f, "name": "cube"}, Trimeshish()]
    for mesh in forms:
        got = json.loads(exact_hlr.render(mesh, view=(1, 2, 3), edges="all").json())["segments"]
        assert got == want


def test_floats_are_their_exact_binary_value():
    # 0.1 is 3602879701896397 / 2^55 in a mesh; Decimal("0.1") and "1/10" are a tenth.
    for x, exact in [(0.1, Fraction(0.1)), (Decimal("0.1"), Fraction(1, 10)), ("1/10", Fraction(1, 10)), (np.float32(0.1), Fraction(float(np.float32(0.1))))]:
        v = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, x]]
        d = exact_hlr.render((v, TETRA[1]), view=(1, 1, 1), edges="all")
        tips = {c for s in d.segments for c in (s["from"][2], s["to"][2])}
        assert tips == {0, exact}
    assert Fraction(0.1) != Fraction(1, 10)


def test_several_bodies_and_scene_dicts():
    # Two boxes that interpenetrate, as a scene dict with the file's keys: the same drawing as
    # data/two_boxes.yaml, with its intersection lines; a list of two meshes is two bodies.
    scene = {"bodies": [{"name": "block", "box": {"min": [0, 0, 0], "max": [4, 2, 2]}},
                        {"name": "bar", "box": {"min": [1, -1, Fraction(1, 2)], "max": [2, 3, Decimal("1.5")]}}],
             "view": {"direction": [1, 1.3, 1.7]}}
    # the file's 1.3 and 1.7 are decimals; the dict's floats are binary: give them as text
    scene["view"]["direction"] = [1, "1.3", "1.7"]
    got = exact_hlr.render(scene)
    want = exact_hlr.render(path("two_boxes.yaml"))
    assert json.loads(got.json())["segments"] == json.loads(want.json())["segments"]
    assert got.bodies == ["block", "bar"] and any(s["kind"] == "intersection" for s in got.segments)
    v, f = read_off("cube.off")
    shifted = [[x + 1, y + Fraction(1, 2), z + Fraction(1, 3)] for x, y, z in v]
    two = exact_hlr.render([(v, f), {"vertices": shifted, "faces": f, "name": "right"}], view="iso")
    assert two.bodies == ["mesh1", "right"]
    assert any(s["kind"] == "intersection" for s in two.segments)


def test_numpy_arrays_are_the_json_piece_by_piece():
    # Every piece of a perspective render with intersections and hidden parts: the arrays hold
    # the JSON's bodies, edges, kinds and flags, its exact numbers to double precision; the
    # Fractions are the JSON's exact strings.
    d = exact_hlr.render(path("two_boxes.yaml"), eye=(9, 7, 11), edges="all")
    js = json.loads(d.json())["segments"]
    a = d.arrays()
    assert d.arrays() is a and len(d) == len(js) == len(a["visible"]) and len(js) > 30
    assert a["start"].dtype == np.float64 and a["start"].shape == (len(js), 2) and a["start3"].shape == (len(js), 3)
    kinds = exact_hlr.LINE_KINDS
    for i, p in enumerate(js):
        if "edge" in p:
            assert (a["body"][i], a["body2"][i], tuple(a["edge"][i])) == (p["body"], -1, tuple(p["edge"]))
        else:
            assert (a["body"][i], a["body2"][i], tuple(a["edge"][i])) == (p["bodies"][0], p["bodies"][1], (-1, -1))
        assert kinds[a["kind"][i]] == p["kind"]
        assert bool(a["visible"][i]) == p["visible"] and bool(a["self_hidden"][i]) == p.get("self_hidden", False)
        assert bool(a["behind_eye"][i]) == p.get("behind_eye", False) and bool(a["clipped"][i]) == p.get("clipped", False)
        for k, key in ((0, "from"), (1, "to")):
            exact = [Fraction(x) for x in p[key]]
            np.testing.assert_allclose(a["start3" if k == 0 else "end3"][i], [float(x) for x in exact], rtol=1e-12, atol=1e-12)
            assert float(Fraction(p["t"][k])) == pytest.approx(a["t"][i][k], abs=1e-15)
        piece = d.piece(i)
        assert piece is d.piece(i)  # made once
        assert [str(x) for x in piece["from"]] == p["from"] and [str(x) for x in piece["to"]] == p["to"]
        assert [str(x) for x in piece["t"]] == p["t"] and piece["visible"] == p["visible"]
    assert d.segments[5] is d.piece(5) and d.piece(-1) is d.segments[-1]


def test_picture_coordinates_are_the_strokes():
    # The cube's front view: every piece's picture coordinates are corners of the square that
    # the plotting stage strokes.
    d = exact_hlr.render(path("cube.off"), view="front")
    (square,) = d.strokes()["visible-silhouette"]
    corners = set(map(tuple, square.tolist()))
    a = d.arrays()
    assert set(map(tuple, a["start"].tolist())) | set(map(tuple, a["end"].tolist())) <= corners


@pytest.mark.parametrize("kwargs,flags,fmt", [
    ({"view": "iso"}, ["--view", "iso"], "svg"),
    ({"view": "dimetric", "hidden": "dashed", "edges": "all"}, ["--view", "dimetric", "--hidden", "dashed", "--edges", "all"], "svg"),
    ({"views": "front,top,right,iso", "page": "A3", "landscape": True}, ["--views", "front,top,right,iso", "--page", "A3", "--landscape"], "svg"),
    ({"views": "front,top,right,iso", "page": "A3", "scale": "10:1"}, ["--views", "front,top,right,iso", "--page", "A3", "--scale", "10:1"], "dxf"),
    ({"view": (-1, Fraction(1, 4), 0.5), "crease": 10}, ["--view", "-1,1/4,0.5", "--crease", "10"], "json"),
    ({"surfaces": True, "hatch": True, "hatch_levels": 3, "view": "iso"}, ["--surfaces", "--hatch", "--hatch-levels", "3", "--view", "iso"], "svg"),
    ({"layers": "visible", "pens": "visible=1,hidden=2", "hidden": "solid"}, ["--layers", "visible", "--pens", "visible=1,hidden=2", "--hidden", "solid"], "svg"),
])
def test_keywords_are_the_cli_options(kwargs, flags, fmt, tmp_path):
    out = tmp_path / ("x." + fmt)
    hlr("render", path("demo.yaml"), *flags, "-o", str(out), "--quiet")
    d = exact_hlr.render(path("demo.yaml"), **kwargs)
    assert d.plot(fmt) == out.read_bytes()
    saved = tmp_path / ("saved." + fmt)
    d.save(saved)
    assert saved.read_bytes() == out.read_bytes()


def test_plans_sections_and_sheet_views(tmp_path):
    # A floor plan and a sheet with a section view, as on the command line.
    out = tmp_path / "plan.svg"
    hlr("render", path("house.yaml"), "--plan", "1.2", "--up-axis", "z", "--no-overhead", "-o", str(out), "--quiet")
    assert exact_hlr.render(path("house.yaml"), plan="1.2", up_axis="z", no_overhead=True).svg().encode() == out.read_bytes()
    sheet = exact_hlr.render(path("house.yaml"), views="front,top,section:A", section_view="A=x<4", page="A3")
    assert sheet.views.keys() == {"front", "top", "section:A"}
    assert any(s["kind"] == "cut" for s in sheet.views["section:A"].segments)
    out = tmp_path / "sheet.svg"
    hlr("render", path("house.yaml"), "--views", "front,top,section:A", "--section-view", "A=x<4", "--page", "A3", "-o", str(out), "--quiet")
    assert sheet.plot("svg") == out.read_bytes()
    with pytest.raises(exact_hlr.OptionError, match="sheet"):
        sheet.json()
    with pytest.raises(exact_hlr.OptionError, match="one drawing"):
        sheet.segments


def test_output_options_override_the_renders():
    d = exact_hlr.render(path("cube.off"), view="iso", hidden="dashed")
    assert d.svg() != d.svg(hidden="none")
    assert d.plot("svg", hidden="none") == exact_hlr.render(path("cube.off"), view="iso").plot("svg")
    with pytest.raises(TypeError, match="render itself"):
        d.svg(view="front")


def test_every_error_is_typed(tmp_path):
    bad = tmp_path / "bad.off"
    bad.write_text("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 x\n3 0 1 2\n")
    with pytest.raises(exact_hlr.InputError) as e:
        exact_hlr.render(str(bad))
    assert e.value.file == str(bad) and e.value.line == 5 and isinstance(e.value, ValueError)
    with pytest.raises(exact_hlr.InputError, match="cannot open"):
        exact_hlr.render(path("none.off"))
    with pytest.raises(exact_hlr.OptionError, match="--view"):
        exact_hlr.render(path("cube.off"), view="sideways")
    with pytest.raises(exact_hlr.OptionError, match="--page"):
        exact_hlr.render(path("cube.off"), page="B7")
    with pytest.raises(exact_hlr.OptionError, match="method"):
        exact_hlr.render(path("cube.off"), method="painter")
    with pytest.raises(TypeError, match="unexpected keyword argument 'colour'"):
        exact_hlr.render(path("cube.off"), colour="red")
    with pytest.raises(exact_hlr.NumberError) as n:
        exact_hlr.render(([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, float("nan")]], TETRA[1]))
    assert "vertex 3" in str(n.value)
    with pytest.raises(exact_hlr.InputError, match="face"):
        exact_hlr.render((TETRA[0], [[0, 1, 9]]))
    with pytest.raises(exact_hlr.OptionError, match="3 numbers"):
        exact_hlr.render(([[0, 0], [1, 0], [0, 1]], [[0, 1, 2]]))
    with pytest.raises(exact_hlr.BodyError, match="contains the eye"):
        exact_hlr.render(path("cube.off"), eye=(0, 0, Fraction(1, 2)), target=(0, 0, -1))
    problem = tmp_path / "p.yaml"
    problem.write_text("problem: roberts\nbodies: 7\n")
    with pytest.raises(exact_hlr.InputError):
        exact_hlr.explain(str(problem))
    with pytest.raises(exact_hlr.OptionError, match="lang"):
        exact_hlr.explain(path("problems/roberts_cube.yaml"), lang="de")
    with pytest.raises(exact_hlr.OptionError, match="unknown output format"):
        exact_hlr.render(path("cube.off")).save(tmp_path / "x.bmp")
    assert not (tmp_path / "x.bmp").exists()
    assert issubclass(exact_hlr.BodyError, exact_hlr.Error) and issubclass(exact_hlr.Error, ValueError)


def test_notebooks_show_the_drawing():
    d = exact_hlr.render(TETRA, view="iso")
    assert d._repr_svg_() == d.svg() and d._repr_svg_().startswith("<?xml")
    assert repr(d) == "<exact_hlr.Drawing: 6 pieces>"


def test_raster_takes_view_names_and_meshes():
    img = exact_hlr.raster(TETRA, view="iso", width=32, height=32)
    seen = {f for row in img.faces() for f in row if f is not None}
    assert seen == {(0, 3)}  # from (1, 1, 1) only the slanted face: the others lie in x, y, z = 0


def test_the_example_script(tmp_path):
    script = os.path.join(ROOT, "examples", "python", "three_views.py")
    out = subprocess.run([sys.executable, script, path("l_prism.off"), str(tmp_path / "l.pdf")], check=True, capture_output=True, text=True)
    assert (tmp_path / "l.pdf").read_bytes().startswith(b"%PDF")
    assert "18 pieces in the iso view, 15 visible" in out.stdout
