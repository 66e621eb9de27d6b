// The topology of a body's face list (course notes section 19: a solid must know which side is
// material, and that is read off how faces meet at edges): every undirected edge with the
// faces that use it and in which direction, in linear time. Closed solids have every edge in
// exactly two faces traversed in opposite directions; the per-face route reads neighbours
// across edges from here.
#pragma once

#include <cstdint>
#include <type_traits>
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

/// The uses of one edge: two in place (a closed surface's edges have two), the rest in the
/// topology's `beyond`, so that a mesh of a million faces does not allocate once per edge and
/// an edge takes 40 bytes. Nothing to free: an array of edges is freed without reading it
/// again (its pages may have been given back, release_pages).
class EdgeUses {
 public:
  std::size_t size() const { return n_; }
  bool empty() const { return n_ == 0; }
  const EdgeUse& operator[](std::size_t k) const { return k < 2 ? in_[k] : more_[k - 2]; }
  /// Appends a use: the first two in place; a later one only counted, its record kept in the
  /// topology's `beyond` (set_beyond points there).
  void push_back(const EdgeUse& u) {
    if (n_ < 2) in_[n_] = u;
    ++n_;
  }
  void set_beyond(const EdgeUse* more) { more_ = more; }

 private:
  EdgeUse in_[2]{};
  const EdgeUse* more_ = nullptr;  // the uses after the two in place (in BodyTopology::beyond)
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
static_assert(std::is_trivially_destructible_v<BodyEdge>);

struct BodyTopology {
  BodyTopology() = default;
  BodyTopology(BodyTopology&&) = default;  // (moves keep `beyond`'s records where the edges point)
  BodyTopology& operator=(BodyTopology&&) = default;
  BodyTopology(const BodyTopology&) = delete;
  BodyTopology& operator=(const BodyTopology&) = delete;

  std::vector<int> face_offset;  // first slot of each face; size faces + 1
  // (RawVector: built on all cores without a serial pass of constructors; read as vectors.)
  RawVector<BodyEdge> edges;     // sorted by (u, v)
  std::vector<EdgeUse> beyond;   // the uses after an edge's first two, edge by edge
  RawVector<int> slot_edge;      // slot -> index in edges (-1 for a repeated vertex)
  RawVector<int> slot_third;     // slot -> the third vertex of the triangle on that side (caller's; empty: not kept)
  bool paired = false;           // pair_sides: slot_edge and slot_third hold the mates (the edges freed or about to be)
};

/// Groups the edge uses of `faces` (vertex ids below `num_vertices`) by undirected edge, on
/// `threads` cores (0: all; the same result on any number). Sides with a repeated vertex
/// (u == v) are no edge. `slot_third` is sized and set to -1, or left empty without `thirds`
/// (a body of triangles: a side's third vertex is its own face's, and across it the mate
/// face's vertex off the edge).
BodyTopology body_topology(const std::vector<Face>& faces, std::size_t num_vertices, unsigned threads = 0, bool thirds = true);

/// For a caller that from now on only asks what lies across each side: slot_edge[s] becomes
/// the face across side s (the other use of an edge with exactly two uses, else -1) and
/// slot_third[s] that use's slot_third (the third vertex on the other side); the edges, the
/// largest array, are freed (unless `free_edges` is false: the caller's last reads of them
/// come first, and it frees them) and `paired` is set. On `threads` cores (the same on any
/// number).
void pair_sides(BodyTopology& t, unsigned threads = 0, bool free_edges = true);

}  // namespace hlr
