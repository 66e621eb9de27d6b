// Sections in the render pipeline (see section.hpp; docs/design.md, "Sections").
#include "io/pipeline/section.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_set>

#include "algorithms/hatching/hatch.hpp"
#include "algorithms/model/facing.hpp"
#include "algorithms/sections/section_cut.hpp"
#include "algorithms/support/parallel.hpp"
#include "io/pipeline/render_steps.hpp"

namespace hlr {
namespace {

constexpr double kDefaultHatchMm = 2.0;       // ISO 128-50: at least 0.7 mm; 2 mm reads at any size
constexpr double kHatchAngles[] = {45, 135};  // adjacent cut bodies alternate
constexpr double kMaxHatchLines = 20000;      // per cap and family: a finer spacing is widened

std::uint64_t edge_key(int u, int v) { return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(u)) << 32) | static_cast<std::uint32_t>(v); }

// A cap's border: the directed edges of its faces that no other face of the cap traverses back.
std::vector<std::array<int, 2>> cap_border(const Polyhedron& p, const std::vector<int>& faces) {
  std::unordered_set<std::uint64_t> all;
  for (int f : faces) {
    const Face& fc = p.faces()[f];
    for (std::size_t k = 0; k < fc.size(); ++k) all.insert(edge_key(fc[k], fc[(k + 1) % fc.size()]));
  }
  std::vector<std::array<int, 2>> out;
  for (int f : faces) {
    const Face& fc = p.faces()[f];
    for (std::size_t k = 0; k < fc.size(); ++k) {
      const int u = fc[k], v = fc[(k + 1) % fc.size()];
      if (!all.count(edge_key(v, u))) out.push_back({u, v});
    }
  }
  return out;
}

// A page point (drawing coordinates) to the point of the plane n·X + d = 0 it shows, doubles.
std::function<std::array<double, 3>(double, double)> lifter(const Projector& proj, const Camera& cam, const Plane& h) {
  const auto ax = proj.axes();
  const DrawingFrame& fr = proj.frame();
  const double scale = fr.identity ? 1 : to_double(fr.scale);
  const std::array<double, 3> centre = fr.identity
                                           ? std::array<double, 3>{0, 0, 0}
                                           : std::array<double, 3>{to_double(fr.centre.x()), to_double(fr.centre.y()), to_double(fr.centre.z())};
  const std::array<double, 3> n = {to_double(h.a()), to_double(h.b()), to_double(h.c())},
                              eye = {to_double(cam.eye.x()), to_double(cam.eye.y()), to_double(cam.eye.z())};
  const double d = to_double(h.d());
  const bool persp = cam.perspective;
  return [=](double x, double y) {
    std::array<double, 3> o, dir;
    for (int k = 0; k < 3; ++k) {
      const double across = x * ax[0][k] + y * ax[1][k];
      o[k] = persp ? eye[k] : across / scale + centre[k];
      dir[k] = persp ? ax[2][k] + across : ax[2][k];
    }
    const double s = -(n[0] * o[0] + n[1] * o[1] + n[2] * o[2] + d) / (n[0] * dir[0] + n[1] * dir[1] + n[2] * dir[2]);
    return std::array<double, 3>{o[0] + s * dir[0], o[1] + s * dir[1], o[2] + s * dir[2]};
  };
}

// Whether the view sees plane h edge-on, exactly: the orthographic direction lies in it, or the
// eye does. Such a cap covers no area of the page (and a page point lifted onto its plane would
// be at infinity).
bool seen_edge_on(const Plane& h, const Camera& cam) {
  if (cam.perspective) return h.value(cam.eye) == 0;
  return h.a() * cam.direction.x() + h.b() * cam.direction.y() + h.c() * cam.direction.z() == 0;
}

