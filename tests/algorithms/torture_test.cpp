// The torture suite: seeded random scenes in the hard places, every piece of
// every route checked by exact ray casting (ray_oracle.hpp), and the routes compared with each
// other. The test command runs a few hundred scenes; scripts/torture.sh runs thousands
// (HLR_TORTURE_SCENES, HLR_TORTURE_SEED).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <random>
#include <sstream>
#include <tuple>

#include "algorithms/hlr/face_occluders.hpp"
#include "algorithms/hlr/roberts.hpp"
#include "io/pipeline/render.hpp"
#include "io/readers/mesh_reader.hpp"
#include "io/readers/scene.hpp"
#include "io/views/view_choice.hpp"
#include "support/compact.hpp"
#include "support/ray_oracle.hpp"

using namespace hlr;
using namespace hlr::test;

namespace {

long env_long(const char* name, long fallback) {
  const char* v = std::getenv(name);
  return v && *v ? std::atol(v) : fallback;
}

struct Generator {
  std::mt19937 rng;
  explicit Generator(unsigned seed) : rng(seed) {}
  int uniform(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); }
  Rational q(int lo, int hi, int den) {
    Rational r(uniform(lo * den, hi * den), den);
    r.canonicalize();
    return r;
  }

  // A box in [0, 12]^3, sometimes a thin slab.
  Polyhedron box() {
    Rational lo[3], hi[3];
    int thin = uniform(0, 3) == 0 ? uniform(0, 2) : -1;
    for (int k = 0; k < 3; ++k) {
      lo[k] = q(0, 10, 4);
      Rational size = k == thin ? Rational(1, uniform(4, 16)) : q(1, 4, 2);
      size.canonicalize();
      hi[k] = lo[k] + size;
    }
    return make_box(Point3(lo[0], lo[1], lo[2]), Point3(hi[0], hi[1], hi[2]));
  }
  // A tetrahedron in [0, 12]^3 with non-zero volume, faces outward.
  Polyhedron tetra() {
    for (;;) {
      std::vector<Point3> v;
      for (int i = 0; i < 4; ++i) v.push_back(Point3(q(0, 12, 3), q(0, 12, 3), q(0, 12, 3)));
      std::vector<Face> f = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
      if (six_signed_volume(v, f) == 0) continue;
      return Polyhedron(v, orient_faces(v, f));
    }
  }
};

// Strictly outside every body (some inward plane negative at the point), or on a surface
// (`allow_surface`: no plane negative for one body, but one zero).
bool eye_ok(const std::vector<std::vector<OraclePlane>>& bodies, const Point3& e, bool allow_surface) {
  for (const auto& b : bodies) {
    bool outside = false, on = false;
    for (const OraclePlane& h : b) {
      Rational v = h.at(e.x(), e.y(), e.z());
      outside = outside || v < 0;
      on = on || v == 0;
    }
    if (!outside && !(allow_surface && on)) return false;
  }
  return true;
}

struct Result {
  Tally faces, roberts;
  long scenes = 0, route_mismatches = 0;
  long gmp_scenes = 0;  // the per-face route ran on GMP integers
};

// The pieces of every edge of both routes must be the same.
void compare_routes(const LineDrawing& a, const LineDrawing& b, Result& res, const std::string& what) {
  std::map<std::tuple<int, int, int>, const Segment*> by_edge;
  for (const Segment& s : b.segments)
    if (s.kind == Segment::Kind::Edge) by_edge[{s.body, s.v0, s.v1}] = &s;
  for (const Segment& s : a.segments) {
    if (s.kind != Segment::Kind::Edge) continue;
    auto it = by_edge.find({s.body, s.v0, s.v1});
    if (it == by_edge.end()) continue;
    const Segment& g = *it->second;
    bool same = g.pieces.size() == s.pieces.size();
    for (std::size_t i = 0; same && i < s.pieces.size(); ++i)
      same = g.pieces[i].t0 == s.pieces[i].t0 && g.pieces[i].t1 == s.pieces[i].t1 && g.pieces[i].visible == s.pieces[i].visible;
    if (!same) {
      ++res.route_mismatches;
      ADD_FAILURE() << what << ": edge " << s.from() << " - " << s.to() << " of body " << s.body << ": the routes differ";
    }
  }
}

