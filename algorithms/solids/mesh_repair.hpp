// Repairs of meshes that describe a valid solid in a degenerate way (course notes section 19:
// a solid is its closed surface; a face of zero area bounds nothing): zero-area triangles on a
// seam, as exporters leave them between two coplanar triangles, and polygons that are not
// planar (a quad mesh's twisted quads), split into triangles.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "kernel/polyhedron.hpp"

namespace hlr {

struct MeshRepair {
  Polyhedron body;
  std::vector<std::string> notes;  // what was changed, after the body's name: "had ...; ..."
  /// Per face of `body`: its number in the input body (outputs name faces by these).
  std::vector<int> input_face;
  /// The input's numbers of the faces removed, and of the faces that took a middle vertex.
  std::vector<int> removed, joined;
};

/// Removes every triangle whose three (distinct) vertices are collinear: its middle vertex m is
/// inserted into the face on the other side of its long edge a-c (between a and c, where that
/// face's edge a-c now runs a-m-c), so the surface stays closed and the sight rays behind the
/// seam stay inside. Exact. nullopt when there is no such triangle (or its long edge is not
/// shared by exactly one other face).
std::optional<MeshRepair> remove_zero_area_triangles(const Polyhedron& body);

/// Splits every face that is not planar (exactly: a vertex off the plane of its Newell normal)
/// into triangles: a quad along its shorter diagonal (exact squared lengths; on a tie the
/// diagonal from its first vertex), a larger polygon by triangulating its projection along its
/// Newell normal where that projection is simple (else it is left as it is, and the renderer
/// names it). `joined` lists the input numbers of the faces split; `input_face` maps each
/// triangle to its polygon. nullopt when every face is planar.
std::optional<MeshRepair> split_nonplanar_faces(const Polyhedron& body);

}  // namespace hlr