// Every point a section keeps has a value <= 0 in each of its planes, and a point between the
// eye and a cap that faces the eye has a positive value in the cap's plane: no body the section
// cut (and no part of it) can hide such a cap. True when every cap of the drawing faces the eye
// and none is a cut-away's (which keeps points on both sides of its planes).
bool caps_face_the_eye(const RenderResult& r) {
  if (r.section_cut_away) return false;
  for (const SceneBody* b : r.bodies)
    for (int k : b->section_cap)
      if (k >= 0 && facing_sign(r.section_planes[static_cast<std::size_t>(k)], r.camera) <= 0) return false;
  return true;
}

// The parts of a hatch line inside its cap as extra lines of the per-face pass, in chunks of
// about 1/32 of the cap's size at dyadic parameters (short lines meet few occluders' boxes; their
// ends keep small denominators), each with the part of it inside the cap (its own parameters).
void add_chunks(const HatchLine& l, double size, int body, int face, FaceRouteHooks& hooks,
                std::vector<std::vector<std::pair<Rational, Rational>>>& inside) {
  const Vector3 d = l.p1 - l.p0;
  const double length = std::sqrt(to_double(dot(d, d)));
  const int m = std::clamp(static_cast<int>(std::ceil(std::log2(std::max(1.0, 32 * length / size)))), 0, 24);
  const Rational h(mpz_class(1), mpz_class(1) << m);
  for (const auto& [t0, t1] : l.inside) {
    const Rational a = t0 / h, b = t1 / h;
    mpz_class k0, k1;
    mpz_fdiv_q(k0.get_mpz_t(), a.get_num_mpz_t(), a.get_den_mpz_t());  // floor
    mpz_cdiv_q(k1.get_mpz_t(), b.get_num_mpz_t(), b.get_den_mpz_t());  // ceiling
    for (mpz_class k = k0; k < k1; ++k) {
      const Rational s0 = Rational(k) * h;
      const Rational lo = std::max(t0, s0), hi = std::min(t1, Rational(s0 + h));
      if (!(lo < hi)) continue;
      hooks.extra_lines.push_back({body, face, l.p0 + s0 * d, l.p0 + Rational(s0 + h) * d, LineKind::Hatch});
      inside.push_back({{Rational((lo - s0) / h), Rational((hi - s0) / h)}});
    }
  }
}

// The visible part of a hatch line: its visible pieces within its inside intervals.
PieceList clipped_pieces(const PieceList& seen, const std::vector<std::pair<Rational, Rational>>& inside) {
  std::vector<Piece> out;
  for (const Piece& p : seen) {
    if (!p.visible || p.behind_eye || p.clipped) continue;
    for (const auto& [a, b] : inside) {
      const Rational& lo = std::max(p.t0, a);
      const Rational& hi = std::min(p.t1, b);
      if (lo < hi) out.push_back(Piece{lo, hi, true});
    }
  }
  PieceList l;
  l.assign(std::move(out));
  return l;
}

// A hatch line seen whole (cap_hatching): one segment, visible where it is inside its cap.
void add_whole(const HatchLine& l, int body, int face, const RenderResult& r, LineDrawing& out) {
  Segment s;
  s.kind = Segment::Kind::Intersection;
  s.line = LineKind::Hatch;
  s.body = s.body2 = body;
  s.face0 = s.face1 = face;
  s.set_ends(l.p0, l.p1);
  PieceList seen;
  seen.set_whole(true);
  s.pieces = clipped_pieces(seen, l.inside);
  if (r.clip) clip_pieces(s, *r.clip);
  if (!s.pieces.empty()) out.segments.push_back(std::move(s));
}

