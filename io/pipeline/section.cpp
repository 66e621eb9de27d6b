// Sections in the render pipeline (see section.hpp; docs/design.md, "Sections").
#include "io/pipeline/section.hpp"

#include <cmath>
#include <map>
#include <unordered_set>

#include "algorithms/sections/hatch.hpp"
#include "algorithms/sections/section_cut.hpp"
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

Vector3 exact_vector(const std::array<double, 3>& v) { return Vector3(Rational(v[0]), Rational(v[1]), Rational(v[2])); }

// The hatch family at `degrees` on the page with `step` drawing units between lines, over the
// values the border's corners take.
HatchFamily family(const Projector& proj, const Camera& cam, double degrees, double step, const Polyhedron& p,
                   const std::vector<std::array<int, 2>>& border) {
  const auto ax = proj.axes();
  const double a = degrees * M_PI / 180, n0 = std::cos(a), n1 = std::sin(a);
  const std::array<double, 3> m = {n0 * ax[0][0] + n1 * ax[1][0], n0 * ax[0][1] + n1 * ax[1][1], n0 * ax[0][2] + n1 * ax[1][2]};
  HatchFamily fam;
  fam.perspective = cam.perspective;
  fam.m = exact_vector(m);
  fam.f = exact_vector(ax[2]);
  fam.eye = cam.eye;
  if (!cam.perspective && !proj.frame().identity) {
    fam.k = 1 / proj.frame().scale;
    fam.o = dot(fam.m, proj.frame().centre - Point3());
  }
  double lo = INFINITY, hi = -INFINITY;
  for (const auto& e : border) {
    const auto q = proj.project(p.vertices()[e[0]]);
    const double c = n0 * q[0] + n1 * q[1];
    lo = std::min(lo, c), hi = std::max(hi, c);
  }
  if (!(hi > lo)) return fam;  // fam.step 0: no lines
  step = std::max(step, (hi - lo) / kMaxHatchLines);
  fam.step = Rational(step);
  fam.first = Rational(std::floor(lo / step)) * fam.step + fam.step / 2;  // no line through the corner the range starts at
  fam.last = Rational(hi);
  return fam;
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
      b.body = Polyhedron(std::move(c.vertices), std::move(c.faces));
      b.section_part = std::move(c.part);
      b.section_cap = std::move(c.cap);
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
  std::vector<Segment> out;
  out.reserve(d.segments.size());
  for (Segment& s : d.segments) {
    if (s.kind == Segment::Kind::Edge && s.face0 >= 0 && s.face1 >= 0 && !bodies[s.body]->section_part.empty()) {
      const SceneBody& b = *bodies[s.body];
      if (b.section_part[s.face0] == b.section_part[s.face1]) continue;
      if (b.section_cap[s.face0] >= 0 || b.section_cap[s.face1] >= 0) s.line = LineKind::Cut;
    }
    out.push_back(std::move(s));
  }
  d.segments = std::move(out);
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
  FaceRouteHooks hooks;
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
      const Vector3 normal = body.body.planes()[faces[0]].normal();
      for (double a : angles) {
        const HatchFamily fam = family(proj, r.camera, a, mm / mm_per_unit, body.body, border);
        for (auto& seg : hatch_region(body.body.vertices(), border, normal, fam))
          hooks.extra_lines.push_back({static_cast<int>(b), faces[0], std::move(seg[0]), std::move(seg[1]), LineKind::Hatch});
      }
    }
  }
  if (hooks.extra_lines.empty()) return out;
  std::vector<const Polyhedron*> polys;
  for (const SceneBody* b : r.bodies) polys.push_back(&b->body);
  LineOptions lo;
  lo.edges = EdgeSelection::Feature;
  lo.intersections = false;
  lo.threads = threads;
  hooks.see_through = see_through_bodies(r);
  hooks.extra_only = true;
  LineDrawing all = face_occluders(polys, r.camera, lo, hooks);
  for (Segment& s : all.segments)
    if (s.line == LineKind::Hatch) out.segments.push_back(std::move(s));
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
