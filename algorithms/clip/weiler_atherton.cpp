// The Weiler–Atherton hidden-surface algorithm, exact (course notes section 31). See
// weiler_atherton.hpp.
#include "algorithms/clip/weiler_atherton.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <tuple>

#include "algorithms/picture/scene_polygons.hpp"
#include "algorithms/support/parallel.hpp"
#include "algorithms/support/progress.hpp"

namespace hlr {
namespace {

// Sutherland–Hodgman against one half-plane: keeps the points where f >= 0 (sign +1) or
// f <= 0 (sign -1); crossing points exact.
std::vector<Exact2> clip_half(const std::vector<Exact2>& p, const PictureLinear& f, int sign) {
  std::vector<Exact2> out;
  const std::size_t n = p.size();
  std::vector<Rational> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = sign * f.at(p[i]);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    if (v[i] >= 0) out.push_back(p[i]);
    if ((v[i] > 0 && v[j] < 0) || (v[i] < 0 && v[j] > 0)) {
      Rational t = v[i] / (v[i] - v[j]);
      out.push_back({p[i][0] + t * (p[j][0] - p[i][0]), p[i][1] + t * (p[j][1] - p[i][1])});
    }
  }
  // Repeated points (a corner on the line) are dropped; a polygon without area is empty.
  std::vector<Exact2> clean;
  for (const Exact2& q : out)
    if (clean.empty() || clean.back() != q) clean.push_back(q);
  while (clean.size() > 1 && clean.front() == clean.back()) clean.pop_back();
  if (clean.size() < 3 || picture_area2(clean) == 0) return {};
  return clean;
}

// Left of the side a -> b: cross(b - a, q - a) >= 0, linear in q.
PictureLinear left_of(const Exact2& a, const Exact2& b) {
  Rational ex = b[0] - a[0], ey = b[1] - a[1];
  return {-(ex * a[1] - ey * a[0]), -ey, ex};
}

class Wa {
 public:
  Wa(const std::vector<const Polyhedron*>& bodies, const Camera& cam, const WeilerAthertonOptions& opt)
      : bodies_(bodies), pp_(cam), opt_(opt) {
    for (std::size_t b = 0, id = 0; b < bodies.size(); ++b) {
      offset_.push_back(static_cast<int>(id));
      for (std::size_t f = 0; f < bodies[b]->num_faces(); ++f, ++id) {
        rays_.push_back(pp_.ray_parameter(bodies[b]->planes()[f]));
        const auto& r = rays_.back();
        front_.push_back(pp_.perspective() ? sgn(r[0].c0) < 0 : sgn(r[1].c0) > 0);
      }
    }
  }

  const PicturePlane& picture() const { return pp_; }
  int id(const WaPolygon& p) const { return offset_[p.body] + p.face; }

  // Nearness of face x over face y as a linear function N(q) whose sign says who is nearer at
  // q (positive: x), valid on the part of the picture in front of the eye where `at` lies.
  PictureLinear nearness(int x, int y, const Exact2& at) const {
    const auto &rx = rays_[x], &ry = rays_[y];
    if (!pp_.perspective()) {
      // s = num / den, den constant, larger nearer: N = s_x - s_y.
      const Rational &dx = rx[1].c0, &dy = ry[1].c0;
      return {rx[0].c0 / dx - ry[0].c0 / dy, rx[0].cx / dx - ry[0].cx / dy, rx[0].cy / dx - ry[0].cy / dy};
    }
    // l = num / den(q), smaller nearer: sign(l_y - l_x) = sign(num_y den_x - num_x den_y)·sign(den_x den_y).
    int s = sgn(rx[1].at(at)) * sgn(ry[1].at(at));
    const Rational &nx = rx[0].c0, &ny = ry[0].c0;
    return {s * (ny * rx[1].c0 - nx * ry[1].c0), s * (ny * rx[1].cx - nx * ry[1].cx), s * (ny * rx[1].cy - nx * ry[1].cy)};
  }

  // Depth used by the preliminary sort: larger is nearer (orthographic s, perspective -l).
  Rational depth(const WaPolygon& p, const Exact2& q) const {
    const auto& r = rays_[id(p)];
    Rational v = r[0].at(q) / r[1].at(q);
    return pp_.perspective() ? Rational(-v) : v;
  }
  Rational nearest(const WaPolygon& p) const {
    Rational best = depth(p, p.pts[0]);
    for (const Exact2& q : p.pts) best = std::max(best, depth(p, q));
    return best;
  }

  // Equal depth everywhere: the face toward the viewer, then the lower face number, is seen.
  bool wins_tie(const WaPolygon& x, const WaPolygon& y) const {
    int a = id(x), b = id(y);
    if (front_[a] != front_[b]) return front_[a];
    return a < b;
  }

