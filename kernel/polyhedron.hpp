// A polyhedron: exact vertex coordinates and exact face planes, the face lists as given, and
// an OpenMesh halfedge mesh with double points (never OpenMesh's default float) built from
// them. Course notes section 19: a solid must know which side is material, so the checks in
// mesh_checks.hpp (closed, manifold, oriented, planar, ...) say when that is known.
#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "kernel/face.hpp"
#include "kernel/geometry.hpp"
#include "kernel/mesh_checks.hpp"
#include "kernel/point_store.hpp"

namespace OpenMesh {
template <class Traits>
class PolyMesh_ArrayKernelT;
}

namespace hlr {

/// The OpenMesh mesh type; its traits (double points) and OpenMesh itself come with
/// kernel/openmesh_mesh.hpp, so that a file that needs a Face does not pull in OpenMesh.
struct MeshTraits;
using Mesh = OpenMesh::PolyMesh_ArrayKernelT<MeshTraits>;


/// Thrown for a face list that cannot describe a polyhedron at all (index out of range,
/// fewer than three vertices). `face()` is the 0-based face index.
class FaceError : public std::runtime_error {
 public:
  FaceError(int face, const std::string& what) : std::runtime_error(what), face_(face) {}
  int face() const { return face_; }

 private:
  int face_;
};

class Polyhedron {
 public:
  /// Builds a polyhedron from exact vertices and faces (vertex indices, 0-based). Throws
  /// FaceError for an index out of range or a face with fewer than 3 vertices. Everything
  /// else (non-planar, non-manifold, ...) is accepted and reported by report().
  Polyhedron(std::vector<Point3> vertices, std::vector<Face> faces);
  /// The same, the vertices brought to lowest terms and the faces checked with `loop(n, body)`
  /// calling body(i) for every i < n (e.g. on all cores; the same result and error on any).
  Polyhedron(std::vector<Point3> vertices, std::vector<Face> faces,
             const std::function<void(std::size_t, const std::function<void(std::size_t)>&)>& loop);
  /// The same for vertices known to be in lowest terms (results of exact arithmetic, points
  /// of another polyhedron): only the faces are checked.
  struct InLowestTerms {};
  Polyhedron(std::vector<Point3> vertices, std::vector<Face> faces, InLowestTerms,
             const std::function<void(std::size_t, const std::function<void(std::size_t)>&)>& loop);

  /// The same for vertices in a store (point_store.hpp): a compact one's exact points are made
  /// only when vertices() is first called. The faces are checked with `loop`.
  Polyhedron(PointStore vertices, std::vector<Face> faces, const std::function<void(std::size_t, const std::function<void(std::size_t)>&)>& loop);

  /// The exact vertices (a compact store's made on the first call, once, safely across threads).
  const std::vector<Point3>& vertices() const { return store_->points(); }
  /// The vertices as stored: their bounds (approx) and a compact store's numerators are read
  /// from here without making the exact points.
  /// Its address stays while the polyhedron lives (copies and moves share it), so segments
  /// borrow their ends from it.
  const PointStore& vertex_store() const { return *store_; }
  const std::vector<Face>& faces() const { return faces_; }
  std::size_t num_vertices() const { return store_->size(); }
  std::size_t num_faces() const { return faces_.size(); }
  /// Undirected edges (i < j), sorted, each once. Computed on first use (not thread-safe then).
  const std::vector<std::pair<int, int>>& edges() const;

  /// Exact plane of each face (Newell normal, oriented by the face's vertex order: a face
  /// listed counter-clockwise seen from outside gets an outward normal). Degenerate (zero
  /// normal) for zero-area faces. Scaled to primitive integer coefficients (primitive_plane).
  /// Made on first use, once, also when that use is on several threads at a time.
  const std::vector<Plane>& planes() const;
  /// The plane of face f alone, as planes()[f] (from there when they are made).
  Plane face_plane(std::size_t f) const;
  /// planes()[f] when the planes are made, else nullptr (nothing is computed).
  const Plane* plane_if_made(std::size_t f) const { return planes_done_.get() ? &planes_[f] : nullptr; }
  /// Computes the planes (once) with `loop(n, body)` calling body(i) for every i < n, e.g. on
  /// all cores (algorithms/support/parallel.hpp: plane_all_faces); planes() then returns them.
  void compute_planes(const std::function<void(std::size_t, const std::function<void(std::size_t)>&)>& loop) const;

  /// The checks of mesh_checks.hpp, computed once.
  const MeshReport& report() const;

  /// The OpenMesh mesh: vertex i is handle i, face f is handle f when no face was refused.
  /// Built on first use (the per-face route never needs it); not thread-safe on that call.
  /// Include kernel/openmesh_mesh.hpp to use it.
  const Mesh& mesh() const;
  /// Faces that OpenMesh's add_face refused (non-manifold or inconsistently oriented), in
  /// order. Never dropped silently: report() names them too.
  const std::vector<int>& refused_faces() const;

  /// The same polyhedron with every face's vertex order reversed.
  Polyhedron reversed() const;

 private:
  void build_mesh() const;
  void check_faces(const std::function<void(std::size_t, const std::function<void(std::size_t)>&)>& loop) const;

  std::shared_ptr<const PointStore> store_;
  std::vector<Face> faces_;
  mutable std::vector<std::pair<int, int>> edges_;
  mutable bool edges_done_ = false;
  mutable std::shared_ptr<Mesh> mesh_;
  mutable std::vector<int> refused_;
  // A flag that copies (the polyhedron stays copyable) and is read and set across threads.
  struct DoneFlag {
    std::atomic<bool> value{false};
    DoneFlag() = default;
    DoneFlag(const DoneFlag& o) : value(o.get()) {}
    DoneFlag& operator=(const DoneFlag& o) {
      value.store(o.get(), std::memory_order_release);
      return *this;
    }
    bool get() const { return value.load(std::memory_order_acquire); }
    void set() { value.store(true, std::memory_order_release); }
  };
  mutable std::vector<Plane> planes_;
  mutable DoneFlag planes_done_;
  mutable std::shared_ptr<MeshReport> report_;
};

/// Orients the faces of a manifold face list consistently (breadth-first over shared edges)
/// and, for a closed component, outward (positive signed volume, exact). Used for inline
/// scene bodies whose faces may come in any orientation. Faces on non-manifold edges are left
/// as they are.
std::vector<Face> orient_faces(const std::vector<Point3>& vertices, std::vector<Face> faces);

/// The box [min, max] as a closed polyhedron with outward quad faces (min < max in each
/// coordinate, else std::invalid_argument). Vertex i has x = max when bit 0 of i is set, y =
/// max for bit 1, z = max for bit 2; faces in the course notes' order: left, right, bottom,
/// top, back, front.
Polyhedron make_box(const Point3& min, const Point3& max);

/// Six times the signed volume enclosed by a closed oriented face list (exact); positive
/// when faces are counter-clockwise seen from outside.
Rational six_signed_volume(const std::vector<Point3>& vertices, const std::vector<Face>& faces);

}  // namespace hlr