// The same scene with every body whose vertices have a compact form in a compact store
// (kernel/point_store.hpp) draws the same pieces as with exact points.
void compare_compact(const std::vector<Polyhedron>& bodies, const Camera& cam, const LineOptions& opt, const LineDrawing& f,
                     const std::string& what) {
  std::vector<Polyhedron> compact;
  for (const Polyhedron& b : bodies) compact.push_back(hlr::test::compact_copy(b).value_or(b));
  std::vector<const Polyhedron*> ptrs;
  for (const Polyhedron& b : compact) ptrs.push_back(&b);
  const LineDrawing c = face_occluders(ptrs, cam, opt);
  bool same = c.segments.size() == f.segments.size();
  for (std::size_t i = 0; same && i < c.segments.size(); ++i) {
    const Segment &s = c.segments[i], &t = f.segments[i];
    same = s.v0 == t.v0 && s.v1 == t.v1 && s.body == t.body && s.pieces.size() == t.pieces.size();
    for (std::size_t k = 0; same && k < s.pieces.size(); ++k) same = s.pieces[k].t1 == t.pieces[k].t1 && s.pieces[k].visible == t.pieces[k].visible;
  }
  if (!same) ADD_FAILURE() << what << ": compact vertices draw differently";
}

void run_scene(const std::vector<Polyhedron>& bodies, const Camera& cam, Result& res, const std::string& what) {
  OracleScene scene(bodies);
  const auto& ptrs = scene.ptrs;
  const auto& planes = scene.planes;
  LineOptions opt;
  opt.edges = EdgeSelection::All;
  opt.intersections = false;  // the oracle samples edges; intersection lines have their own tests
  LineDrawing f = face_occluders(ptrs, cam, opt);
  RobertsResult r = roberts(ptrs, cam, opt);
  ++res.scenes;
  res.gmp_scenes += !f.stats.faces->integer_path;
  long before = res.faces.disagreements;
  sample_check(f, planes, cam, res.faces, ("faces, " + what).c_str());
  sample_check(r, planes, cam, res.roberts, ("roberts, " + what).c_str());
  const char* only = std::getenv("HLR_TORTURE_DUMP_SEED");
  bool wanted = only && what.rfind("seed " + std::string(only) + ",", 0) == 0;
  if (res.faces.disagreements != before) ADD_FAILURE() << "scene: " << what;
  if (res.faces.disagreements != before || wanted) {
    if (std::getenv("HLR_TORTURE_DUMP") || wanted) {  // the scene as a YAML scene file
      std::cout << "# " << what << "\nbodies:\n";
      for (std::size_t b = 0; b < bodies.size(); ++b) {
        std::cout << "  - name: b" << b << "\n    vertices: [";
        for (std::size_t v = 0; v < bodies[b].num_vertices(); ++v) {
          const Point3& q = bodies[b].vertices()[v];
          std::cout << (v ? ", " : "") << "[" << to_string(q.x()) << ", " << to_string(q.y()) << ", " << to_string(q.z()) << "]";
        }
        std::cout << "]\n    faces: [";
        for (std::size_t f = 0; f < bodies[b].num_faces(); ++f) {
          std::cout << (f ? ", " : "") << "[";
          for (std::size_t k = 0; k < bodies[b].faces()[f].size(); ++k) std::cout << (k ? ", " : "") << bodies[b].faces()[f][k];
          std::cout << "]";
        }
        std::cout << "]\n";
      }
      auto v3 = [](const auto& p) { return "[" + to_string(p[0]) + ", " + to_string(p[1]) + ", " + to_string(p[2]) + "]"; };
      if (cam.perspective) std::cout << "view: {eye: " << v3(cam.eye) << ", target: " << v3(cam.target) << "}\n";
      else std::cout << "view: {direction: " << v3(cam.direction) << "}\n";
    }
  }
  compare_routes(r, f, res, what);
  compare_compact(bodies, cam, opt, f, what);
}