  WeilerAthertonResult run(std::vector<WaPolygon> polys) {
    if (polys.size() > opt_.max_polygons) too_many();
    run_list(std::move(polys), 0, nullptr);
    return std::move(res_);
  }

 private:
  [[noreturn]] void too_many() const {
    throw std::invalid_argument("Weiler-Atherton is for exam-sized scenes: more than " + std::to_string(opt_.max_polygons) +
                                " polygons (use --method faces)");
  }

  void sort_list(std::vector<WaPolygon>& list, int level) {
    std::vector<std::pair<Rational, std::size_t>> key;
    for (std::size_t i = 0; i < list.size(); ++i) {
      if (!list[i].nearest) list[i].nearest = nearest(list[i]);
      key.emplace_back(*list[i].nearest, i);
    }
    std::stable_sort(key.begin(), key.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    std::vector<WaPolygon> sorted;
    for (auto& k : key) sorted.push_back(list[k.second]);
    list = std::move(sorted);
    if (opt_.trace) {
      WaStep s;
      s.kind = WaStep::Kind::Sort;
      s.level = level;
      s.polygons = list;
      for (auto& k : key) s.depths.push_back(k.first);
      res_.steps.push_back(std::move(s));
    }
  }

  // The notes' loop: the front polygon clips the list; its inside list is resolved; the work
  // goes on with the outside list. `first`: the clipper forced by a violation (step 4).
  void run_list(std::vector<WaPolygon> list, int level, const WaPolygon* first) {
    if (level > static_cast<int>(rays_.size()) + 8) throw std::logic_error("Weiler-Atherton: recursion did not end");
    std::vector<std::tuple<int, int, int>> used;
    bool forced = first != nullptr;
    WaPolygon forced_clipper = first ? *first : WaPolygon{};
    while (!list.empty()) {
      if (!forced) sort_list(list, level);
      const WaPolygon clipper = forced ? forced_clipper : list.front();
      forced = false;
      std::vector<WaPolygon> inside, outside;
      for (const WaPolygon& p : list) split_by(p, clipper, inside, outside);
      if (inside.size() + outside.size() > opt_.max_polygons) too_many();
      ++res_.clips;
      if (opt_.trace) {
        WaStep s;
        s.kind = WaStep::Kind::Clip;
        s.level = level;
        s.polygons = {clipper};
        s.inside = inside;
        s.outside = outside;
        res_.steps.push_back(std::move(s));
      }
      resolve(std::move(inside), clipper, level);
      list = std::move(outside);
      if (level == 0 && progress_enabled() && res_.clips % 64 == 0)  // the outer loop, where a long run spends its time
        progress("Weiler-Atherton: " + std::to_string(res_.clips) + " clips, " + std::to_string(list.size()) + " polygons left");
    }
  }

  // Steps 3 and 4 on the inside list (all of it within the clipper's outline).
  void resolve(std::vector<WaPolygon> inside, const WaPolygon& clipper, int level) {
    std::vector<WaPolygon> kept;
    std::optional<WaPolygon> violator;
    for (WaPolygon& p : inside) {
      if (p.body == clipper.body && p.face == clipper.face && p.piece == clipper.piece) {
        kept.push_back(p);
        continue;
      }
      PictureLinear n = nearness(id(p), id(clipper), p.pts[0]);
      int pos = 0, neg = 0;
      std::vector<Rational> vals;
      for (const Exact2& q : p.pts) {
        vals.push_back(n.at(q));
        pos += vals.back() > 0, neg += vals.back() < 0;
      }
      bool tie = pos == 0 && neg == 0;
      if ((pos == 0 && !tie) || (tie && !wins_tie(p, clipper))) {
        trace(WaStep::Kind::Hidden, level, p, clipper, vals);
        continue;
      }
      if (pos > 0 && neg > 0) {
        // They pierce each other: cut along the line where the planes meet.
        std::vector<Exact2> front = clip_half(p.pts, n, 1), back = clip_half(p.pts, n, -1);
        ++res_.splits;
        if (opt_.trace) {
          WaStep s;
          s.kind = WaStep::Kind::Split;
          s.level = level;
          s.subject = p;
          s.polygons = {WaPolygon{p.body, p.face, p.piece, front, {}}, WaPolygon{p.body, p.face, p.piece, back, {}}};
          s.depths = vals;
          res_.steps.push_back(std::move(s));
        }
        p.pts = std::move(front);
        p.nearest.reset();
        if (p.pts.empty()) continue;
      }
      trace(WaStep::Kind::Violation, level, p, clipper, vals);
      kept.push_back(p);
      if (!violator) violator = p;
    }
    if (!violator) {
      for (const WaPolygon& p : kept) display(p, level);
      return;
    }
    // Step 4: subdivide again with the polygon that is in front as the clipper.
    ++res_.recursions;
    std::tuple<int, int, int> key{violator->body, violator->face, violator->piece};
    if (std::find(clippers_.begin(), clippers_.end(), key) != clippers_.end()) {
      ++res_.cycles;  // the notes' cyclic overlap: it clipped before
      trace(WaStep::Kind::Cycle, level, *violator, clipper, {});
    }
    clippers_.push_back(key);
    run_list(std::move(kept), level + 1, &*violator);
    clippers_.pop_back();
  }

  void display(const WaPolygon& p, int level) {
    res_.visible.push_back(p);
    if (opt_.trace) {
      WaStep s;
      s.kind = WaStep::Kind::Display;
      s.level = level;
      s.subject = p;
      res_.steps.push_back(std::move(s));
    }
  }

  void trace(WaStep::Kind k, int level, const WaPolygon& p, const WaPolygon& clipper, const std::vector<Rational>& vals) {
    if (!opt_.trace) return;
    WaStep s;
    s.kind = k;
    s.level = level;
    s.subject = p;
    s.polygons = {clipper};
    s.depths = vals;
    res_.steps.push_back(std::move(s));
  }

  // The doubles' box of a polygon, widened far beyond their error: boxes apart mean polygons
  // apart (a filter that only skips work).
  static std::array<double, 4> box_of(const WaPolygon& p) {
    std::array<double, 4> b{INFINITY, INFINITY, -INFINITY, -INFINITY};
    for (const Exact2& q : p.pts) {
      double x = q[0].get_d(), y = q[1].get_d();
      b = {std::min(b[0], x), std::min(b[1], y), std::max(b[2], x), std::max(b[3], y)};
    }
    double pad = box_pad({b[0], b[1], b[2], b[3]});
    return {b[0] - pad, b[1] - pad, b[2] + pad, b[3] + pad};
  }

  // p ∩ clipper into `inside`, p minus clipper as convex pieces into `outside`.
  void split_by(const WaPolygon& p, const WaPolygon& c, std::vector<WaPolygon>& inside, std::vector<WaPolygon>& outside) {
    const auto pb = box_of(p), cb = box_of(c);
    if (pb[2] < cb[0] || cb[2] < pb[0] || pb[3] < cb[1] || cb[3] < pb[1]) {
      outside.push_back(p);  // apart: all of it is outside
      return;
    }
    std::vector<Exact2> rest = p.pts;
    const std::size_t n = c.pts.size();
    for (std::size_t k = 0; k < n && !rest.empty(); ++k) {
      PictureLinear f = left_of(c.pts[k], c.pts[(k + 1) % n]);
      std::vector<Exact2> out = clip_half(rest, f, -1);
      if (!out.empty()) outside.push_back(WaPolygon{p.body, p.face, p.piece, std::move(out), {}});
      rest = clip_half(rest, f, 1);
    }
    if (!rest.empty()) inside.push_back(WaPolygon{p.body, p.face, p.piece, std::move(rest), {}});
  }

  const std::vector<const Polyhedron*>& bodies_;
  PicturePlane pp_;
  const WeilerAthertonOptions& opt_;
  std::vector<int> offset_;
  std::vector<std::array<PictureLinear, 2>> rays_;
  std::vector<char> front_;
  std::vector<std::tuple<int, int, int>> clippers_;
  WeilerAthertonResult res_;
};

}  // namespace

WeilerAthertonResult weiler_atherton(const std::vector<const Polyhedron*>& bodies, const Camera& camera, const LineDrawing& lines,
                                     const WeilerAthertonOptions& options) {
  for (const Polyhedron* p : bodies) plane_all_faces(*p);
  if (camera.perspective)
    for (std::size_t b = 0; b < bodies.size(); ++b)
      for (const Point3& v : bodies[b]->vertices())
        if (camera.in_front(v) != Sign::Positive)
          throw std::invalid_argument("Weiler-Atherton: body " + std::to_string(b) + " reaches the eye's plane or behind it");
  Wa wa(bodies, camera, options);
  std::vector<WaPolygon> polys;
  for (ScenePolygon& p : scene_polygons(bodies, wa.picture(), lines)) polys.push_back(WaPolygon{p.body, p.face, p.piece, std::move(p.pts), {}});
  return wa.run(std::move(polys));
}

Rational wa_nearest_depth(const WaPolygon& p, const std::vector<const Polyhedron*>& bodies, const Camera& camera) {
  PicturePlane pp(camera);
  auto r = pp.ray_parameter(bodies[p.body]->planes()[p.face]);
  Rational best;
  bool first = true;
  for (const Exact2& q : p.pts) {
    Rational v = r[0].at(q) / r[1].at(q);
    if (camera.perspective) v = -v;
    if (first || v > best) best = v;
    first = false;
  }
  return best;
}

}  // namespace hlr
