// Polyhedron: exact vertices and planes beside an OpenMesh mesh (see polyhedron.hpp).
#include "kernel/polyhedron.hpp"

#include <OpenMesh/Core/System/omstream.hh>
#include <algorithm>
#include <array>
#include <deque>
#include <mutex>
#include <stdexcept>
#include <unordered_map>

#include "kernel/openmesh_mesh.hpp"

namespace hlr {

Polyhedron::Polyhedron(std::vector<Point3> vertices, std::vector<Face> faces)
    : Polyhedron(std::move(vertices), std::move(faces), [](std::size_t n, const std::function<void(std::size_t)>& body) {
        for (std::size_t i = 0; i < n; ++i) body(i);
      }) {}

Polyhedron::Polyhedron(std::vector<Point3> vertices, std::vector<Face> faces,
                       const std::function<void(std::size_t, const std::function<void(std::size_t)>&)>& loop)
    : faces_(std::move(faces)) {
  // GMP compares fractions correctly only in lowest terms: a coordinate built through the API
  // as mpq_class(836, 1024) is brought to 209/256 here, once, for every route.
  loop(vertices.size(), [&](std::size_t i) {
    Point3& p = vertices[i];
    if (in_lowest_terms(p[0]) && in_lowest_terms(p[1]) && in_lowest_terms(p[2])) return;
    std::array<Rational, 3> c{p.x(), p.y(), p.z()};
    for (Rational& q : c) q.canonicalize();
    p = Point3(c[0], c[1], c[2]);
  });
  store_ = std::make_shared<const PointStore>(std::move(vertices));
  check_faces(loop);
}

Polyhedron::Polyhedron(std::vector<Point3> vertices, std::vector<Face> faces, InLowestTerms,
                       const std::function<void(std::size_t, const std::function<void(std::size_t)>&)>& loop)
    : store_(std::make_shared<const PointStore>(std::move(vertices))), faces_(std::move(faces)) {
  check_faces(loop);
}

Polyhedron::Polyhedron(PointStore vertices, std::vector<Face> faces,
                       const std::function<void(std::size_t, const std::function<void(std::size_t)>&)>& loop)
    : store_(std::make_shared<const PointStore>(std::move(vertices))), faces_(std::move(faces)) {
  check_faces(loop);
}

// Faces checked on the loop, the first bad one (in order) reported.
void Polyhedron::check_faces(const std::function<void(std::size_t, const std::function<void(std::size_t)>&)>& loop) const {
  const long nv = static_cast<long>(store_->size());
  std::vector<char> bad(faces_.size(), 0);
  loop(faces_.size(), [&](std::size_t f) {
    if (faces_[f].size() < 3) bad[f] = 1;
    for (int v : faces_[f])
      if (v < 0 || v >= nv) bad[f] = 1;
  });
  const auto first_bad = std::find(bad.begin(), bad.end(), 1);
  if (first_bad == bad.end()) return;
  const std::size_t f = static_cast<std::size_t>(first_bad - bad.begin());
  if (faces_[f].size() < 3)
    throw FaceError(static_cast<int>(f), "face " + std::to_string(f) + " has " + std::to_string(faces_[f].size()) +
                                             " vertices; a face needs at least 3");
  for (int v : faces_[f])
    if (v < 0 || v >= nv)
      throw FaceError(static_cast<int>(f), "face " + std::to_string(f) + " uses vertex " + std::to_string(v) +
                                               ", but there are only " + std::to_string(nv) + " vertices");
}

const std::vector<std::pair<int, int>>& Polyhedron::edges() const {
  if (!edges_done_) {
    for (const auto& f : faces_)
      for (std::size_t i = 0; i < f.size(); ++i) {
        int a = f[i], b = f[(i + 1) % f.size()];
        if (a != b) edges_.push_back({std::min(a, b), std::max(a, b)});
      }
    std::sort(edges_.begin(), edges_.end());
    edges_.erase(std::unique(edges_.begin(), edges_.end()), edges_.end());
    edges_done_ = true;
  }
  return edges_;
}

const Mesh& Polyhedron::mesh() const {
  if (!mesh_) build_mesh();
  return *mesh_;
}

const std::vector<int>& Polyhedron::refused_faces() const {
  if (!mesh_) build_mesh();
  return refused_;
}

void Polyhedron::build_mesh() const {
  mesh_ = std::make_shared<Mesh>();
  mesh_->reserve(store_->size(), edges().size(), faces_.size());
  for (const Point3& p : vertices()) mesh_->add_vertex(Mesh::Point(to_double(p.x()), to_double(p.y()), to_double(p.z())));
  // add_face only logs on failure; silence the log and record the refused faces instead.
  bool was_enabled = omerr().is_enabled();
  omerr().disable();
  std::vector<Mesh::VertexHandle> vh;
  for (std::size_t f = 0; f < faces_.size(); ++f) {
    vh.clear();
    for (int v : faces_[f]) vh.push_back(Mesh::VertexHandle(v));
    std::vector<int> sorted = faces_[f];
    std::sort(sorted.begin(), sorted.end());
    bool repeated = std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end();
    if (repeated || !mesh_->add_face(vh).is_valid()) refused_.push_back(static_cast<int>(f));
  }
  if (was_enabled) omerr().enable();
}

namespace {
std::mutex& planes_mutex() {  // one for all polyhedra: planes are made once each
  static std::mutex m;
  return m;
}
}  // namespace

void Polyhedron::compute_planes(const std::function<void(std::size_t, const std::function<void(std::size_t)>&)>& loop) const {
  if (planes_done_.get()) return;
  std::vector<Plane> out(faces_.size());
  loop(faces_.size(), [&](std::size_t f) { out[f] = face_plane(f); });
  std::lock_guard<std::mutex> lock(planes_mutex());
  if (planes_done_.get()) return;
  planes_ = std::move(out);
  planes_done_.set();
}

const std::vector<Plane>& Polyhedron::planes() const {
  if (!planes_done_.get()) {
    std::lock_guard<std::mutex> lock(planes_mutex());
    if (!planes_done_.get()) {
      std::vector<Plane> out;
      out.reserve(faces_.size());
      for (std::size_t f = 0; f < faces_.size(); ++f) out.push_back(face_plane(f));
      planes_ = std::move(out);
      planes_done_.set();
    }
  }
  return planes_;
}

Plane Polyhedron::face_plane(std::size_t f) const {
  if (planes_done_.get()) return planes_[f];
  const Face& face = faces_[f];
  if (face.size() <= 8) {  // nearly every face: no allocation
    const Point3* pts[8];
    for (std::size_t i = 0; i < face.size(); ++i) pts[i] = &vertices()[face[i]];
    return primitive_plane_of_polygon(pts, face.size());
  }
  std::vector<const Point3*> pts;
  for (int v : face) pts.push_back(&vertices()[v]);
  return primitive_plane_of_polygon(pts.data(), pts.size());
}

const MeshReport& Polyhedron::report() const {
  if (!report_) {
    report_ = std::make_shared<MeshReport>(check_mesh(vertices(), faces_, planes()));
    report_->refused_faces = refused_faces();
  }
  return *report_;
}

Polyhedron Polyhedron::reversed() const {
  std::vector<Face> faces = faces_;
  for (auto& f : faces) std::reverse(f.begin(), f.end());
  if (store_->compact())
    return Polyhedron(*store_, std::move(faces), [](std::size_t n, const std::function<void(std::size_t)>& body) {
      for (std::size_t i = 0; i < n; ++i) body(i);
    });
  return Polyhedron(vertices(), std::move(faces));
}

Polyhedron make_box(const Point3& lo, const Point3& hi) {
  for (int i = 0; i < 3; ++i)
    if (!(lo[i] < hi[i])) throw std::invalid_argument("box min must be below max in x, y and z");
  std::vector<Point3> vs;
  for (int k = 0; k < 8; ++k)  // bit 0: x, bit 1: y, bit 2: z
    vs.emplace_back(k & 1 ? hi.x() : lo.x(), k & 2 ? hi.y() : lo.y(), k & 4 ? hi.z() : lo.z());
  // Counter-clockwise seen from outside, in the course notes' order: left (x min), right,
  // bottom (y min), top, back (z min), front.
  std::vector<Face> faces = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  return Polyhedron(std::move(vs), std::move(faces));
}

Rational six_signed_volume(const std::vector<Point3>& vs, const std::vector<Face>& faces) {
  // Sum over fan triangles of det[a, b, c] relative to the first vertex (origin-independent
  // for closed surfaces).
  Rational total = 0;
  if (vs.empty()) return total;
  const Point3& o = vs[0];
  for (const auto& f : faces)
    for (std::size_t i = 1; i + 1 < f.size(); ++i) {
      Vector3 a = vs[f[0]] - o, b = vs[f[i]] - o, c = vs[f[i + 1]] - o;
      total += dot(a, cross(b, c));
    }
  return total;
}

std::vector<Face> orient_faces(const std::vector<Point3>& vs, std::vector<Face> faces) {
  // Directed-edge adjacency: for an undirected edge, the faces using it.
  std::unordered_map<std::uint64_t, std::vector<int>> by_edge;
  auto ukey = [](int a, int b) {
    if (a > b) std::swap(a, b);
    return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b);
  };
  for (std::size_t f = 0; f < faces.size(); ++f)
    for (std::size_t i = 0; i < faces[f].size(); ++i)
      by_edge[ukey(faces[f][i], faces[f][(i + 1) % faces[f].size()])].push_back(static_cast<int>(f));
  auto has_directed = [](const Face& f, int a, int b) {
    for (std::size_t i = 0; i < f.size(); ++i)
      if (f[i] == a && f[(i + 1) % f.size()] == b) return true;
    return false;
  };
  std::vector<int> component(faces.size(), -1);
  int ncomp = 0;
  for (std::size_t seed = 0; seed < faces.size(); ++seed) {
    if (component[seed] >= 0) continue;
    std::deque<int> queue{static_cast<int>(seed)};
    component[seed] = ncomp;
    std::vector<int> members;
    while (!queue.empty()) {
      int f = queue.front();
      queue.pop_front();
      members.push_back(f);
      const Face& face = faces[f];
      for (std::size_t i = 0; i < face.size(); ++i) {
        int a = face[i], b = face[(i + 1) % face.size()];
        const auto& users = by_edge[ukey(a, b)];
        if (users.size() != 2) continue;  // boundary or non-manifold: no propagation
        int g = users[0] == f ? users[1] : users[0];
        if (component[g] >= 0) continue;
        // Neighbour must traverse the shared edge as b -> a.
        if (has_directed(faces[g], a, b)) std::reverse(faces[g].begin(), faces[g].end());
        component[g] = ncomp;
        queue.push_back(g);
      }
    }
    // Outward for closed components: make the enclosed signed volume positive.
    std::vector<Face> comp_faces;
    for (int f : members) comp_faces.push_back(faces[f]);
    if (six_signed_volume(vs, comp_faces) < 0)
      for (int f : members) std::reverse(faces[f].begin(), faces[f].end());
    ++ncomp;
  }
  return faces;
}

}  // namespace hlr
