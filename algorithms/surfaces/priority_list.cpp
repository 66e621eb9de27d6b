// The priority-list (painter's) algorithm, exact (course notes sections 32-34, part 3.3). See
// priority_list.hpp; why a list painted this way is right and why it ends: docs/design.md,
// "The priority list, exact".
#include "algorithms/surfaces/priority_list.hpp"

#include "algorithms/support/parallel.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <stdexcept>

#include "algorithms/picture/picture_box.hpp"
#include "kernel/predicates.hpp"

namespace hlr {
namespace {

// Which sides of a plane a polygon's corners take, counted from the eye: near (the eye's side),
// far, and on the plane.
struct Sides {
  int near = 0, far = 0, on = 0;
  bool in_plane() const { return near == 0 && far == 0; }
};

using Box = PictureBox;

class Painter {
 public:
  Painter(const std::vector<const Polyhedron*>& bodies, const Camera& cam, const PriorityOptions& opt)
      : bodies_(bodies), cam_(cam), pp_(cam), opt_(opt) {
    for (std::size_t b = 0, id = 0; b < bodies.size(); ++b) {
      offset_.push_back(static_cast<int>(id));
      for (std::size_t f = 0; f < bodies[b]->num_faces(); ++f, ++id) {
        const Plane& h = bodies[b]->planes()[f];
        eye_.push_back(cam.perspective ? sgn(h.value(cam.eye))
                                       : sgn(h.a() * cam.direction.x() + h.b() * cam.direction.y() + h.c() * cam.direction.z()));
      }
    }
  }

  const PicturePlane& picture() const { return pp_; }

  PriorityResult run(std::vector<ScenePolygon> first) {
    res_.polygons.reserve(first.size() + first.size() / 4 + 16);  // parts rarely need more: few copies of exact corners
    for (ScenePolygon& p : first) {
      PriorityPolygon q{p.body, p.face, p.piece, static_cast<int>(res_.polygons.size()), std::move(p.corners), std::move(p.pts), {}, {}};
      add(std::move(q));
    }
    res_.initial = res_.polygons.size();
    if (!opt_.trace && res_.initial > 64) build_grid();
    Order cmp{&res_.polygons};
    std::set<int, Order> rest(cmp);
    for (std::size_t i = 0; i < res_.polygons.size(); ++i) rest.insert(static_cast<int>(i));
    if (opt_.trace) {
      PriorityStep s;
      s.kind = PriorityStep::Kind::Sort;
      s.list.assign(rest.begin(), rest.end());
      res_.steps.push_back(std::move(s));
    }
    std::vector<int> front;  // polygons moved to the head of the list, the head last
    while (!front.empty() || !rest.empty()) {
      const int a = front.empty() ? *rest.begin() : front.back();
      Outcome o = examine(a, front, rest);
      if (o.kind == Outcome::Paint) {
        if (!front.empty() && front.back() == a)
          front.pop_back();
        else
          rest.erase(a);
        state_[a] = kGone;
        res_.order.push_back(a);
        if (opt_.trace) trace_pair(PriorityStep::Kind::Paint, a, -1);
      } else if (o.kind == Outcome::Swap) {
        ++res_.swaps;
        if (opt_.trace) trace_pair(PriorityStep::Kind::Swap, a, o.b);
        rest.erase(o.b);
        marked_[o.b] = 1;
        front.push_back(o.b);
        state_[o.b] = kFront;
      } else {
        split(o, front, rest);
      }
    }
    return std::move(res_);
  }

 private:
  struct Order {
    const std::vector<PriorityPolygon>* p;
    bool operator()(int x, int y) const {
      int c = cmp((*p)[x].zmin, (*p)[y].zmin);
      return c != 0 ? c < 0 : x < y;
    }
  };
  struct Outcome {
    enum Kind { Paint, Swap, Split } kind = Paint;
    int b = -1;
    bool cycle = false;
  };

  int fid(int i) const { return offset_[res_.polygons[i].body] + res_.polygons[i].face; }
  const Plane& plane(int i) const { return bodies_[res_.polygons[i].body]->planes()[res_.polygons[i].face]; }
  int eye(int i) const { return eye_[fid(i)]; }

  // Larger is nearer: orthographic P·v, perspective -(P - E)·(target - E).
  Rational depth(const Point3& v) const {
    if (cam_.perspective) return -cam_.depth(v);
    return v.x() * cam_.direction.x() + v.y() * cam_.direction.y() + v.z() * cam_.direction.z();
  }

