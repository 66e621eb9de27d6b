// Conversions between hlr's exact points and CGAL's Exact_predicates_exact_constructions
// kernel (Epeck), for code that uses CGAL algorithms directly (convex hulls in tests, Nef
// polyhedra, the kernel benchmark). Include only in .cpp files: it pulls in CGAL's kernel.
#pragma once

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include "kernel/geometry.hpp"

namespace hlr {

using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;

Epeck::Point_3 to_epeck(const Point3& p);
Epeck::FT to_epeck_ft(const Rational& q);
Point3 from_epeck(const Epeck::Point_3& p);

}  // namespace hlr