std::string describe(unsigned seed, const Camera& c) {
  return "seed " + std::to_string(seed) + (c.perspective ? ", eye " + to_string(c.eye) + ", target " + to_string(c.target)
                                                         : ", view " + to_string(c.direction));
}

// Perspective with the eye among the bodies (walk-through views), and orthographic views along
// axes and edges: five boxes (some thin slabs) and a tetrahedron; with `far_bits`, also a box
// 2^-far_bits wide far from the others, whose coordinates put the whole scene on the
// multi-limb path (70) or on GMP integers (200), where the other bodies stay on the grid of
// small denominators (face_engine.hpp, Prepared::on_grid) and the far box does not; with
// `eye_off_grid`, half of the free eyes moved by 2^-90 (off that grid); with `off_grid`, only
// orthographic views, and two of the boxes moved by 2^-90 along (1, 1, 1), off the grid: their
// triangles hide as occluders made from each corner's own integers (Engine::local_planes) and
// their sides close by the doubles' filter or exactly (Engine::wedge_side).
void eye_among_the_bodies(long n, unsigned seed0, int far_bits, bool eye_off_grid = false, bool off_grid = false) {
  Result res;
  for (long i = 0; i < n; ++i) {
    unsigned seed = seed0 * 100003u + static_cast<unsigned>(i);
    Generator g(seed);
    std::vector<Polyhedron> bodies;
    for (int k = 0; k < 5; ++k) bodies.push_back(g.box());
    bodies.push_back(g.tetra());
    if (far_bits) {
      Rational e = 1;
      mpq_div_2exp(e.get_mpq_t(), e.get_mpq_t(), static_cast<mp_bitcnt_t>(far_bits));
      bodies.push_back(make_box(Point3(-40, -40, -40), Point3(Rational(-40) + e, Rational(-40) + e, Rational(-40) + e)));
    }
    if (off_grid) {
      Rational e = 1;
      mpq_div_2exp(e.get_mpq_t(), e.get_mpq_t(), 90);
      for (int k = 0; k < 2; ++k) {
        std::vector<Point3> moved;
        for (const Point3& p : bodies[k].vertices()) moved.push_back(Point3(p.x() + e, p.y() + e, p.z() + e));
        bodies[k] = Polyhedron(std::move(moved), bodies[k].faces());
      }
    }
    std::vector<std::vector<OraclePlane>> planes;
    for (const auto& b : bodies) planes.push_back(oracle_planes(b));
    Camera cam;
    int kind = off_grid ? 3 : static_cast<int>(i % 5);
    if (kind == 4) {  // the eye on the surface of a box: on a face, an edge or a vertex
      Point3 eye;
      for (;;) {  // until the point is inside no other body
        const Polyhedron& b = bodies[g.uniform(0, 4)];
        const Point3 &lo = b.vertices()[0], &hi = b.vertices()[7];
        Rational c[3];
        int on = g.uniform(1, 3);  // how many coordinates lie on the box's bounds
        for (int k = 0; k < 3; ++k) {
          Rational u(g.uniform(1, 7), 8);
          u.canonicalize();
          c[k] = k < on ? (g.uniform(0, 1) ? lo[k] : hi[k]) : lo[k] + u * (hi[k] - lo[k]);
        }
        eye = Point3(c[0], c[1], c[2]);
        if (eye_ok(planes, eye, true)) break;
      }
      Point3 target;
      do target = Point3(g.q(0, 12, 2), g.q(0, 12, 2), g.q(0, 12, 2));
      while (target == eye);
      cam = make_perspective(eye, target);
    } else if (kind == 3) {  // orthographic along an axis, a face diagonal or a generic direction
      static const int dirs[][3] = {{0, 0, 1}, {1, 0, 0}, {0, -1, 0}, {1, 1, 0}, {1, 0, -1}, {1, 2, 3}, {-2, 1, 1}};
      const int* d = dirs[g.uniform(0, 6)];
      cam = make_orthographic(Vector3(d[0], d[1], d[2]));
    } else {
      Point3 eye;
      for (int tries = 0;; ++tries) {
        eye = Point3(g.q(-2, 14, 4), g.q(-2, 14, 4), g.q(-2, 14, 4));
        if (kind == 2) {  // on the plane of a face of some box
          int b = g.uniform(0, 4), k = g.uniform(0, 2);
          Rational c[3] = {eye.x(), eye.y(), eye.z()};
          c[k] = bodies[b].vertices()[g.uniform(0, 1) ? 0 : 7][k];
          eye = Point3(c[0], c[1], c[2]);
        } else if (eye_off_grid && kind == 0) {
          Rational e = 1;
          mpq_div_2exp(e.get_mpq_t(), e.get_mpq_t(), 90);
          eye = Point3(eye.x() + e, eye.y(), eye.z());
        }
        if (eye_ok(planes, eye, false)) break;
      }
      Point3 target;
      do target = Point3(g.q(0, 12, 2), g.q(0, 12, 2), g.q(0, 12, 2));
      while (target == eye);
      cam = make_perspective(eye, target);
    }
    run_scene(bodies, cam, res, describe(seed, cam));
  }
  std::cout << "[torture] " << res.scenes << " scenes; faces: " << res.faces.samples << " samples, " << res.faces.hidden_samples
            << " hidden, " << res.faces.disagreements << " wrong; roberts: " << res.roberts.disagreements << " wrong; "
            << res.route_mismatches << " edges where the routes differ\n";
  EXPECT_EQ(res.faces.disagreements, 0);
  EXPECT_EQ(res.roberts.disagreements, 0);
  EXPECT_EQ(res.route_mismatches, 0);
  EXPECT_GT(res.faces.hidden_samples, res.faces.samples / 10);
  EXPECT_EQ(res.gmp_scenes, far_bits > 150 ? res.scenes : 0);
}

}  // namespace