  int add(PriorityPolygon p) {
    if (res_.polygons.size() >= opt_.max_polygons)
      throw std::invalid_argument("priority list: more than " + std::to_string(opt_.max_polygons) + " polygons after the cuts");
    p.zmin = p.zmax = depth(p.corners[0]);
    for (const Point3& c : p.corners) {
      Rational z = depth(c);
      if (z < p.zmin) p.zmin = z;
      if (z > p.zmax) p.zmax = z;
    }
    std::array<Rational, 4> ex{p.pts[0][0], p.pts[0][1], p.pts[0][0], p.pts[0][1]};
    for (const Exact2& q : p.pts)
      for (int k = 0; k < 2; ++k) {
        if (q[k] < ex[k]) ex[k] = q[k];
        if (q[k] > ex[k + 2]) ex[k + 2] = q[k];
      }
    exact_box_.push_back(std::move(ex));
    box_.push_back(picture_box(p.pts));
    std::vector<std::array<double, 2>> d;
    for (const Exact2& q : p.pts) d.push_back({q[0].get_d(), q[1].get_d()});
    dpts_.push_back(std::move(d));
    marked_.push_back(0);
    state_.push_back(kRest);
    res_.polygons.push_back(std::move(p));
    return static_cast<int>(res_.polygons.size()) - 1;
  }

  // The sides of polygon x's corners against the plane of polygon y.
  Sides sides(int x, int y, std::vector<Rational>* values) const {
    const Plane& h = plane(y);
    const int eye_sign = eye(y);
    const auto& on_plane = res_.polygons[y].corners;
    Sides s;
    for (const Point3& v : res_.polygons[x].corners) {
      int k;
      if (values) {  // the exam page shows the values
        values->push_back(h.value(v));
        k = sgn(values->back()) * eye_sign;
      } else if (std::find(on_plane.begin(), on_plane.end(), v) != on_plane.end()) {
        k = 0;  // a corner of y (a shared vertex of a mesh): on its plane, no arithmetic
      } else {
        k = static_cast<int>(side_of_plane(h, v)) * eye_sign;  // filtered, exact
      }
      (k > 0 ? s.near : k < 0 ? s.far : s.on)++;
    }
    return s;
  }

  // Equal depth everywhere: the face toward the viewer, then the lower face number, is seen.
  bool wins_tie(int x, int y) const {
    int a = fid(x), b = fid(y);
    bool fa = eye_[a] > 0, fb = eye_[b] > 0;
    if (fa != fb) return fa;
    return a < b;
  }

  // Tests 1 and 2: the boxes apart along axis k (touching is apart: the interiors do not meet).
  bool apart(int a, int b, int k) const {
    const Box &x = box_[a], &y = box_[b];
    if (x.ok && y.ok && (x.hi[k] < y.lo[k] || y.hi[k] < x.lo[k])) return true;
    const auto &ex = exact_box_[a], &ey = exact_box_[b];
    return ex[k + 2] <= ey[k] || ey[k + 2] <= ex[k];
  }

  // Test 5: the projections' interiors do not meet (convex polygons: some side of one has all
  // of the other on or outside it).
  bool separated_by_side(int i, int j) const {
    const auto &p = res_.polygons[i].pts, &q = res_.polygons[j].pts;
    const auto &dp = dpts_[i], &dq = dpts_[j];
    for (std::size_t k = 0; k < p.size(); ++k) {
      const std::size_t k1 = (k + 1) % p.size();
      bool all_out = true;
      for (std::size_t m = 0; m < q.size(); ++m)
        if (orient2d(p[k], p[k1], q[m], dp[k], dp[k1], dq[m]) > 0) {
          all_out = false;
          break;
        }
      if (all_out) return true;
    }
    return false;
  }
  bool disjoint(int a, int b) const { return separated_by_side(a, b) || separated_by_side(b, a); }

