// OpenMesh's view of a Polyhedron (course notes section 19: the halfedge structure that says
// whether a face list bounds a solid): the mesh type with double points (never OpenMesh's
// default float). Only the files that use the OpenMesh mesh include this header.
#pragma once

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>

#include "kernel/polyhedron.hpp"

namespace hlr {

struct MeshTraits : public OpenMesh::DefaultTraits {
  typedef OpenMesh::Vec3d Point;
  typedef OpenMesh::Vec3d Normal;
};

}  // namespace hlr