TEST(Torture, EyeAmongTheBodies) {
  eye_among_the_bodies(env_long("HLR_TORTURE_SCENES", 200), static_cast<unsigned>(env_long("HLR_TORTURE_SEED", 12)), 0);
}

// The same scenes on the multi-limb path (its filters: signs known from the vertices on a plane
// or from doubles, exact planes remade on demand).
TEST(Torture, EyeAmongTheBodiesOnTheMultiLimbPath) {
  eye_among_the_bodies(env_long("HLR_TORTURE_SCENES", 200) / 2, static_cast<unsigned>(env_long("HLR_TORTURE_SEED", 12)), 70);
}

// And on GMP integers, most vertices on the grid of small denominators: their normals and
// side planes from the grid's small integers, the filters on doubles scaled by a power of two
// (face_engine.hpp); the eye on the grid or, for half of the free eyes, just off it.
TEST(Torture, EyeAmongTheBodiesOnGmpWithAGrid) {
  eye_among_the_bodies(env_long("HLR_TORTURE_SCENES", 200) / 2, static_cast<unsigned>(env_long("HLR_TORTURE_SEED", 12)) + 1, 200, true);
}

// GMP integers in orthographic views with two boxes off the grid (see eye_among_the_bodies).
TEST(Torture, OffGridBoxesOnGmpInOrthographicViews) {
  eye_among_the_bodies(env_long("HLR_TORTURE_SCENES", 200) / 4, static_cast<unsigned>(env_long("HLR_TORTURE_SEED", 12)) + 2, 200, false, true);
}

