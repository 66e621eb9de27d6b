// The exact ray-casting oracle applied to a whole drawing: the middle of every visible or hidden
// piece checked against the faces on its sight ray (tests/support/face_oracle.hpp), for the
// model readers' tests (STEP, IGES, glTF, 3MF).
#pragma once

#include <gtest/gtest.h>

#include "io/pipeline/render.hpp"
#include "support/face_oracle.hpp"

namespace hlr::test {

// The oracle: the middle of every piece is visible exactly when no face is nearer on its sight
// ray (pieces whose ray grazes a face's border are skipped). Returns the pieces decided.
inline long check_visibility(const RenderResult& r) {
  std::vector<const Polyhedron*> polys;
  for (const SceneBody* b : r.bodies) polys.push_back(&b->body);
  const PicturePlane pp(r.camera);
  const auto faces = oracle_faces(polys, pp);
  long decided = 0;
  for (const Segment& s : r.drawing.segments)
    for (const Piece& p : s.pieces) {
      const Point3 x = s.at((p.t0 + p.t1) / 2);
      const Exact2 q = pp.project(x);
      const SightRay ray = sight_ray(r.camera, pp, q);
      int k = ray.dir[0] != 0 ? 0 : ray.dir[1] != 0 ? 1 : 2;
      const Rational t = (x[k] - ray.base[k]) / ray.dir[k];  // orthographic: larger is nearer
      bool nearer = false, unsure = false;
      for (const SightHit& h : sight_hits(faces, r.camera, pp, q))
        if (h.nearness > t) (h.in == 0 ? unsure : nearer) = true;
      if (unsure && !nearer) continue;
      ++decided;
      EXPECT_EQ(p.visible, !nearer) << to_string(s.line) << " piece of " << s.from() << " - " << s.to();
    }
  return decided;
}

}  // namespace hlr::test