// The keep cut, then the cut-away, as one cut (cap k of the cut-away is cap keep.size() + k).
CutSolid cut_both(const Polyhedron& body, const std::vector<Plane>& keep, const std::vector<Plane>& away) {
  CutSolid c = keep.empty() ? CutSolid{} : cut_solid(body, keep);
  if (away.empty() || c.state == CutSolid::State::Removed) return c;
  const bool was_cut = c.state == CutSolid::State::Cut;
  const Polyhedron cur = was_cut ? Polyhedron(c.vertices, c.faces) : body;
  CutSolid d = cut_away(cur, away);
  d.open = d.open || c.open;
  if (d.state != CutSolid::State::Cut) {
    if (d.state == CutSolid::State::Removed) return d;
    return c;
  }
  const int n1 = static_cast<int>(cur.num_faces()), nf = static_cast<int>(body.num_faces()), m1 = static_cast<int>(keep.size());
  for (std::size_t f = 0; f < d.part.size(); ++f) {
    const int q = d.part[f];
    if (q < n1) {
      d.part[f] = was_cut ? c.part[q] : q;
      d.cap[f] = was_cut ? c.cap[q] : -1;
    } else {
      d.part[f] = nf + m1 + (q - n1);
      d.cap[f] = m1 + (q - n1);
    }
  }
  return d;
}

}  // namespace

void cut_bodies(const std::vector<Plane>& planes, const std::vector<Plane>& away, std::vector<SceneBody*>& bodies, std::vector<DrawingBody>& names,
                std::vector<std::string>& notes) {
  std::vector<SceneBody*> kept_bodies;
  std::vector<DrawingBody> kept_names;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    SceneBody& b = *bodies[i];
    if (!b.cut) {
      kept_bodies.push_back(&b), kept_names.push_back(std::move(names[i]));
      continue;
    }
    CutSolid c = cut_both(b.body, planes, away);
    if (c.state == CutSolid::State::Removed) continue;
    if (c.open) notes.push_back(b.source + ": body '" + b.name + "' is open: its faces are cut, it gets no cap (its inside is not known)");
    if (c.state == CutSolid::State::Cut) {
      DrawingBody& n = names[i];
      const int input_faces = static_cast<int>(b.body.num_faces());
      std::vector<int> input_face;
      for (int part : c.part)
        input_face.push_back(part < input_faces ? n.output_face(part) : static_cast<int>(n.input_faces(input_faces)) + part - input_faces);
      n.input_face = std::move(input_face);
      n.numbered = n.input_faces(input_faces) + planes.size() + away.size();
      const ParallelLoop loop;  // (the faces checked on all cores; the points are the input's or exact results)
      b.body = Polyhedron(std::move(c.vertices), std::move(c.faces), Polyhedron::InLowestTerms{},
                          [&](std::size_t n, const std::function<void(std::size_t)>& body) { loop.for_each(n, 4096, body); });
      b.surfaces = renumbered_surfaces(b.surfaces, c.part);
      b.section_part = std::move(c.part);
      b.section_cap = std::move(c.cap);
      b.face_texcoords.clear();
    }
    kept_bodies.push_back(&b), kept_names.push_back(std::move(names[i]));
  }
  bodies = std::move(kept_bodies);
  names = std::move(kept_names);
}

void cut_near(const Plane& keep, std::vector<SceneBody*>& bodies, std::vector<DrawingBody>& names, std::vector<std::vector<int>>* parent) {
  std::vector<SceneBody*> kept_bodies;
  std::vector<DrawingBody> kept_names;
  if (parent) parent->clear();
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    SceneBody& b = *bodies[i];
    CutSolid c = cut_solid(b.body, {keep});
    if (c.state == CutSolid::State::Removed) continue;
    if (parent) {
      std::vector<int> from(b.body.num_faces());
      for (std::size_t f = 0; f < from.size(); ++f) from[f] = static_cast<int>(f);
      if (c.state == CutSolid::State::Cut) {
        from.clear();
        for (int q : c.part) from.push_back(q < static_cast<int>(b.body.num_faces()) ? q : -1);
      }
      parent->push_back(std::move(from));
    }
    if (c.state == CutSolid::State::Cut) {
      DrawingBody& n = names[i];
      const int now = static_cast<int>(b.body.num_faces());
      const int cap_number = static_cast<int>(n.input_faces(now));  // after the input's faces and the section's caps
      const bool was_cut = !b.section_part.empty();
      int cap_part = now;  // a part number no face of the body has yet
      for (int q : b.section_part) cap_part = std::max(cap_part, q + 1);
      std::vector<int> input_face, part, cap;
      for (int q : c.part) {
        const bool old = q < now;
        input_face.push_back(old ? n.output_face(q) : cap_number);
        part.push_back(!old ? cap_part : was_cut ? b.section_part[q] : q);
        cap.push_back(!old ? kEyeCap : was_cut ? b.section_cap[q] : -1);
      }
      n.input_face = std::move(input_face);
      n.numbered = cap_number + 1;
      b.body = Polyhedron(std::move(c.vertices), std::move(c.faces));
      b.surfaces = renumbered_surfaces(b.surfaces, c.part);
      b.section_part = std::move(part);
      b.section_cap = std::move(cap);
      b.face_texcoords.clear();
    }
    kept_bodies.push_back(&b), kept_names.push_back(std::move(names[i]));
  }
  bodies = std::move(kept_bodies);
  names = std::move(kept_names);
}