  // The notes' tests for the head A against B. Returns the first yes (1-5) or 0, and in
  // `swapped` whether B may go before A (3: B wholly on the far side of A's plane, 4: A wholly
  // on the near side of B's plane).
  int tests(int a, int b, int& swapped, Sides& sa, Sides& sb, PriorityStep* st) {
    ++res_.pairs;
    swapped = 0;
    const bool all = st != nullptr;
    std::vector<Rational>* va = st ? &st->f_b_at_a : nullptr;
    std::vector<Rational>* vb = st ? &st->f_a_at_b : nullptr;
    int first = 0;
    if (apart(a, b, 0)) first = 1;
    else if (apart(a, b, 1)) first = 2;
    bool have_a = false, have_b = false;
    if (!first || all) sa = sides(a, b, va), have_a = true;
    if (!first && (sa.in_plane() ? wins_tie(b, a) : sa.near == 0)) first = 3;
    if (!first || all) sb = sides(b, a, vb), have_b = true;
    if (!first && (sb.in_plane() ? wins_tie(b, a) : sb.far == 0)) first = 4;
    if (!first && disjoint(a, b)) first = 5;
    if (first) ++res_.passed[first];
    if (!first || all) {
      if (!have_a) sa = sides(a, b, nullptr);
      if (!have_b) sb = sides(b, a, nullptr);
      if (sb.in_plane() ? wins_tie(a, b) : sb.near == 0) swapped = 3;
      else if (sa.in_plane() ? wins_tie(a, b) : sa.far == 0) swapped = 4;
    }
    return first;
  }

  // Every polygon that A might hide: those moved to the head (below A) and the rest of the list
  // up to the first whose farthest corner is nearer than A's nearest.
  Outcome examine(int a, const std::vector<int>& front, const std::set<int, Order>& rest) {
    const Rational& top = res_.polygons[a].zmax;
    auto check = [&](int b, Outcome& o) {
      if (b == a || res_.polygons[b].zmin > top) return false;
      int swapped = 0;
      Sides sa, sb;
      PriorityStep* st = nullptr;
      if (opt_.trace) {
        res_.steps.emplace_back();
        st = &res_.steps.back();
        st->kind = PriorityStep::Kind::Tests;
        st->a = a, st->b = b, st->eye_a = eye(a), st->eye_b = eye(b);
      }
      int first = tests(a, b, swapped, sa, sb, st);
      if (st) st->passed = first, st->swapped = swapped;
      if (first) return false;
      o.b = b;
      if (swapped && !marked_[b]) {
        o.kind = Outcome::Swap;
        return true;
      }
      o.kind = Outcome::Split;
      o.cycle = swapped != 0;
      return true;
    };
    Outcome o;
    if (grid_.on) {
      // Only the polygons whose boxes share a cell with A's: for the others test 1 or 2 says
      // yes. Put to the tests in the same order as the full scan, so the outcome is the same.
      std::vector<int> cand = grid_candidates(a, top);
      auto rank = [&](int id) { return state_[id] == kFront ? static_cast<long>(front.rend() - std::find(front.rbegin(), front.rend(), id)) : 0L; };
      std::sort(cand.begin(), cand.end(), [&](int x, int y) {
        long rx = rank(x), ry = rank(y);
        if ((rx > 0) != (ry > 0)) return rx > 0;
        if (rx > 0) return rx > ry;
        return Order{&res_.polygons}(x, y);
      });
      for (int b : cand)
        if (check(b, o)) return o;
      return o;
    }
    for (auto it = front.rbegin(); it != front.rend(); ++it)
      if (check(*it, o)) return o;
    for (int b : rest) {
      if (res_.polygons[b].zmin > top) break;
      if (check(b, o)) return o;
    }
    return o;
  }

