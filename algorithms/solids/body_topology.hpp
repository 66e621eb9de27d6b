// The topology of a body's face list (course notes section 19: a solid must know which side is
// material, and that is read off how faces meet at edges): every undirected edge with the
// faces that use it and in which direction, in linear time. Closed solids have every edge in
// exactly two faces traversed in opposite directions; the per-face route reads neighbours
// across edges from here.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "algorithms/support/uninitialised.hpp"
#include "kernel/polyhedron.hpp"

namespace hlr {

/// One use of an edge by a face (8 bytes: a 10M-triangle mesh has 30M).
struct EdgeUse {
  int face;
  int slot : 31;         // face_offset[face] + position of the edge's first vertex in the face
  unsigned forward : 1;  // traversed from the lower vertex id to the higher
};
static_assert(sizeof(EdgeUse) == 8);

/// The uses of one edge: two in place (a closed surface's edges have two), more beside, so
/// that a mesh of a million faces does not allocate once per edge (and an edge takes 40 bytes,
/// not 64 as with a vector beside).
class EdgeUses {
 public:
  EdgeUses() = default;
  EdgeUses(const EdgeUses& o) : n_(o.n_) {
    in_[0] = o.in_[0], in_[1] = o.in_[1];
    if (o.more_) more_ = std::make_unique<std::vector<EdgeUse>>(*o.more_);
  }
  EdgeUses& operator=(const EdgeUses& o) {
    if (this != &o) *this = EdgeUses(o);
    return *this;
  }
  EdgeUses(EdgeUses&&) noexcept = default;
  EdgeUses& operator=(EdgeUses&&) noexcept = default;

  std::size_t size() const { return n_; }
  bool empty() const { return n_ == 0; }
  const EdgeUse& operator[](std::size_t k) const { return k < 2 ? in_[k] : (*more_)[k - 2]; }
  void push_back(const EdgeUse& u) {
    if (n_ < 2) {
      in_[n_] = u;
    } else {
      if (!more_) more_ = std::make_unique<std::vector<EdgeUse>>();
      more_->push_back(u);
    }
    ++n_;
  }

 private:
  EdgeUse in_[2]{};
  std::unique_ptr<std::vector<EdgeUse>> more_;
  std::uint32_t n_ = 0;
};

/// One undirected edge (body-local vertex ids u < v) and its uses, in order of slot.
struct BodyEdge {
  int u, v;
  EdgeUses uses;
  /// Exactly two uses in opposite directions (an edge of a closed, oriented surface).
  bool closed_pair() const { return uses.size() == 2 && uses[0].forward != uses[1].forward; }
};
static_assert(sizeof(BodyEdge) == 40);

struct BodyTopology {
  std::vector<int> face_offset;  // first slot of each face; size faces + 1
  // (RawVector: built on all cores without a serial pass of constructors; read as vectors.)
  RawVector<BodyEdge> edges;     // sorted by (u, v)
  RawVector<int> slot_edge;      // slot -> index in edges (-1 for a repeated vertex)
  RawVector<int> slot_third;     // slot -> the third vertex of the triangle on that side (caller's)
  bool paired = false;           // pair_sides: edges freed, slot_edge and slot_third hold the mates
};

/// Groups the edge uses of `faces` (vertex ids below `num_vertices`) by undirected edge, on
/// `threads` cores (0: all; the same result on any number). Sides with a repeated vertex
/// (u == v) are no edge. `slot_third` is sized and set to -1.
BodyTopology body_topology(const std::vector<Face>& faces, std::size_t num_vertices, unsigned threads = 0);

/// For a caller that from now on only asks what lies across each side: slot_edge[s] becomes
/// the face across side s (the other use of an edge with exactly two uses, else -1) and
/// slot_third[s] that use's slot_third (the third vertex on the other side); the edges, the
/// largest array, are freed and `paired` is set. On `threads` cores (the same on any number).
void pair_sides(BodyTopology& t, unsigned threads = 0);

}  // namespace hlr