// The same two boxes off the grid on the multi-limb path (no far box: every coordinate below
// 2^125), where their normals and occluder planes are made in fixed widths (fixed_int.hpp).
TEST(Torture, OffGridBoxesOnTheMultiLimbPathInOrthographicViews) {
  eye_among_the_bodies(env_long("HLR_TORTURE_SCENES", 200) / 4, static_cast<unsigned>(env_long("HLR_TORTURE_SEED", 12)) + 3, 0, false, true);
}

// Every scene the torture suite (or a report) found wrong once, as a named file in
// data/degenerate/: both routes checked by the oracle and against each other.
TEST(Torture, DegenerateFiles) {
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(HLR_DATA_DIR) + "/degenerate")) {
    if (entry.path().extension() != ".yaml") continue;
    Scene scene = load_scene(entry.path().string());
    std::vector<Polyhedron> bodies;
    std::vector<const Polyhedron*> ptrs;
    for (const SceneBody& b : scene.bodies) bodies.push_back(b.body);
    for (const Polyhedron& p : bodies) ptrs.push_back(&p);
    Camera cam = choose_camera({}, &scene.view, ptrs);
    Result res;
    run_scene(bodies, cam, res, entry.path().filename().string());
    EXPECT_EQ(res.faces.disagreements, 0) << entry.path();
    EXPECT_EQ(res.roberts.disagreements, 0) << entry.path();
    EXPECT_EQ(res.route_mismatches, 0) << entry.path();
    EXPECT_GT(res.faces.hidden_samples, 0) << entry.path() << ": the scene hides something";
    ++files;
  }
  EXPECT_GE(files, 6);
}

namespace {

// One mesh made of disjoint boxes (the hard families): some components inside out, some
// faces split into two triangles with a zero-area triangle on the seam, sometimes a bow-tie
// face. The drawing through the render pipeline must agree with exact ray casting against the
// clean boxes; a bow-tie must be refused.
struct DefectMesh {
  std::vector<Point3> vs;
  std::vector<Face> faces;
  std::vector<std::string> defects;
  bool bow_tie = false;
  void add_box(const Polyhedron& box, bool inside_out, bool seam, bool bowtie) {
    const int base = static_cast<int>(vs.size());
    for (const Point3& p : box.vertices()) vs.push_back(p);
    for (std::size_t f = 0; f < box.faces().size(); ++f) {
      Face q = box.faces()[f];
      for (int& v : q) v += base;
      if (inside_out) std::reverse(q.begin(), q.end());
      if (bowtie && f == 5) {  // swap two corners: the quad's edges cross
        std::swap(q[1], q[2]);
        bow_tie = true;
      }
      if (seam && f == 5 && !bowtie) {  // a, b, c, d -> (a b c), zero-area (a c m), (a m c d)
        const int m = static_cast<int>(vs.size());
        const Point3 &A = vs[q[0]], &C = vs[q[2]];
        vs.push_back(Point3((A.x() + C.x()) / 2, (A.y() + C.y()) / 2, (A.z() + C.z()) / 2));
        faces.push_back({q[0], q[1], q[2]});
        faces.push_back({q[0], q[2], m});
        faces.push_back({q[0], m, q[2], q[3]});
        continue;
      }
      faces.push_back(q);
    }
    if (inside_out) defects.push_back("inside-out");
    if (seam) defects.push_back("seam");
  }
};

bool boxes_apart(const Polyhedron& a, const Polyhedron& b) {
  // Disjoint with a gap in some axis (vertices 0 and 7 are min and max of make_box).
  for (int k = 0; k < 3; ++k)
    if (a.vertices()[7][k] < b.vertices()[0][k] || b.vertices()[7][k] < a.vertices()[0][k]) return true;
  return false;
}

}  // namespace