  // A uniform grid over the picture boxes (doubles, widened): two polygons that share no cell
  // have boxes apart (the cell of a point is monotone in the point, so boxes that meet share
  // the cell of a common point), which is test 1 or 2 answering yes.
  void build_grid() {
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (const Box& b : box_) {
      if (!b.ok) return;
      for (int k = 0; k < 2; ++k) lo[k] = std::min(lo[k], b.lo[k]), hi[k] = std::max(hi[k], b.hi[k]);
    }
    const int n = static_cast<int>(std::min<double>(2048, std::ceil(std::sqrt(static_cast<double>(box_.size())))));
    grid_.nx = grid_.ny = std::max(n, 1);
    grid_.x0 = lo[0], grid_.y0 = lo[1];
    grid_.cw = (hi[0] - lo[0]) / grid_.nx, grid_.ch = (hi[1] - lo[1]) / grid_.ny;
    if (!(grid_.cw > 0) || !(grid_.ch > 0) || !std::isfinite(grid_.cw) || !std::isfinite(grid_.ch)) return;
    grid_.cells.assign(static_cast<std::size_t>(grid_.nx) * grid_.ny, {});
    grid_.on = true;
    for (std::size_t i = 0; i < box_.size(); ++i) grid_insert(static_cast<int>(i));
  }
  std::array<int, 4> grid_range(const Box& b) const {
    auto cell = [](double v, double o, double w, int n) { return std::clamp(static_cast<int>(std::floor((v - o) / w)), 0, n - 1); };
    return {cell(b.lo[0], grid_.x0, grid_.cw, grid_.nx), cell(b.lo[1], grid_.y0, grid_.ch, grid_.ny),
            cell(b.hi[0], grid_.x0, grid_.cw, grid_.nx), cell(b.hi[1], grid_.y0, grid_.ch, grid_.ny)};
  }
  void grid_insert(int id) {
    if (!grid_.on) return;
    if (!box_[id].ok) {  // doubles lost this part: no grid from here on
      grid_.on = false;
      return;
    }
    auto r = grid_range(box_[id]);
    for (int y = r[1]; y <= r[3]; ++y)
      for (int x = r[0]; x <= r[2]; ++x) grid_.cells[static_cast<std::size_t>(y) * grid_.nx + x].push_back(id);
  }
  std::vector<int> grid_candidates(int a, const Rational& top) {
    ++stamp_;
    if (seen_.size() < res_.polygons.size()) seen_.resize(res_.polygons.size(), 0);
    std::vector<int> out;
    auto r = grid_range(box_[a]);
    for (int y = r[1]; y <= r[3]; ++y)
      for (int x = r[0]; x <= r[2]; ++x)
        for (int id : grid_.cells[static_cast<std::size_t>(y) * grid_.nx + x]) {
          if (seen_[id] == stamp_) continue;
          seen_[id] = stamp_;
          if (id == a || state_[id] == kGone || res_.polygons[id].zmin > top) continue;
          out.push_back(id);
        }
    return out;
  }

  // Sutherland–Hodgman in space: the part of polygon i where sign·h >= 0, cut exactly where the
  // test function changes sign; nothing when the part has no area in the picture.
  std::optional<PriorityPolygon> part(const PriorityPolygon& p, int sign, const std::vector<Rational>& f) const {
    const std::size_t n = p.corners.size();
    PriorityPolygon out{p.body, p.face, p.piece, p.source, {}, {}, {}, {}};
    auto keep = [&](const Point3& c) {
      Exact2 q = pp_.project(c);
      if (!out.pts.empty() && out.pts.back() == q) return;
      out.corners.push_back(c), out.pts.push_back(std::move(q));
    };
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t j = (k + 1) % n;
      int sk = sign * sgn(f[k]), sj = sign * sgn(f[j]);
      if (sk >= 0) keep(p.corners[k]);
      if (sk * sj < 0) {
        Rational t = f[k] / (f[k] - f[j]);
        const Point3 &A = p.corners[k], &B = p.corners[j];
        keep(Point3(A.x() + t * (B.x() - A.x()), A.y() + t * (B.y() - A.y()), A.z() + t * (B.z() - A.z())));
      }
    }
    while (out.pts.size() > 1 && out.pts.front() == out.pts.back()) out.pts.pop_back(), out.corners.pop_back();
    if (out.pts.size() < 3 || picture_area2(out.pts) == 0) return std::nullopt;
    return out;
  }

  // Polygon i cut by plane h into its two sides (one part when h does not cross it).
  std::vector<PriorityPolygon> cut(int i, const Plane& h, std::vector<Rational>& values) const {
    values.clear();
    for (const Point3& c : res_.polygons[i].corners) values.push_back(h.value(c));
    std::vector<PriorityPolygon> parts;
    for (int sign : {1, -1})
      if (auto q = part(res_.polygons[i], sign, values)) parts.push_back(std::move(*q));
    return parts;
  }

  // Polygon i cut along the picture outline of polygon j: the planes through the eye (or along
  // the view) and each side of j; the parts outside j, then the part inside.
  std::vector<PriorityPolygon> cut_by_outline(int i, int j) const {
    const PriorityPolygon& c = res_.polygons[j];
    std::vector<PriorityPolygon> parts;
    PriorityPolygon rest = res_.polygons[i];
    const std::size_t n = c.corners.size();
    for (std::size_t k = 0; k < n; ++k) {
      const Point3 &A = c.corners[k], &B = c.corners[(k + 1) % n];
      Vector3 nrm = cam_.perspective ? cross(A - cam_.eye, B - cam_.eye) : cross(B - A, cam_.direction);
      Plane h(nrm.x(), nrm.y(), nrm.z(), -(nrm.x() * A.x() + nrm.y() * A.y() + nrm.z() * A.z()));
      int inside = 0;
      for (const Point3& v : c.corners)
        if (int s = sgn(h.value(v))) inside = s;
      if (inside == 0) return {};
      std::vector<Rational> f;
      for (const Point3& v : rest.corners) f.push_back(h.value(v));
      auto out = part(rest, -inside, f);
      auto in = part(rest, inside, f);
      if (out && in) parts.push_back(std::move(*out));
      if (!in) return {};  // cannot happen for polygons whose outlines overlap
      rest = std::move(*in);
    }
    parts.push_back(std::move(rest));
    return parts;
  }

