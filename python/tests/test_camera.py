"""A perspective camera with a picture frame (--fov, --frame, --focal): the drawing clipped
exactly to the viewing pyramid, checked against the unframed drawing by exact arithmetic, and
the page fitting the frame."""
import json
import os
import re
from fractions import Fraction

import pytest

import exact_hlr

DATA = os.environ.get("HLR_DATA_DIR", os.path.join(os.path.dirname(__file__), "..", "..", "data"))
ROOM = os.path.join(DATA, "interior_room.yaml")
INSIDE = dict(eye=(1, Fraction(1, 2), Fraction(8, 5)), target=(4, 3, Fraction(6, 5)), up=(0, 0, 1))


def state_at(d, a, seg, t):
    """(visible, clipped, point) of segment `seg` at parameter t, from the exact pieces."""
    for i in range(len(a["segment"])):
        if a["segment"][i] != seg:
            continue
        p = d.piece(i)
        t0, t1 = p["t"]
        if t0 <= t <= t1 and t1 > t0:
            w = (t - t0) / (t1 - t0)
            point = tuple(p["from"][k] + w * (p["to"][k] - p["from"][k]) for k in range(3))
            return p["visible"] and not p["clipped"] and not p["behind_eye"], point
    raise AssertionError(f"segment {seg} has no piece at t = {t}")


def without_camera(tmp_path):
    plain = tmp_path / "room.yaml"
    plain.write_text(re.sub(r"camera:.*", "", open(ROOM).read(), flags=re.S))
    return str(plain)


def side(plane, point):
    a, b, c, e = (Fraction(x) for x in plane)
    return a * point[0] + b * point[1] + c * point[2] + e


@pytest.mark.parametrize("camera", [
    dict(INSIDE, fov=90),                                        # the eye among the walls
    dict(INSIDE, focal=24, sensor=(36, 24), edges="all"),
    dict(eye=(9, -7, 5), target=(3, 2, 1), up=(0, 0, 1), frame=("7/2", 2)),  # from outside, a tight frame
])
def test_the_frame_clips_exactly_what_the_pyramid_holds(camera, tmp_path):
    # Every segment sampled at many exact parameters: seen in the framed drawing exactly where
    # the unframed drawing sees it and the point lies strictly inside the four planes.
    framed = exact_hlr.render(ROOM, **camera)
    plain_kw = {k: v for k, v in camera.items() if k not in ("fov", "focal", "sensor", "frame")}
    plain = exact_hlr.render(without_camera(tmp_path), **plain_kw)
    planes = json.loads(framed.json())["view"]["frame"]["planes"]
    assert len(planes) == 4
    af, ap = framed.arrays(), plain.arrays()
    nseg = int(ap["segment"].max()) + 1
    assert int(af["segment"].max()) + 1 == nseg
    checked = cut = 0
    for seg in range(nseg):
        for k in range(1, 12):
            t = Fraction(k, 12) + Fraction(1, 977)
            seen_plain, p = state_at(plain, ap, seg, t)
            seen_framed, q = state_at(framed, af, seg, t)
            assert p == q
            sides = [side(h, p) for h in planes]
            if any(s == 0 for s in sides):
                continue
            inside = all(s > 0 for s in sides)
            assert seen_framed == (seen_plain and inside), (seg, t)
            checked += 1
            cut += seen_plain and not inside
    assert checked > 300 and cut > 10
    for i in range(len(af["segment"])):  # no visible piece reaches outside
        p = framed.piece(i)
        if p["visible"] and not p["clipped"]:
            assert all(side(h, p["from"]) >= 0 and side(h, p["to"]) >= 0 for h in planes)