TEST(Torture, MeshDefects) {
  const long count = env_long("HLR_TORTURE_SCENES", 200) / 2;
  const unsigned seed0 = static_cast<unsigned>(env_long("HLR_TORTURE_SEED", 1));
  Tally tally;
  long refused = 0, inside_out = 0, seams = 0;
  for (long s = 0; s < count; ++s) {
    Generator g(seed0 * 7919u + static_cast<unsigned>(s));
    std::vector<Polyhedron> boxes;
    const int n = g.uniform(2, 4);
    for (int tries = 0; static_cast<int>(boxes.size()) < n && tries < 50; ++tries) {
      Polyhedron b = g.box();
      bool apart = true;
      for (const Polyhedron& o : boxes) apart = apart && boxes_apart(b, o);
      if (apart) boxes.push_back(std::move(b));
    }
    DefectMesh mesh;
    const bool bowtie_scene = g.uniform(0, 9) == 0;
    for (std::size_t i = 0; i < boxes.size(); ++i)
      mesh.add_box(boxes[i], i > 0 && g.uniform(0, 1) == 1, g.uniform(0, 1) == 1, bowtie_scene && i == 0);
    inside_out += std::count(mesh.defects.begin(), mesh.defects.end(), "inside-out");
    seams += std::count(mesh.defects.begin(), mesh.defects.end(), "seam");
    Scene scene;
    scene.file = "defects.off";
    scene.bodies.push_back(SceneBody{"defects", "defects.off", Polyhedron(mesh.vs, mesh.faces), {}, {}, {}});
    RenderOptions opt;
    opt.lines.edges = EdgeSelection::All;
    opt.lines.intersections = false;
    // Orthographic along a random direction (sometimes an axis, sometimes of extreme size), or
    // perspective from outside the boxes.
    std::vector<std::vector<OraclePlane>> planes;
    for (const Polyhedron& b : boxes) planes.push_back(oracle_planes(b));
    if (g.uniform(0, 1) == 0) {
      Vector3 d(g.q(-3, 3, 1), g.q(-3, 3, 1), g.q(1, 3, 1));
      Rational scale = g.uniform(0, 1) ? Rational(1) : (g.uniform(0, 1) ? Rational(mpz_class(1) << 1000) : Rational(1, mpz_class(1) << 1000));
      opt.view.direction = scale * d;
    } else {
      Point3 eye;
      do eye = Point3(g.q(-4, 16, 2), g.q(-4, 16, 2), g.q(-4, 16, 2));
      while (!eye_ok(planes, eye, false));
      opt.view.eye = eye;
    }
    std::string what = "mesh defects, seed " + std::to_string(seed0) + ", scene " + std::to_string(s);
    try {
      RenderResult r = render({scene}, opt);
      EXPECT_FALSE(mesh.bow_tie) << what << ": a bow-tie face was drawn";
      const long before = tally.disagreements;
      sample_check(r.drawing, planes, r.camera, tally, what.c_str());
      if (tally.disagreements != before && std::getenv("HLR_TORTURE_DUMP")) {  // the mesh as OFF, and the view
        std::cout << "# " << what << "; " << (opt.view.eye ? "--eye " + to_string(*opt.view.eye) : "--view " + to_string(*opt.view.direction))
                  << "\nOFF\n" << mesh.vs.size() << " " << mesh.faces.size() << " 0\n";
        for (const Point3& p : mesh.vs) std::cout << to_string(p.x()) << " " << to_string(p.y()) << " " << to_string(p.z()) << "\n";
        for (const Face& f : mesh.faces) {
          std::cout << f.size();
          for (int v : f) std::cout << " " << v;
          std::cout << "\n";
        }
      }
    } catch (const RenderBodyError& e) {
      ++refused;
      EXPECT_TRUE(mesh.bow_tie) << what << ": refused: " << e.what();
    }
  }
  std::cout << "[torture] " << count << " defect meshes (" << inside_out << " inside-out components, " << seams
            << " zero-area seams, " << refused << " bow-ties refused): " << tally.samples << " samples, " << tally.disagreements
            << " wrong\n";
  EXPECT_EQ(tally.disagreements, 0);
  EXPECT_GT(inside_out, 0);
  EXPECT_GT(seams, 0);
  EXPECT_GT(refused, 0);
}