  void split(const Outcome& o, std::vector<int>& front, std::set<int, Order>& rest) {
    const int a = front.empty() ? *rest.begin() : front.back();
    const int b = o.b;
    if (o.cycle) {
      ++res_.cycles;
      if (opt_.trace) trace_pair(PriorityStep::Kind::Cycle, a, b);
    }
    // The notes: A is cut by B's plane. A cyclic pair where A does not cross B's plane: B by
    // A's plane; where neither crosses the other's plane (the cycle runs through other
    // polygons): A along B's outline, or B along A's.
    Sides sa = sides(a, b, nullptr);
    Sides sb = sides(b, a, nullptr);
    int victim = a, cutter = b;
    std::vector<PriorityPolygon> parts;
    std::vector<Rational> values;
    bool outline = false;
    if (sa.near > 0 && sa.far > 0) {
      parts = cut(a, plane(b), values);
    } else if (sb.near > 0 && sb.far > 0) {
      victim = b, cutter = a;
      parts = cut(b, plane(a), values);
    } else {
      outline = true;
      parts = cut_by_outline(a, b);
      if (parts.size() < 2) victim = b, cutter = a, parts = cut_by_outline(b, a);
      if (parts.size() < 2) throw std::logic_error("priority list: a cyclic overlap that no cut breaks");
    }
    if (parts.size() < 2) throw std::logic_error("priority list: a cut that made no parts");
    ++res_.splits;
    if (outline) ++res_.outline_splits;
    auto pos = std::find(front.begin(), front.end(), victim);
    if (pos != front.end())
      front.erase(pos);
    else
      rest.erase(victim);
    state_[victim] = kGone;
    PriorityStep st;
    st.kind = PriorityStep::Kind::Split;
    st.a = victim, st.b = cutter, st.values = std::move(values), st.along_outline = outline;
    for (PriorityPolygon& p : parts) {
      int id = add(std::move(p));
      rest.insert(id);
      grid_insert(id);
      st.parts.push_back(id);
    }
    if (opt_.trace) res_.steps.push_back(std::move(st));
  }

  void trace_pair(PriorityStep::Kind k, int a, int b) {
    PriorityStep s;
    s.kind = k;
    s.a = a, s.b = b;
    res_.steps.push_back(std::move(s));
  }

  const std::vector<const Polyhedron*>& bodies_;
  const Camera& cam_;
  PicturePlane pp_;
  const PriorityOptions& opt_;
  std::vector<int> offset_;
  std::vector<int> eye_;  // per face: the sign of its plane's function on the eye's side
  std::vector<std::array<Rational, 4>> exact_box_;
  std::vector<Box> box_;
  std::vector<std::vector<std::array<double, 2>>> dpts_;  // the pictures in doubles, for the filter
  std::vector<char> marked_;
  enum : char { kRest, kFront, kGone };
  std::vector<char> state_;  // where each polygon is: in the sorted rest, moved to the head, or painted or cut
  struct Grid {
    bool on = false;
    double x0 = 0, y0 = 0, cw = 0, ch = 0;
    int nx = 0, ny = 0;
    std::vector<std::vector<int>> cells;
  } grid_;
  std::vector<unsigned> seen_;
  unsigned stamp_ = 0;
  PriorityResult res_;
};

}  // namespace

PriorityResult priority_list(const std::vector<const Polyhedron*>& bodies, const Camera& camera, const LineDrawing& lines,
                             const PriorityOptions& options) {
  for (const Polyhedron* p : bodies) plane_all_faces(*p);
  if (camera.perspective)
    for (std::size_t b = 0; b < bodies.size(); ++b)
      for (const Point3& v : bodies[b]->vertices())
        if (camera.in_front(v) != Sign::Positive)
          throw std::invalid_argument("priority list: body " + std::to_string(b) + " reaches the eye's plane or behind it");
  Painter painter(bodies, camera, options);
  return painter.run(scene_polygons(bodies, painter.picture(), lines));
}

}  // namespace hlr
