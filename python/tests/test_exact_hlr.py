"""Tests of the Python module exact_hlr: exact values, not just "it runs"."""
import json
import os
from fractions import Fraction

import pytest

import exact_hlr

DATA = os.environ.get("HLR_DATA_DIR", os.path.join(os.path.dirname(__file__), "..", "..", "data"))


def path(name):
    return os.path.join(DATA, name)


def test_cube_exact_pieces():
    # The cube [-1, 1]^3 seen along (1, 2, 3) with every edge: the faces x = 1, y = 1, z = 1
    # face the viewer, so the three edges at the vertex (-1, -1, -1) are self-hidden (both of
    # their faces turn away) and the other nine are visible whole.
    d = exact_hlr.render([path("cube.off")], view=(1, 2, 3), edges="all")
    segs = d.segments
    assert len(segs) == 12
    assert d.method == "faces"
    for s in segs:
        assert all(isinstance(c, Fraction) for c in s["from"] + s["to"] + s["t"])
        assert s["t"] == (0, 1)
        at_back_corner = (-1, -1, -1) in (s["from"], s["to"])
        assert s["visible"] == (not at_back_corner)
        assert s["self_hidden"] == at_back_corner
    assert sum(1 for s in segs if s["visible"]) == 9


def test_demo_scene_matches_the_cli_json():
    d = exact_hlr.render(path("demo.yaml"))
    j = json.loads(d.json())
    assert j["stats"]["method"] == "faces"
    assert len(j["segments"]) == len(d.segments)
    first = j["segments"][0]
    assert [Fraction(x) for x in first["from"]] == list(d.segments[0]["from"])
    assert any(s["kind"] == "intersection" for s in d.segments)
    assert d.svg(hidden="dashed").startswith("<?xml")


def test_perspective_and_rational_input():
    d = exact_hlr.render([path("two_boxes.yaml")], eye=("10", -12, Fraction(9)), method="roberts")
    assert d.method == "roberts"
    assert any(not s["visible"] for s in d.segments)


def test_clip_box_exact():
    r = exact_hlr.clip("box:0,2,0,2,0,2", (-1, 1, 1, 3, 1, 1))
    assert r["status"] == "visible"
    assert r["t"] == (Fraction(1, 4), Fraction(3, 4))
    assert r["from"] == (0, 1, 1) and r["to"] == (2, 1, 1)
    assert exact_hlr.clip("box:0,2,0,2,0,2", (3, 3, 3, 4, 4, 4))["status"] == "outside"


def test_explain_roberts_problem():
    problems = os.path.join(DATA, "problems")
    name = sorted(f for f in os.listdir(problems) if f.startswith("roberts"))[0]
    md = exact_hlr.explain(os.path.join(problems, name))
    assert "E" in md and "|" in md
    sol = json.loads(exact_hlr.explain(os.path.join(problems, name), format="json"))
    assert "sections" in sol


def test_errors_are_exceptions():
    with pytest.raises(ValueError, match="contains the eye"):
        exact_hlr.render([path("cube.off")], eye=(0, 0, Fraction(1, 2)), target=(0, 0, -1))
    with pytest.raises(ValueError, match="cannot open"):
        exact_hlr.render([path("none.off")])
    with pytest.raises(ValueError):
        exact_hlr.render([path("cube.off")], method="painter")


def test_plot_strokes_and_formats():
    # The cube's front view: one closed square (the back edges lie under the front ones, the
    # four edges along the view are points), and the same sheet in every format.
    d = exact_hlr.render([path("cube.off")], view=(0, 0, 1))
    layers = d.strokes(hidden="dashed")
    assert list(layers) == ["visible-silhouette"]
    (square,) = layers["visible-silhouette"]
    assert square.shape == (5, 2) and square.dtype == "float64" and tuple(square[0]) == tuple(square[-1])
    assert sorted(set(map(tuple, square.tolist()))) == [(-1.0, -1.0), (-1.0, 1.0), (1.0, -1.0), (1.0, 1.0)]
    assert d.plot("pdf", page="A4").startswith(b"%PDF")
    assert d.plot("png").startswith(b"\x89PNG")
    assert b"AC1015" in d.plot("dxf")
    assert b'inkscape:label="1 visible-silhouette"' in d.plot("svg", scale="10:1", page="A4")