def test_the_page_is_the_frame():
    # A 90-degree lens on a 3:2 frame: the picture's half-width 1 and half-height 2/3 at unit
    # distance (to the double), 150 mm wide, so 100 mm high; --focal 18 on full frame is the same.
    d = exact_hlr.render(ROOM, fov=90)
    rect = json.loads(d.json())["view"]["frame"]["rect"]
    assert rect == pytest.approx([-1, -2 / 3, 1, 2 / 3], abs=1e-12)
    assert 'width="150.000mm" height="100.000mm"' in d.svg()
    focal = json.loads(exact_hlr.render(ROOM, focal=18).json())["view"]["frame"]["rect"]
    assert focal == pytest.approx(rect, abs=1e-12)
    square = exact_hlr.render(ROOM, fov=60, aspect="1:1")
    assert 'width="150.000mm" height="150.000mm"' in square.svg()
    both = json.loads(exact_hlr.render(ROOM, fov=90, fov_v=60).json())["view"]["frame"]["rect"]
    assert both == pytest.approx([-1, -3 ** -0.5, 1, 3 ** -0.5], abs=1e-12)


def test_scene_camera_and_options_agree(tmp_path):
    # The scene file's camera (fov 90) and the same camera as options draw the same bytes.
    from_file = exact_hlr.render(ROOM).svg()
    assert exact_hlr.render(without_camera(tmp_path), eye="1,0.5,1.6", target="4,3,1.2", up="0,0,1", fov=90).svg() == from_file


def test_filled_products_in_a_frame(tmp_path):
    # Surfaces, shadows and tone hatching seen through a frame from outside: the exact visible
    # polygons are the unframed ones (the JSON keeps them whole), the lines are clipped exactly,
    # and the page's fills and hatch lines lie inside the frame.
    scene = without_camera(tmp_path)
    eye = dict(eye=(14, -9, 7), target=(3, 2, 1), up=(0, 0, 1))
    plain = json.loads(exact_hlr.render(scene, surfaces=True, **eye).json())
    framed_d = exact_hlr.render(scene, surfaces=True, fov=20, **eye)
    framed = json.loads(framed_d.json())
    assert framed["surfaces"] == plain["surfaces"]
    planes = framed["view"]["frame"]["planes"]
    for p in framed["segments"]:
        if p["visible"] and not p.get("clipped"):
            assert all(side(h, [Fraction(x) for x in p["from"]]) >= 0 and side(h, [Fraction(x) for x in p["to"]]) >= 0 for h in planes)
    assert any(p.get("clipped") for p in framed["segments"])
    for svg in (framed_d.svg(), exact_hlr.render(scene, hatch=True, fov=20, **eye).svg()):
        w, h = (float(x) for x in re.search(r'viewBox="0 0 ([0-9.]+) ([0-9.]+)"', svg).groups())
        numbers = [float(x) for path in re.findall(r' d="([^"]+)"', svg) for x in re.findall(r"-?[0-9]+\.?[0-9]*", path)]
        assert numbers and min(numbers) >= -0.3 and max(numbers[0::2]) <= w + 0.3 and max(numbers[1::2]) <= h + 0.3


def test_frames_that_are_refused(tmp_path):
    with pytest.raises(exact_hlr.OptionError, match="perspective"):
        exact_hlr.render(ROOM, view="iso", fov=60)
    assert "frame" not in json.loads(exact_hlr.render(ROOM, view="iso").json())["view"]  # the scene's lens is for its camera
    with pytest.raises(exact_hlr.OptionError, match="--fov"):
        exact_hlr.render(ROOM, fov=180)
    with pytest.raises(exact_hlr.OptionError, match="one of"):
        exact_hlr.render(ROOM, fov=60, focal=35)
    with pytest.raises(exact_hlr.OptionError, match="shape a frame"):
        exact_hlr.render(ROOM, aspect="16:9", eye=(9, -7, 5))
    bad = tmp_path / "bad.yaml"
    bad.write_text("bodies:\n  - box: {min: [0, 0, 0], max: [1, 1, 1]}\nview:\n  direction: [1, 1, 1]\n  fov: 40\n")
    with pytest.raises(exact_hlr.InputError, match="perspective") as e:
        exact_hlr.render(str(bad))
    assert e.value.line == 4