void section_hooks(const std::vector<const SceneBody*>& bodies, FaceRouteHooks& hooks) {
  hooks.face_part.assign(bodies.size(), {});
  hooks.cap_face.assign(bodies.size(), {});
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    if (bodies[b]->section_part.empty()) continue;
    hooks.face_part[b] = bodies[b]->section_part;
    for (int k : bodies[b]->section_cap) hooks.cap_face[b].push_back(k >= 0);
  }
}

void mark_cut_lines(LineDrawing& d, const std::vector<const SceneBody*>& bodies) {
  if (std::all_of(bodies.begin(), bodies.end(), [](const SceneBody* b) { return b->section_part.empty(); })) return;
  // Kept in place, in order (no second array of the drawing's segments).
  auto dropped = [&](Segment& s) {
    if (s.kind == Segment::Kind::Edge && s.face0 >= 0 && s.face1 >= 0 && !bodies[s.body]->section_part.empty()) {
      const SceneBody& b = *bodies[s.body];
      if (b.section_part[s.face0] == b.section_part[s.face1]) return true;
      if (b.section_cap[s.face0] == kEyeCap || b.section_cap[s.face1] == kEyeCap) return true;  // on the near plane
      if (b.section_cap[s.face0] >= 0 || b.section_cap[s.face1] >= 0) s.line = LineKind::Cut;
    }
    return false;
  };
  std::size_t kept = 0;
  for (Segment& s : d.segments) {
    if (dropped(s)) continue;
    if (&s != &d.segments[kept]) d.segments[kept] = std::move(s);
    ++kept;
  }
  d.segments.erase(d.segments.begin() + static_cast<std::ptrdiff_t>(kept), d.segments.end());
}

bool has_caps(const RenderResult& r) {
  for (const SceneBody* b : r.bodies)
    for (int k : b->section_cap)
      if (k >= 0) return true;
  return false;
}