def test_visible_surfaces_exact_and_both_methods_agree():
    # The cube [-1, 1]^3 seen along (1, 1, 1): three faces seen whole, each a square of exact
    # corners; in the picture's exact units each has area 8 and together 24. The course's
    # Weiler-Atherton algorithm gives the same.
    d = exact_hlr.render([path("cube.off")], view=(1, 1, 1), surfaces=True)
    faces = d.surfaces
    assert [(f["body"], f["face"], f["side"]) for f in faces] == [(0, 1, "front"), (0, 3, "front"), (0, 5, "front")]
    for f in faces:
        (poly,) = f["polygons"]
        assert poly["holes"] == [] and poly["area"] == Fraction(8)
        assert all(isinstance(c, Fraction) for p in poly["outer"] for c in p)
        assert f["shade"].startswith("#") and len(f["shade"]) == 7
    assert (1, -1, -1) in faces[0]["polygons"][0]["outer"]
    wa = exact_hlr.render([path("demo.yaml")], method="weiler-atherton")
    fast = exact_hlr.render([path("demo.yaml")], surfaces=True)
    area = lambda dr: {(f["body"], f["face"]): f["area"] for f in dr.surfaces}
    assert area(wa) == area(fast) and len(area(fast)) == 14
    assert b'id="surfaces"' in fast.plot("svg")
    assert json.loads(fast.json())["surfaces"]["stats"]["faces_seen"] == 14
    assert exact_hlr.render([path("cube.off")]).surfaces is None


def test_priority_list_paints_back_to_front():
    # The painter's list of the demo scene: 14 faces, 7 cuts: 10 faces painted whole and 11 parts,
    # every polygon an exact list of 3D corners; the JSON carries the same order.
    d = exact_hlr.render([path("demo.yaml")], method="priority")
    order = d.priority
    assert len(order) == 21 and sum(p["cut"] for p in order) == 11
    assert all(isinstance(c, Fraction) for p in order for q in p["corners"] for c in q)
    js = json.loads(d.json())["priority"]
    assert [(o["body"], o["face"]) for o in js["order"]] == [(p["body"], p["face"]) for p in order]
    assert js["stats"]["cuts"] == 7
    assert exact_hlr.render([path("cube.off")]).priority is None


def test_shadows_on_the_ground():
    # The unit cube on the ground under a light toward (1, 1, 1), seen from above: the shadow
    # seen on the ground is the hull of the two squares less the cube's own footprint, area 2.
    import os, tempfile
    with tempfile.TemporaryDirectory() as d:
        scene = os.path.join(d, "s.yaml")
        with open(scene, "w") as f:
            f.write("bodies:\n  - box: {min: [0, 0, 0], max: [1, 1, 1]}\nground: z = 0\n"
                    "view: {direction: [0, 0, 1], up: [0, 1, 0]}\nlight: [1, 1, 1]\n")
        dr = exact_hlr.render([scene], shadows=True)
        sh = json.loads(dr.json())["shadows"]
        ground = [f for f in sh["faces"] if f["body"] == 1]
        assert len(ground) == 1 and Fraction(ground[0]["shadow_area"]) == 2


def test_lines_seen_through_glass():
    # The demo's glass box shows its back edges and the block behind it as a class of their own.
    dr = exact_hlr.render([path("transparency_demo.yaml")])
    pieces = json.loads(dr.json())["segments"]
    through = [p for p in pieces if p.get("through")]
    assert through and all(not p["visible"] for p in through)
    assert {p["body"] for p in through} == {0, 1, 2}
    assert any(name.startswith("through-") for name in dr.strokes())
    hidden = exact_hlr.render([path("transparency_demo.yaml")], through=False)
    assert not any(p.get("through") for p in json.loads(hidden.json())["segments"])


def test_raster_algorithms_agree_and_centres_are_exact():
    images = [exact_hlr.raster(path("demo.yaml"), algorithm=a, width=64, height=40)
              for a in ("zbuffer", "scanline", "warnock", "raytrace")]
    faces = images[0].faces()
    assert len(faces) == 40 and len(faces[0]) == 64
    assert all(im.faces() == faces for im in images[1:])
    assert sum(f is not None for row in faces for f in row) > 500
    assert images[0].png()[:8] == b"\x89PNG\r\n\x1a\n"
    c = images[0].centre(10, 7)
    assert all(isinstance(x, Fraction) for x in c)
    cam = json.loads(images[0].camera())
    o, r, d = ([Fraction(v) for v in cam[k]] for k in ("origin", "right", "down"))
    assert tuple(o[k] + Fraction(21, 2) * r[k] + Fraction(15, 2) * d[k] for k in range(3)) == c


