// Views that share their work (io/pipeline/render.hpp ViewShare, algorithms/hlr/face_occluders.hpp
// FaceRouteShare; docs/design.md, "Views that share their work"): every view of a set drawn
// with the work of the views before it gives exactly the drawing (every segment, every exact
// piece, the notes, the counters) that the same view gives alone. The scenes hold the places
// the shared work could get wrong: interpenetrating bodies (intersection lines kept), an
// inside-out solid and an inside-out component (turned once, seen from every side), an open
// surface, a touching tetrahedron, polygon faces, crease lines that go on (OpenSCAD's cone),
// coordinates on the 64-bit, multi-limb and GMP paths; views along faces and edges, a
// perspective view (which shares nothing) between orthographic ones, and options that change
// between views (the crease angle, every edge classified or not).
#include <gtest/gtest.h>

#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "algorithms/hlr/face_occluders.hpp"
#include "io/pipeline/render.hpp"
#include "io/readers/scene.hpp"
#include "io/writers/json_writer.hpp"

namespace hlr {
namespace {

Polyhedron turned(const Polyhedron& p) {
  std::vector<Face> faces = p.faces();
  for (Face& f : faces) std::reverse(f.begin(), f.end());
  return Polyhedron(p.vertices(), faces);
}

Polyhedron scaled(const Polyhedron& p, const Rational& k) {
  std::vector<Point3> v;
  for (const Point3& q : p.vertices()) v.emplace_back(q.x() * k, q.y() * k, q.z() * k);
  return Polyhedron(v, p.faces());
}

// A box with one face left out: an open surface.
Polyhedron open_box(const Point3& a, const Point3& b) {
  Polyhedron box = make_box(a, b);
  std::vector<Face> faces(box.faces().begin() + 1, box.faces().end());
  return Polyhedron(box.vertices(), faces);
}

// Two boxes in one body, the inner one inside out (a cavity stays as it is; this one is not
// inside the other, so it is turned) - then the whole body as one mesh.
Polyhedron two_shells() {
  Polyhedron a = make_box(Point3(5, 0, 0), Point3(6, 1, 1)), b = turned(make_box(Point3(7, 0, 0), Point3(8, 1, 1)));
  std::vector<Point3> v = a.vertices();
  std::vector<Face> f = a.faces();
  for (const Point3& q : b.vertices()) v.push_back(q);
  for (Face g : b.faces()) {
    for (int& i : g) i += static_cast<int>(a.vertices().size());
    f.push_back(g);
  }
  return Polyhedron(v, f);
}

Scene mixed_scene(const Rational& k) {
  Scene s;
  s.file = "(test)";
  auto add = [&](const std::string& name, Polyhedron p) {
    s.bodies.push_back(SceneBody{name, "(test)", scaled(p, k), identity_transform(), {}, {}});
  };
  add("a", make_box(Point3(0, 0, 0), Point3(2, 2, 2)));
  add("b", make_box(Point3(1, 1, Rational(1, 2)), Point3(3, Rational(5, 2), Rational(3, 2))));  // through a
  add("inside-out", turned(make_box(Point3(-3, 0, 0), Point3(-2, 1, 3))));
  add("open", open_box(Point3(0, -3, 0), Point3(1, -2, 1)));
  add("tetra", Polyhedron({Point3(2, 0, 0), Point3(3, 0, 0), Point3(2, 1, 0), Point3(2, 0, 1)}, {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}));
  add("shells", two_shells());
  return s;
}

std::vector<ViewRequest> views() {
  std::vector<ViewRequest> v;
  for (const Vector3& d : {Vector3(1, 1, 1), Vector3(-1, Rational(13, 10), Rational(17, 10)), Vector3(0, 0, 1), Vector3(1, 0, 0), Vector3(1, 1, 0),
                           Vector3(-2, -1, Rational(1, 3))})
    v.push_back(ViewRequest{d, {}, {}, {}});
  // The eye among the bodies, then orthographic again.
  v.insert(v.begin() + 3, ViewRequest{{}, Point3(Rational(5, 2), Rational(-1, 2), Rational(7, 4)), Point3(1, 1, 1), {}});
  return v;
}

// The whole drawing as the JSON writer puts it, and the notes.
std::string text(const RenderResult& r) {
  std::string out = to_json(r.names, r.drawing, r.camera);
  for (const std::string& n : r.notes) out += "\nnote: " + n;
  return out;
}

// The first line where two texts differ, both versions ("" when they are the same).
std::string first_difference(const std::string& a, const std::string& b) {
  std::istringstream x(a), y(b);
  std::string p, q;
  for (int line = 1;; ++line) {
    const bool more_a = static_cast<bool>(std::getline(x, p)), more_b = static_cast<bool>(std::getline(y, q));
    if (!more_a && !more_b) return "";
    if (more_a != more_b || p != q)
      return "line " + std::to_string(line) + ":\n shared: " + (more_a ? p : "(end)") + "\n alone:  " + (more_b ? q : "(end)");
  }
}

// The drawing's text, or the error a view gives (an eye inside a solid).
std::string drawn(const std::vector<Scene>& scenes, const RenderOptions& o) {
  try {
    return text(render(scenes, o));
  } catch (const std::exception& e) {
    return std::string("error: ") + e.what();
  }
}

// Each view alone, then all of them through one share: the same texts. Returns the number
// policy the shared work was done on (exact_int.hpp: 0 64-bit, 1 128-bit, 2 multi-limb, 3 GMP).
int check_alike(const std::vector<Scene>& scenes, const std::vector<RenderOptions>& options, const std::string& what) {
  auto share = std::make_shared<ViewShare>();
  for (std::size_t i = 0; i < options.size(); ++i) {
    SCOPED_TRACE(what + ", view " + std::to_string(i));
    const std::string alone = drawn(scenes, options[i]);
    RenderOptions o = options[i];
    o.share = share;
    const std::string together = drawn(scenes, o);
    EXPECT_EQ(first_difference(together, alone), "");
  }
  EXPECT_TRUE(share->scenes && share->faces && share->faces->prepared) << what << ": no view shared its work";
  return share->faces ? share->faces->policy : -1;
}

std::vector<RenderOptions> each_view(const RenderOptions& base) {
  std::vector<RenderOptions> out;
  for (const ViewRequest& v : views()) {
    RenderOptions o = base;
    o.view = v;
    out.push_back(o);
  }
  return out;
}

TEST(ViewShare, EveryViewDrawsAsItDoesAlone) {
  // 1: the 64-bit path; 2^-70: multi-limb; 2^-200: GMP.
  const std::pair<Rational, int> scales[] = {{Rational(1), 0}, {Rational(1, mpz_class(1) << 70), 2}, {Rational(1, mpz_class(1) << 200), 3}};
  for (const auto& [k, policy] : scales) {
    const std::vector<Scene> scenes{mixed_scene(k)};
    RenderOptions feature;
    EXPECT_EQ(check_alike(scenes, each_view(feature), "features at scale " + k.get_str()), policy);
    RenderOptions all;
    all.lines.edges = EdgeSelection::All;
    EXPECT_EQ(check_alike(scenes, each_view(all), "every edge at scale " + k.get_str()), policy);
  }
}

// Random boxes and tetrahedra on a small integer grid (touching, coplanar, nested and
// interpenetrating often), some turned inside out or left open, seen along axes, edges and
// general directions and from eyes among them.
TEST(ViewShare, RandomScenesDrawAsAlone) {
  std::mt19937 rng(20261204);
  auto coord = [&](int hi) { return Rational(static_cast<long>(rng() % (hi + 1))); };
  for (int scene = 0; scene < 40; ++scene) {
    Scene s;
    s.file = "(test)";
    const int n = 2 + static_cast<int>(rng() % 4);
    for (int b = 0; b < n; ++b) {
      const auto make = [&]() -> Polyhedron {
        if (rng() % 2) {
          const Point3 lo(coord(3), coord(3), coord(3));
          return make_box(lo, Point3(lo.x() + 1 + coord(2), lo.y() + 1 + coord(2), lo.z() + 1 + coord(2)));
        }
        std::vector<Point3> v;
        do {
          v = {Point3(coord(4), coord(4), coord(4)), Point3(coord(4), coord(4), coord(4)), Point3(coord(4), coord(4), coord(4)),
               Point3(coord(4), coord(4), coord(4))};
        } while (dot(v[1] - v[0], cross(v[2] - v[0], v[3] - v[0])) == 0);
        if (dot(v[1] - v[0], cross(v[2] - v[0], v[3] - v[0])) > 0) std::swap(v[1], v[2]);
        return Polyhedron(v, {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}});
      };
      Polyhedron p = make();
      const unsigned kind = rng() % 6;
      if (kind == 0) p = turned(p);
      if (kind == 1) p = Polyhedron(p.vertices(), std::vector<Face>(p.faces().begin() + 1, p.faces().end()));
      s.bodies.push_back(SceneBody{"b" + std::to_string(b), "(test)", p, identity_transform(), {}, {}});
    }
    std::vector<RenderOptions> options;
    for (int v = 0; v < 5; ++v) {
      RenderOptions o;
      if (rng() % 2) o.lines.edges = EdgeSelection::All;
      if (v == 2) {
        auto third = [&] { return Rational(static_cast<long>(rng() % 16), 3); };
        o.view.eye = Point3(third(), third(), third());
        o.view.target = Point3(2, 2, 2);
      } else {
        static const int dirs[][3] = {{0, 0, 1}, {1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {-1, 2, 3}, {2, -3, 1}, {0, 1, -1}};
        const auto& d = dirs[rng() % 7];
        o.view.direction = Vector3(d[0], d[1], d[2]);
      }
      options.push_back(o);
    }
    check_alike({s}, options, "random scene " + std::to_string(scene));
  }
}

TEST(ViewShare, OptionsThatChangeBetweenViewsAreHeeded) {
  const std::vector<Scene> scenes{load_input(std::string(HLR_DATA_DIR) + "/openscad/example002.off", "")};
  std::vector<RenderOptions> options = each_view(RenderOptions{});
  for (std::size_t i = 0; i < options.size(); ++i) {
    options[i].lines.crease_degrees = i % 3 == 0 ? 30 : i % 3 == 1 ? 60 : 10;
    options[i].lines.continue_creases = i % 4 != 2;
    options[i].lines.intersections = i % 2 == 0;
    if (i == 4) options[i].lines.edges = EdgeSelection::All, options[i].lines.classify_all = true;
  }
  check_alike(scenes, options, "example002");
}

TEST(ViewShare, SectionsAndFilledViewsMakeTheirOwn) {
  // A section cuts the bodies: it neither takes nor leaves the shared scenes; the plain views
  // around it still draw as alone.
  const std::vector<Scene> scenes{mixed_scene(1)};
  std::vector<RenderOptions> options = each_view(RenderOptions{});
  options[1].section = {Plane(1, 0, 0, -1)};  // x <= 1 kept
  options[5].surfaces = true;
  check_alike(scenes, options, "with a section and surfaces");
}

}  // namespace
}  // namespace hlr