LineDrawing cap_hatching(const RenderResult& r, double mm_per_unit, double pen_mm, unsigned threads) {
  LineDrawing out;
  if (!has_caps(r) || !(mm_per_unit > 0)) return out;
  const Projector proj = drawing_projector(r.drawing, r.camera);
  // No body can hide a hatch line (caps_face_the_eye) and none lies behind the eye: every one
  // is seen whole, as the per-face pass would find it, and is drawn as one segment.
  const bool all_cut = std::all_of(r.bodies.begin(), r.bodies.end(), [](const SceneBody* b) { return b->cut; });
  const bool whole = !r.camera.perspective && all_cut && caps_face_the_eye(r);
  FaceRouteHooks hooks;
  std::vector<std::vector<std::pair<Rational, Rational>>> inside;  // per hatch line
  // The default angle alternates between materials (bodies of one material: one hatch, as ISO
  // 128-50 wants for one part or one material) and, for bodies without one, between bodies.
  std::map<std::string, int> style_index;
  for (std::size_t b = 0; b < r.bodies.size(); ++b) {
    const SceneBody& body = *r.bodies[b];
    std::map<int, std::vector<int>> caps;  // plane -> its cap's faces
    for (std::size_t f = 0; f < body.section_cap.size(); ++f)
      if (body.section_cap[f] >= 0) caps[body.section_cap[f]].push_back(static_cast<int>(f));
    if (caps.empty()) continue;
    const HatchStyle style = body.hatch.value_or(HatchStyle{});
    std::string key = "body " + std::to_string(b);
    if (body.material) {
      const auto& c = body.material->colour;
      key = "material " + std::to_string(c[0]) + " " + std::to_string(c[1]) + " " + std::to_string(c[2]);
    }
    const int index = style_index.emplace(key, static_cast<int>(style_index.size())).first->second;
    const double angle = style.angle.value_or(kHatchAngles[index % 2]);
    if (style.pattern == HatchStyle::Pattern::None) continue;
    const double mm = style.pattern == HatchStyle::Pattern::Solid ? pen_mm : style.spacing.value_or(kDefaultHatchMm);
    std::vector<double> angles = {angle};
    if (style.pattern == HatchStyle::Pattern::Cross) angles.push_back(angle + 90);
    for (const auto& [plane, faces] : caps) {
      const std::vector<std::array<int, 2>> border = cap_border(body.body, faces);
      // (this face's plane alone: a cut mesh has many faces)
      const Plane h = body.body.face_plane(faces[0]);
      if (seen_edge_on(h, r.camera)) continue;  // no area on the page, nothing to hatch
      std::array<double, 4> box = {INFINITY, INFINITY, -INFINITY, -INFINITY};
      double lo3[3] = {INFINITY, INFINITY, INFINITY}, hi3[3] = {-INFINITY, -INFINITY, -INFINITY};
      for (const auto& e : border) {
        const Point3& v = body.body.vertices()[e[0]];
        const auto q = proj.project(v);
        box = {std::min(box[0], q[0]), std::min(box[1], q[1]), std::max(box[2], q[0]), std::max(box[3], q[1])};
        for (int k = 0; k < 3; ++k) lo3[k] = std::min(lo3[k], to_double(v[k])), hi3[k] = std::max(hi3[k], to_double(v[k]));
      }
      const double size = std::max({hi3[0] - lo3[0], hi3[1] - lo3[1], hi3[2] - lo3[2]});
      for (double a : angles) {
        const double rad = a * M_PI / 180, n0 = std::cos(rad), n1 = std::sin(rad);
        double clo = INFINITY, chi = -INFINITY;
        for (double x : {box[0], box[2]})
          for (double y : {box[1], box[3]}) clo = std::min(clo, n0 * x + n1 * y), chi = std::max(chi, n0 * x + n1 * y);
        const double step = std::max(mm / mm_per_unit, (chi - clo) / kMaxHatchLines);
        const double first = std::floor(clo / step) * step + step / 2;  // no line through the corner the range starts at
        for (const HatchLine& l : hatch_lines(body.body.vertices(), border, h, lifter(proj, r.camera, h), a, first, step, chi, box, size))
          if (whole) add_whole(l, static_cast<int>(b), faces[0], r, out);
          else add_chunks(l, size, static_cast<int>(b), faces[0], hooks, inside);
      }
    }
  }
  if (whole || hooks.extra_lines.empty()) return out;
  std::vector<const Polyhedron*> polys;
  for (const SceneBody* b : r.bodies) polys.push_back(&b->body);
  LineOptions lo;
  lo.edges = EdgeSelection::Feature;
  lo.intersections = false;
  lo.threads = threads;
  hooks.see_through = see_through_bodies(r);
  hooks.extra_only = true;
  if (caps_face_the_eye(r)) {  // only the bodies the section did not cut can hide a hatch line
    std::vector<char> cut;
    for (const SceneBody* b : r.bodies) cut.push_back(b->cut);
    hooks.may_occlude = [cut = std::move(cut)](int body, const std::array<int, 3>&) { return !cut[static_cast<std::size_t>(body)]; };
  }
  hooks.share = r.section_share;  // the drawing's prepared bodies, when it left them
  LineDrawing all = face_occluders(polys, r.camera, lo, hooks);
  std::size_t k = 0;
  for (Segment& s : all.segments) {
    if (s.line != LineKind::Hatch) continue;
    s.pieces = clipped_pieces(s.pieces, inside[k++]);
    if (r.near_plane) clip_near(s, *r.near_plane);  // clipped as the drawing is
    if (r.clip) clip_pieces(s, *r.clip);
    if (!s.pieces.empty()) out.segments.push_back(std::move(s));
  }
  out.facing = std::move(all.facing);
  return out;
}