def test_repaired_mesh_keeps_the_input_face_numbers():
    # The seam cube's face 12 is a zero-area triangle the loader removes; its faces 11 and 13
    # (the front, z = 1) keep their numbers in the surfaces, the painter's list and the raster.
    seam = path("degenerate/meshes/zero_area_seam.off")
    d = exact_hlr.render([seam], surfaces=True)
    assert sorted(f["face"] for f in d.surfaces) == [11, 13]
    body = json.loads(d.json())["bodies"][0]
    assert body["faces"][12] == "removed" and body["removed_faces"] == [12] and len(body["faces"]) == 14
    painted = {p["face"] for p in exact_hlr.render([seam], method="priority").priority}
    assert 13 in painted and 12 not in painted
    seen = {f for row in exact_hlr.raster(seam, width=16, height=16).faces() for f in row if f is not None}
    assert seen == {(0, 11), (0, 13)}


def test_section_caps_and_hatch_in_the_json():
    d = json.loads(exact_hlr.render(path("house.yaml"), section=["z<1.2"], view=[0, 0, 1], up=[0, 1, 0]).json())
    assert d["section"]["planes"] == [["0", "0", "1", "-6/5"]]
    assert d["section"]["caps"] and d["section"]["hatch"]
    assert any(s["kind"] == "cut" for s in d["segments"])
    with pytest.raises(ValueError):
        exact_hlr.render(path("house.yaml"), section=["w<1"])


def test_own_lines_hidden_by_the_bodies():
    # The cube [-1, 1]^3 seen from +z: a line through it along x is hidden inside it, seen
    # outside; Fractions and strings are exact.
    d = exact_hlr.render(path("cube.off"), view=(0, 0, 1), lines=[[(-3, 0, 0), (Fraction(3), "0", 0)]])
    got = sorted((s["from"][0], s["to"][0], s["visible"]) for s in d.segments if s["kind"] == "polyline")
    assert got == [(-3, -1, True), (-1, 1, False), (1, 3, True)]
    with pytest.raises(ValueError):
        exact_hlr.render(path("cube.off"), lines=[[(0, 0, 0)]])


def hlr_cli(*args):
    import subprocess
    exe = os.environ.get("HLR_BIN", "hlr")
    return subprocess.run([exe, *args], check=True, capture_output=True).stdout


@pytest.mark.parametrize("name,kwargs,flags", [
    ("house.yaml", {"section": ["y>4.5"]}, ["--section", "y>4.5"]),
    ("house.yaml", {"cutaway": ["x>4", "y>3"], "surfaces": True}, ["--cutaway", "x>4", "--cutaway", "y>3", "--surfaces"]),
    ("demo.yaml", {"surfaces": True}, ["--surfaces"]),
    ("demo.yaml", {}, []),
    ("two_boxes.yaml", {"shadows": True}, ["--shadows"]),
])
def test_svg_is_the_cli_svg_byte_for_byte(name, kwargs, flags, tmp_path):
    # One output stage: Drawing.svg() and `hlr render x -o a.svg` write the same bytes.
    out = tmp_path / "a.svg"
    hlr_cli("render", path(name), *flags, "-o", str(out), "--quiet")
    assert exact_hlr.render(path(name), **kwargs).svg().encode() == out.read_bytes()
    dashed = tmp_path / "b.svg"
    hlr_cli("render", path(name), *flags, "--hidden", "dashed", "--width", "90", "--stroke", "0.5", "-o", str(dashed), "--quiet")
    got = exact_hlr.render(path(name), **kwargs).svg(hidden="dashed", width=90, stroke=0.5)
    assert got.encode() == dashed.read_bytes()


def test_plot_is_the_cli_picture_byte_for_byte(tmp_path):
    for fmt in ("svg", "dxf", "png"):
        out = tmp_path / ("p." + fmt)
        hlr_cli("render", path("demo.yaml"), "--hidden", "dashed", "--page", "A4", "--scale", "10:1", "-o", str(out), "--quiet")
        got = exact_hlr.render(path("demo.yaml")).plot(fmt, hidden="dashed", page="A4", scale="10:1")
        assert got == out.read_bytes(), fmt