namespace {

Polyhedron cube_box(Rational x0, Rational y0, Rational z0, Rational x1, Rational y1, Rational z1) {
  return make_box(Point3(x0, y0, z0), Point3(x1, y1, z1));
}

// Renders a file of data/degenerate/meshes with a view, checks every piece by exact ray casting
// against the clean convex solids `truth`, and returns the notes.
std::vector<std::string> check_named(const std::string& file, const ViewRequest& view, const std::vector<Polyhedron>& truth,
                                     RenderMethod method = RenderMethod::Faces) {
  RenderOptions opt;
  opt.method = method;
  opt.view = view;
  opt.lines.edges = EdgeSelection::All;
  opt.lines.intersections = false;
  RenderResult r = render_files({std::string(HLR_DATA_DIR) + "/degenerate/meshes/" + file}, opt);
  std::vector<std::vector<OraclePlane>> planes;
  for (const Polyhedron& p : truth) planes.push_back(oracle_planes(p));
  Tally t;
  sample_check(r.drawing, planes, r.camera, t, file.c_str());
  EXPECT_EQ(t.disagreements, 0) << file;
  return r.notes;
}

bool has_note(const std::vector<std::string>& notes, const std::string& part) {
  for (const auto& n : notes)
    if (n.find(part) != std::string::npos) return true;
  return false;
}

}  // namespace

TEST(Torture, InsideOutComponentIsTurned) {
  std::vector<Polyhedron> truth = {cube_box(0, 0, 0, 2, 2, 2), cube_box(3, Rational(1, 2), Rational(1, 2), 4, Rational(3, 2), Rational(3, 2))};
  for (ViewRequest v : {ViewRequest{Vector3(1, Rational(13, 10), Rational(17, 10)), {}, {}, {}},
                        ViewRequest{Vector3(1, 0, 0), {}, {}, {}}, ViewRequest{{}, Point3(7, 1, 1), Point3(0, 1, 1), {}}})
    EXPECT_TRUE(has_note(check_named("inside_out_component.off", v, truth), "inside-out component"));
  EXPECT_THROW(check_named("inside_out_component.off", {}, truth, RenderMethod::Roberts), RenderBodyError);
}

TEST(Torture, CavityIsNotTurned) {
  // The oracle cannot hold a cavity; the drawing of the outer cube must equal the plain cube's.
  RenderOptions opt;
  opt.view.direction = Vector3(1, Rational(13, 10), Rational(17, 10));
  opt.lines.edges = EdgeSelection::All;
  RenderResult r = render_files({std::string(HLR_DATA_DIR) + "/degenerate/meshes/cavity.off"}, opt);
  EXPECT_FALSE(has_note(r.notes, "inside-out"));
  for (const Segment& s : r.drawing.segments)
    for (const Piece& p : s.pieces)  // every edge of the cavity is hidden, every edge of the cube is not
      if (s.v0 >= 8) EXPECT_FALSE(p.visible);
}

TEST(Torture, ZeroAreaSeamDoesNotLeak) {
  std::vector<Polyhedron> truth = {cube_box(0, 0, 0, 1, 1, 1),
                                   cube_box(Rational(1, 4), Rational(1, 4), -2, Rational(3, 4), Rational(3, 4), -1)};
  // Along z the box behind is wholly hidden; the seam x = y crosses its edges' images.
  for (ViewRequest v : {ViewRequest{Vector3(0, 0, 1), {}, {}, {}}, ViewRequest{Vector3(1, -1, 10), {}, {}, {}},
                        ViewRequest{{}, Point3(Rational(1, 2), Rational(1, 2), 5), Point3(Rational(1, 2), Rational(1, 2), 0), {}}}) {
    EXPECT_TRUE(has_note(check_named("zero_area_seam.off", v, truth), "zero-area triangle"));
    check_named("zero_area_seam.off", v, truth, RenderMethod::Roberts);
  }
  // Feature lines: no line across the flat front face (the seam is not a boundary).
  RenderOptions opt;
  opt.view.direction = Vector3(0, 0, 1);
  opt.lines.edges = EdgeSelection::Feature;
  RenderResult r = render_files({std::string(HLR_DATA_DIR) + "/degenerate/meshes/zero_area_seam.off"}, opt);
  for (const Segment& s : r.drawing.segments) EXPECT_NE(s.line, LineKind::Boundary);
  for (const Segment& s : r.drawing.segments) EXPECT_FALSE(s.v0 == 16 || s.v1 == 16) << "a line through the seam's middle vertex";
}