namespace {

std::string exact_point_json(const Point3& p) { return "[\"" + p.x().get_str() + "\",\"" + p.y().get_str() + "\",\"" + p.z().get_str() + "\"]"; }

// The border's directed edges chained into closed loops.
std::vector<std::vector<int>> border_loops(const std::vector<std::array<int, 2>>& border) {
  std::multimap<int, std::size_t> from;
  for (std::size_t k = 0; k < border.size(); ++k) from.emplace(border[k][0], k);
  std::vector<char> used(border.size(), 0);
  std::vector<std::vector<int>> loops;
  for (std::size_t k = 0; k < border.size(); ++k) {
    if (used[k]) continue;
    std::vector<int> loop;
    for (std::size_t e = k;;) {
      used[e] = 1;
      loop.push_back(border[e][0]);
      auto [lo, hi] = from.equal_range(border[e][1]);
      std::size_t next = border.size();
      for (auto it = lo; it != hi; ++it)
        if (!used[it->second]) next = it->second;
      if (next == border.size()) break;
      e = next;
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

}  // namespace

std::string section_json(const RenderResult& r, const LineDrawing& hatch, double mm_per_unit) {
  if (r.section_planes.empty()) return "";
  std::string out = ",\n \"section\": {\"planes\": [";
  for (std::size_t k = 0; k < r.section_planes.size(); ++k) {
    const Plane& h = r.section_planes[k];
    out += std::string(k ? "," : "") + "[\"" + h.a().get_str() + "\",\"" + h.b().get_str() + "\",\"" + h.c().get_str() + "\",\"" + h.d().get_str() +
           "\"]";
  }
  out += "],\n  \"caps\": [";
  bool first = true;
  for (std::size_t b = 0; b < r.bodies.size(); ++b) {
    const SceneBody& body = *r.bodies[b];
    std::map<int, std::vector<int>> caps;
    for (std::size_t f = 0; f < body.section_cap.size(); ++f)
      if (body.section_cap[f] >= 0) caps[body.section_cap[f]].push_back(static_cast<int>(f));
    for (const auto& [plane, faces] : caps) {
      out += std::string(first ? "" : ",") + "\n   {\"body\":" + std::to_string(b) + ",\"plane\":" + std::to_string(plane) + ",\"loops\":[";
      first = false;
      const auto loops = border_loops(cap_border(body.body, faces));
      for (std::size_t l = 0; l < loops.size(); ++l) {
        out += l ? ",[" : "[";
        for (std::size_t k = 0; k < loops[l].size(); ++k) out += (k ? "," : "") + exact_point_json(body.body.vertices()[loops[l][k]]);
        out += "]";
      }
      out += "]}";
    }
  }
  out += "],\n  \"hatch_scale_mm_per_unit\": " + std::to_string(mm_per_unit) + ",\n  \"hatch\": [";
  first = true;
  for (const Segment& s : hatch.segments)
    for (const Piece& p : s.pieces) {
      if (!p.visible || p.behind_eye || p.clipped) continue;
      out += std::string(first ? "" : ",") + "\n   {\"body\":" + std::to_string(s.body) + ",\"from\":" + exact_point_json(s.at(p.t0)) +
             ",\"to\":" + exact_point_json(s.at(p.t1)) + "}";
      first = false;
    }
  out += "]}";
  return out;
}

}  // namespace hlr
