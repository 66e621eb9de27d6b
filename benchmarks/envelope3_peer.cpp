// The exact peer of `hlr render --surfaces` (the visible-surfaces benchmark): CGAL's Envelope_3 on the
// same triangles, with Epeck's exact numbers. Orthographic visibility along a view direction d
// is invariant under the shear x' = x - (dx/dz)·z, y' = y - (dy/dz)·z, z' = z, which turns d
// into the z axis, so the upper envelope of the sheared triangles along z is what a viewer at
// +d sees: the visible part of every triangle, exactly (CGAL's answer, not ours).
//   envelope3_peer MESH.off DX,DY,DZ   (dz != 0; coordinates exact in doubles, e.g. k/1024)
// Prints the diagram's size and the seconds of the envelope alone and of the whole run.
// Not built by default (a CGAL unit compiles for minutes): `make envelope3_peer`, or
// scripts/bench_surfaces.sh --peer.
#include <CGAL/Env_triangle_traits_3.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/envelope_3.h>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <list>
#include <sstream>
#include <string>

#include "io/readers/mesh_reader.hpp"

namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Traits = CGAL::Env_triangle_traits_3<Kernel>;
using Diagram = CGAL::Envelope_diagram_2<Traits>;
using FT = Kernel::FT;

// A coordinate as an exact double; throws when the file's number is not one.
double exact_double(const hlr::Rational& q) {
  const double d = q.get_d();
  if (hlr::Rational(d) != q) throw std::invalid_argument("envelope3_peer: a coordinate is not exact in doubles");
  return d;
}

// A small rational (the view's components) as num / den in exact numbers.
FT exact_small(const hlr::Rational& q) {
  if (!q.get_num().fits_slong_p() || !q.get_den().fits_slong_p()) throw std::invalid_argument("envelope3_peer: view components too large");
  return FT(q.get_num().get_si()) / FT(q.get_den().get_si());
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: envelope3_peer MESH.off DX,DY,DZ\n";
    return 2;
  }
  try {
    const auto t0 = std::chrono::steady_clock::now();
    const hlr::Polyhedron mesh = hlr::load_mesh(argv[1]);
    std::stringstream view(argv[2]);
    std::string part;
    FT d[3];
    for (int k = 0; k < 3; ++k) {
      if (!std::getline(view, part, ',')) throw std::invalid_argument("envelope3_peer: view DX,DY,DZ");
      d[k] = exact_small(hlr::parse_rational(part));
    }
    if (d[2] == 0) throw std::invalid_argument("envelope3_peer: the view's z must not be 0");
    const FT sx = d[0] / d[2], sy = d[1] / d[2];
    std::list<Traits::Surface_3> triangles;
    for (const hlr::Face& f : mesh.faces()) {
      if (f.size() != 3) throw std::invalid_argument("envelope3_peer: triangles only");
      Kernel::Point_3 p[3];
      for (int k = 0; k < 3; ++k) {
        const hlr::Point3& v = mesh.vertices()[f[k]];
        const FT x(exact_double(v.x())), y(exact_double(v.y())), z(exact_double(v.z()));
        p[k] = Kernel::Point_3(x - sx * z, y - sy * z, z);
      }
      if (!Kernel::Collinear_3()(p[0], p[1], p[2])) triangles.emplace_back(p[0], p[1], p[2]);
    }
    const auto t1 = std::chrono::steady_clock::now();
    Diagram diagram;
    CGAL::upper_envelope_3(triangles.begin(), triangles.end(), diagram);
    const auto t2 = std::chrono::steady_clock::now();
    std::size_t faces = 0;
    for (auto f = diagram.faces_begin(); f != diagram.faces_end(); ++f)
      if (f->number_of_surfaces() > 0) ++faces;
    std::printf("envelope3: triangles %zu, diagram faces %zu (covered %zu), edges %zu, vertices %zu, envelope %.3f s, total %.3f s\n",
                triangles.size(), static_cast<std::size_t>(diagram.number_of_faces()), faces,
                static_cast<std::size_t>(diagram.number_of_edges()), static_cast<std::size_t>(diagram.number_of_vertices()),
                std::chrono::duration<double>(t2 - t1).count(), std::chrono::duration<double>(t2 - t0).count());
  } catch (const std::exception& e) {
    std::cerr << e.what() << "\n";
    return 1;
  }
  return 0;
}