// A quad mesh's non-planar quads are split along their shorter diagonals (the family: polygon
// meshes from modellers, CGAL's torus_quad and mpi, PLY cubes with moved corners): the drawing
// is exact for those triangles (the oracle against the hand-split convex solid), and is the
// drawing of the hand-split OFF except the diagonals' creases (a diagonal is still drawn where it
// is a silhouette).
TEST(Torture, NonPlanarQuadsAreSplit) {
  const std::string dir = std::string(HLR_DATA_DIR) + "/degenerate/meshes/";
  const Polyhedron truth = load_mesh(dir + "twisted_quads_triangles.off");
  ASSERT_TRUE(truth.report().closed());
  for (ViewRequest v : {ViewRequest{Vector3(1, Rational(13, 10), Rational(17, 10)), {}, {}, {}}, ViewRequest{Vector3(0, -1, 0), {}, {}, {}},
                        ViewRequest{{}, Point3(0, -200, 20), Point3(0, 0, 20), {}}}) {
    EXPECT_TRUE(has_note(check_named("twisted_quads.off", v, {truth}), "4 non-planar quads split along the shorter diagonal"));
    RenderOptions opt;
    opt.view = v;
    std::map<std::pair<int, int>, std::string> quads, triangles;
    auto text = [](const Segment& s) {
      std::ostringstream o;
      o << to_string(s.line);
      for (const Piece& p : s.pieces) o << " [" << p.t0 << "," << p.t1 << (p.visible ? " v]" : " h]");
      return o.str();
    };
    for (const Segment& s : render_files({dir + "twisted_quads.off"}, opt).drawing.segments) quads[{s.v0, s.v1}] = text(s);
    for (const Segment& s : render_files({dir + "twisted_quads_triangles.off"}, opt).drawing.segments) {
      const std::pair<int, int> e{std::min(s.v0, s.v1), std::max(s.v0, s.v1)};
      const bool diagonal = e == std::pair{1, 4} || e == std::pair{2, 5} || e == std::pair{3, 6} || e == std::pair{0, 7};
      if (!diagonal || s.line == LineKind::Silhouette) triangles[{s.v0, s.v1}] = text(s);  // a diagonal can be an outline
    }
    EXPECT_EQ(quads, triangles);
  }
}

TEST(Torture, OverlappingComponentsRefusedByRoberts) {
  std::vector<Polyhedron> truth = {cube_box(0, 0, 0, 2, 2, 2), cube_box(1, 1, 1, 3, 3, 3)};
  check_named("overlapping_cubes.off", {Vector3(1, Rational(13, 10), Rational(17, 10)), {}, {}, {}}, truth);
  try {
    check_named("overlapping_cubes.off", {}, truth, RenderMethod::Roberts);
    FAIL() << "Roberts drew one mesh of two overlapping cubes";
  } catch (const RenderBodyError& e) {
    EXPECT_NE(std::string(e.what()).find("volume 8 != its volume 16"), std::string::npos) << e.what();
  }
}

TEST(Torture, SymmetricBowTieRefused) {
  EXPECT_THROW(check_named("symmetric_bow_tie.off", {}, {}), RenderBodyError);
}
