// Per-face occluders (see face_occluders.hpp): the scene scaled to integers under the
// narrowest number policy whose bound holds (exact_int.hpp: 64-bit, 128-bit, fixed-width
// multi-limb, then GMP), then the engine (face_engine.hpp).
#include "algorithms/hlr/face_occluders.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <numeric>
#include <optional>
#include <unordered_map>

#include "algorithms/hlr/face_engine.hpp"
#include "algorithms/support/parallel.hpp"
#include "kernel/exact_int.hpp"

namespace hlr {
namespace {

// The orthographic view direction as integers: its own common denominator, then divided by
// the components' greatest common divisor. False when a component reaches `bits` bits.
template <class P>
bool direction_fast(const Camera& cam, int bits, Vec<P>& view) {
  const Rational* d[3] = {&cam.direction[0], &cam.direction[1], &cam.direction[2]};
  std::uint64_t Ld = 1;
  if (!common_denominator(d, 3, std::uint64_t(1) << bounds::kDenominatorBits, Ld)) return false;
  Int128 s[3];
  for (int k = 0; k < 3; ++k)
    if (!scaled_integer(*d[k], Ld, Int128(1) << 62, s[k])) return false;
  Int128 g = gcd128(gcd128(s[0], s[1]), s[2]);
  for (int k = 0; k < 3; ++k) {
    s[k] /= g;
    if (abs128(s[k]) >= (Int128(1) << bits)) return false;
    view[k] = static_cast<typename P::C>(s[k]);
  }
  return true;
}

// The same in GMP integers (`reduce`: divided by the greatest common divisor).
void direction_gmp(const Camera& cam, mpz_class (&s)[3], bool reduce) {
  mpz_class Ld = 1, g = 0;
  for (int k = 0; k < 3; ++k) mpz_lcm(Ld.get_mpz_t(), Ld.get_mpz_t(), cam.direction[k].get_den_mpz_t());
  for (int k = 0; k < 3; ++k) {
    s[k] = cam.direction[k].get_num() * (Ld / cam.direction[k].get_den());
    mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), s[k].get_mpz_t());
  }
  for (int k = 0; k < 3 && reduce; ++k)
    if (g != 0) mpz_divexact(s[k].get_mpz_t(), s[k].get_mpz_t(), g.get_mpz_t());
}

// The multi-limb path's: false when a component is not below its bound.
bool direction_wide(const Camera& cam, Vec<Wide>& view) {
  mpz_class s[3];
  direction_gmp(cam, s, true);
  for (int k = 0; k < 3; ++k) {
    if (mpz_sizeinbase(s[k].get_mpz_t(), 2) > std::size_t(Wide::kBits)) return false;
    view[k] = Wide::C(s[k].get_mpz_t());
  }
  return true;
}

// The lowest common denominator of a compact store's (point_store.hpp) coordinates: den / g, g
// the greatest common divisor of den and every numerator (num / den in lowest terms has the
// denominator den / gcd(den, num), and the least common multiple of such divisors' cofactors
// is den over their greatest common divisor).
std::uint64_t compact_denominator(const PointStore& store, const ParallelLoop& loop) {
  const auto den = static_cast<std::uint64_t>(store.denominator());
  const auto& nums = store.numerators();
  PerWorker<std::uint64_t> part(loop, den);
  loop.run(nums.size(), 16384, [&](unsigned w, std::size_t b, std::size_t e) {
    std::uint64_t g = part[w];
    for (std::size_t i = b; i < e && g > 1; ++i)
      for (int k = 0; k < 3; ++k) g = std::gcd(g, static_cast<std::uint64_t>(nums[i][k] < 0 ? -nums[i][k] : nums[i][k]));
    part[w] = g;
  });
  std::uint64_t g = den;
  for (unsigned w = 0; w < part.size(); ++w) g = std::gcd(g, part[w]);
  return den / g;
}

// Every vertex of every body scaled on all cores into `pts` (body after body), one coordinate at
// a time by `scaler()`'s function (made per chunk of vertices: it may keep scratch numbers),
// which returns false for a value that does not fit. False when one does not.
// A compact store's (point_store.hpp) vertices scaled to the common denominator L: num / den =
// (num / h)·(L / Lb), Lb = compact_denominator(store) and h = den / Lb (both exact divisions).
template <class P>
bool scale_compact(const PointStore& store, std::uint64_t L, Int128 limit, const ParallelLoop& loop, Vec<P>* out) {
  const auto den = static_cast<std::uint64_t>(store.denominator());
  const std::uint64_t Lb = compact_denominator(store, loop), h = den / Lb;
  const Int128 times = static_cast<Int128>(L / Lb);
  const auto& nums = store.numerators();
  PerWorker<char> fits(loop, 1);
  loop.run(nums.size(), 4096, [&](unsigned w, std::size_t b, std::size_t e) {
    for (std::size_t i = b; i < e && fits[w]; ++i)
      for (int k = 0; k < 3; ++k) {
        const Int128 v = static_cast<Int128>(nums[i][k] / static_cast<std::int64_t>(h)) * times;
        if (abs128(v) >= limit) fits[w] = 0;
        else out[i][k] = static_cast<typename P::C>(v);
      }
  });
  for (unsigned w = 0; w < fits.size(); ++w)
    if (!fits[w]) return false;
  return true;
}

template <class P, class Scaler>
bool scale_vertices(const std::vector<const Polyhedron*>& bodies, std::size_t total, const ParallelLoop& loop, std::vector<Vec<P>>& pts,
                    const Scaler& scaler, std::uint64_t L = 0, Int128 limit = 0) {
  constexpr std::size_t kChunk = 4096;  // vertices
  pts.clear();
  reserve_touched(pts, total, loop);
  pts.resize(total);
  std::size_t at = 0;
  for (const Polyhedron* p : bodies) {
    if (L != 0 && p->vertex_store().compact()) {
      if (!scale_compact<P>(p->vertex_store(), L, limit, loop, pts.data() + at)) return false;
      at += p->num_vertices();
      continue;
    }
    const std::vector<Point3>& vs = p->vertices();
    std::vector<char> ok((vs.size() + kChunk - 1) / kChunk, 1);
    loop.for_each(ok.size(), 1, [&](std::size_t c) {
      auto one = scaler();
      for (std::size_t i = c * kChunk, e = std::min(vs.size(), i + kChunk); i < e && ok[c]; ++i)
        for (int k = 0; k < 3 && ok[c]; ++k) ok[c] = one(vs[i][k], pts[at + i][k]);
    });
    if (std::find(ok.begin(), ok.end(), 0) != ok.end()) return false;
    at += vs.size();
  }
  return true;
}

// Scale every coordinate (and the eye) by a common denominator; the view direction by its own.
// False when a scaled value reaches `bits` bits (then a wider policy takes the scene).
template <class P>
bool scale_fast(const std::vector<const Polyhedron*>& bodies, const Camera& cam, int bits, std::vector<Vec<P>>& pts,
                Vec<P>& view, Rational& scale, unsigned threads) {
  const Int128 kLimit = Int128(1) << bits;
  const std::uint64_t kDenLimit = std::uint64_t(1) << bounds::kDenominatorBits;
  const ParallelLoop loop(threads);
  constexpr std::size_t kChunk = 4096;  // vertices
  // The common denominator per fixed chunk on all cores, then combined in order (the least
  // common multiple does not depend on the grouping; any part over the limit puts it over).
  std::uint64_t L = 1;
  auto combine = [&](std::uint64_t d) {
    const UInt128 l = static_cast<UInt128>(L / std::gcd(L, d)) * d;
    if (l >= kDenLimit) return false;
    L = static_cast<std::uint64_t>(l);
    return true;
  };
  std::size_t total = 0;
  for (const Polyhedron* p : bodies) {
    const PointStore& store = p->vertex_store();
    total += store.size();
    if (store.compact()) {
      if (!combine(compact_denominator(store, loop))) return false;
      continue;
    }
    const std::vector<Point3>& vs = p->vertices();
    const std::size_t chunks = (vs.size() + kChunk - 1) / kChunk;
    std::vector<std::uint64_t> part(chunks, 1);
    std::vector<char> fits(chunks, 1);
    loop.for_each(chunks, 1, [&](std::size_t c) {
      std::vector<const Rational*> qs;
      for (std::size_t i = c * kChunk, e = std::min(vs.size(), i + kChunk); i < e; ++i)
        for (int k = 0; k < 3; ++k) qs.push_back(&vs[i][k]);
      fits[c] = common_denominator(qs.data(), static_cast<int>(qs.size()), kDenLimit, part[c]);
    });
    for (std::size_t c = 0; c < chunks; ++c)
      if (!fits[c] || !combine(part[c])) return false;
  }
  if (cam.perspective) {
    const Rational* eye[3] = {&cam.eye[0], &cam.eye[1], &cam.eye[2]};
    std::uint64_t Le = 1;
    if (!common_denominator(eye, 3, kDenLimit, Le) || !combine(Le)) return false;
  }
  const auto scaler = [&] {
    return [&](const Rational& q, typename P::C& out) {
      Int128 s;
      if (!scaled_integer(q, L, kLimit, s)) return false;
      out = static_cast<typename P::C>(s);
      return true;
    };
  };
  if (!scale_vertices<P>(bodies, total, loop, pts, scaler, L, kLimit)) return false;
  if (cam.perspective) {
    for (int k = 0; k < 3; ++k) {
      Int128 s;
      if (!scaled_integer(cam.eye[k], L, kLimit, s)) return false;
      view[k] = static_cast<typename P::C>(s);
    }
  } else if (!direction_fast<P>(cam, bits, view)) {
    return false;
  }
  scale = Rational(static_cast<unsigned long>(L));
  return true;
}

// The common denominator of every coordinate and the eye in GMP integers: per chunk of
// vertices on all cores, then of those. Stops once it passes `stop_bits` bits (0: never).
mpz_class gmp_common_denominator(const std::vector<const Polyhedron*>& bodies, const Camera& cam, const ParallelLoop& loop, int stop_bits) {
  constexpr std::size_t kChunk = 4096;  // vertices
  mpz_class L = 1;
  for (const Polyhedron* p : bodies) {
    const std::vector<Point3>& vs = p->vertices();
    std::vector<mpz_class> part((vs.size() + kChunk - 1) / kChunk, 1);
    loop.for_each(part.size(), 1, [&](std::size_t c) {
      mpz_ptr l = part[c].get_mpz_t();
      for (std::size_t i = c * kChunk, e = std::min(vs.size(), i + kChunk); i < e; ++i)
        for (int k = 0; k < 3; ++k)
          if (!mpz_divisible_p(l, vs[i][k].get_den_mpz_t())) mpz_lcm(l, l, vs[i][k].get_den_mpz_t());
    });
    for (const mpz_class& d : part) mpz_lcm(L.get_mpz_t(), L.get_mpz_t(), d.get_mpz_t());
    if (stop_bits > 0 && mpz_sizeinbase(L.get_mpz_t(), 2) > std::size_t(stop_bits)) return L;
  }
  if (cam.perspective)
    for (int k = 0; k < 3; ++k) mpz_lcm(L.get_mpz_t(), L.get_mpz_t(), cam.eye[k].get_den_mpz_t());
  return L;
}

// The scene's grid (face_engine.hpp, Prepared::on_grid) for the multi-limb and GMP paths: the
// denominators below 2^62 that many vertices have (each vertex's: of its three coordinates; at
// least one vertex in 64), most frequent first, joined while their least common multiple G
// stays below 2^62; a vertex is on the grid when its denominator divides G and its
// coordinates times G are below 2^61. `rare`: a rarer denominator joins too while G times the
// largest coordinate M stays below 2^60, where it takes no vertex off the grid (an exporter's
// few longer decimals or float32's finer binary fractions on small coordinates); not for the
// GMP path, whose cut points' denominators would make its small integers long.
struct SceneGrid {
  std::vector<char> on;
  std::vector<std::array<std::int64_t, 3>> small;
  std::uint64_t G = 1;
};

std::uint64_t vertex_denominator(const Point3& v) {
  std::uint64_t d = 1;
  for (int k = 0; k < 3; ++k) {
    const mpz_class& q = v[k].get_den();
    if (!mpz_fits_ulong_p(q.get_mpz_t())) return 0;
    const std::uint64_t e = mpz_get_ui(q.get_mpz_t()), g = std::gcd(d, e);
    if (d / g > (std::uint64_t(1) << 62) / e) return 0;
    d = d / g * e;
  }
  return d;
}

SceneGrid scene_grid(const std::vector<const Polyhedron*>& bodies, std::size_t total, const ParallelLoop& loop, bool rare) {
  SceneGrid grid;
  std::vector<std::uint64_t> den(total);
  std::vector<const Point3*> vertex(total);
  std::size_t at = 0;
  for (const Polyhedron* p : bodies) {
    const std::vector<Point3>& vs = p->vertices();
    loop.for_each(vs.size(), 4096, [&](std::size_t i) { den[at + i] = vertex_denominator(vs[i]), vertex[at + i] = &vs[i]; });
    at += vs.size();
  }
  std::unordered_map<std::uint64_t, std::size_t> count;
  for (std::size_t i = 0; i < total;) {  // runs of one denominator counted at once
    std::size_t j = i + 1;
    while (j < total && den[j] == den[i]) ++j;
    if (den[i]) count[den[i]] += j - i;
    i = j;
  }
  std::vector<std::pair<std::size_t, std::uint64_t>> by_count;
  for (const auto& [d, n] : count) by_count.emplace_back(n, d);
  std::sort(by_count.begin(), by_count.end(), std::greater<>());
  double M = 0;  // the largest |coordinate|, rounded up
  if (rare) {
    PerWorker<double> top(loop, 0.0);
    loop.run(total, 4096, [&](unsigned w, std::size_t b, std::size_t e) {
      for (std::size_t i = b; i < e; ++i)
        for (int k = 0; k < 3; ++k) top[w] = std::max({top[w], std::fabs(vertex[i]->approx(k).lo), std::fabs(vertex[i]->approx(k).hi)});
    });
    for (unsigned w = 0; w < top.size(); ++w) M = std::max(M, top[w]);
  }
  for (const auto& [n, d] : by_count) {
    const bool many = n * 64 >= total;
    if (!many && !rare) break;  // a rare denominator (a cut point's) would only make every small integer larger
    const std::uint64_t g = std::gcd(grid.G, d);
    if (grid.G / g > ((std::uint64_t(1) << 62) - 1) / d) continue;
    const std::uint64_t joined = grid.G / g * d;
    if (many || static_cast<double>(joined) * M < 0x1p59) grid.G = joined;  // (doubles within 2^-52: 0x1p59 under 2^60)
  }
  grid.on.assign(total, 0);
  grid.small.assign(total, {0, 0, 0});
  const Int128 limit = Int128(1) << 61;
  loop.for_each(total, 4096, [&](std::size_t i) {
    if (!den[i] || grid.G % den[i] != 0) return;
    bool fits = true;
    for (int k = 0; k < 3 && fits; ++k) {
      Int128 s;
      fits = scaled_integer((*vertex[i])[k], grid.G, limit, s);
      if (fits) grid.small[i][k] = static_cast<std::int64_t>(s);
    }
    grid.on[i] = fits;
  });
  if (std::find(grid.on.begin(), grid.on.end(), 1) == grid.on.end()) return {};  // no vertex on it: no grid
  return grid;
}

// L / d for the denominators d of one run of coordinates: the last 16, by d's lowest limb and
// size (an exporter's decimals have a few dozen denominators, 2^a·5^b; one division each).
class QuotientCache {
 public:
  const mpz_class& get(const mpz_class& L, const mpz_class& d) {
    mpz_srcptr dp = d.get_mpz_t();
    Slot& s = slot_[(mpz_getlimbn(dp, 0) ^ (mpz_getlimbn(dp, 0) >> 17) ^ mpz_size(dp)) % kSlots];
    if (!s.used || s.d != d) {
      s.d = d;
      mpz_divexact(s.q.get_mpz_t(), L.get_mpz_t(), dp);
      s.used = true;
    }
    return s.q;
  }

 private:
  static constexpr std::size_t kSlots = 16;
  struct Slot {
    mpz_class d, q;
    bool used = false;
  };
  std::array<Slot, kSlots> slot_;
};

// Wide: the common denominator L of any size (GMP), then every coordinate (and the eye) scaled
// on all cores and kept when below 2^Wide::kBits: a vertex on the scene's grid as its small
// integers times L / G in fixed-width limbs, any other through GMP; the view direction by its
// own denominator. False when a value is not below the bound (then GMP integers take the scene).
bool scale_wide(const std::vector<const Polyhedron*>& bodies, const Camera& cam, std::vector<Vec<Wide>>& pts, Vec<Wide>& view, Rational& scale,
                SceneGrid& grid, unsigned threads) {
  const ParallelLoop loop(threads);
  const auto fits = [](const mpz_class& v) { return mpz_sizeinbase(v.get_mpz_t(), 2) <= std::size_t(Wide::kBits); };
  std::size_t total = 0;
  for (const Polyhedron* p : bodies) total += p->num_vertices();
  const mpz_class L = gmp_common_denominator(bodies, cam, loop, Wide::kBits);
  if (!fits(L)) return false;
  grid = scene_grid(bodies, total, loop, true);
  const Wide::C K(mpz_class(L / mpz_class(static_cast<unsigned long>(grid.G))).get_mpz_t());  // G divides L
  // q·L, exact (q's denominator divides L), into `out` when below the bound. L / den from the
  // last quotients made with that denominator (`cache`: a decimal scene has few of them).
  auto scaled = [&](const Rational& q, mpz_class& t, Wide::C& out, QuotientCache& cache) {
    t = cache.get(L, q.get_den());
    t *= q.get_num();
    if (!fits(t)) return false;
    out = Wide::C(t.get_mpz_t());
    return true;
  };
  constexpr std::size_t kChunk = 4096;  // vertices
  pts.clear();
  reserve_touched(pts, total, loop);
  pts.resize(total);
  std::size_t first = 0;
  for (const Polyhedron* p : bodies) {
    const std::vector<Point3>& vs = p->vertices();
    std::vector<char> ok((vs.size() + kChunk - 1) / kChunk, 1);
    loop.for_each(ok.size(), 1, [&](std::size_t c) {
      mpz_class t;
      QuotientCache cache;
      for (std::size_t i = c * kChunk, e = std::min(vs.size(), i + kChunk); i < e && ok[c]; ++i) {
        const std::size_t at = first + i;
        for (int k = 0; k < 3 && ok[c]; ++k) {
          if (!grid.on.empty() && grid.on[at]) {
            pts[at][k] = Wide::C::product(K, Wide::C(static_cast<long>(grid.small[at][k])));
            ok[c] = pts[at][k].bits() <= Wide::kBits;
          } else {
            ok[c] = scaled(vs[i][k], t, pts[at][k], cache);
          }
        }
      }
    });
    if (std::find(ok.begin(), ok.end(), 0) != ok.end()) return false;
    first += vs.size();
  }
  mpz_class t;
  QuotientCache cache;
  if (cam.perspective) {
    for (int k = 0; k < 3; ++k)
      if (!scaled(cam.eye[k], t, view[k], cache)) return false;
  } else if (!direction_wide(cam, view)) {
    return false;
  }
  scale = Rational(L);
  return true;
}

void scale_big(const std::vector<const Polyhedron*>& bodies, const Camera& cam, std::vector<Vec<Big>>& pts, Vec<Big>& view, Rational& scale,
               SceneGrid& grid, unsigned threads) {
  std::size_t total = 0;
  for (const Polyhedron* p : bodies) total += p->num_vertices();
  const ParallelLoop loop(threads);
  const mpz_class L = gmp_common_denominator(bodies, cam, loop, 0);
  grid = scene_grid(bodies, total, loop, false);
  auto sc = [&](const Rational& q) { return mpz_class(q.get_num() * (L / q.get_den())); };
  pts.resize(total);
  std::size_t first = 0;
  for (const Polyhedron* p : bodies) {  // on all cores, each vertex into its own slot
    const std::vector<Point3>& vs = p->vertices();
    loop.for_each(vs.size(), 4096, [&](std::size_t i) {
      const std::size_t at = first + i;
      if (grid.on.empty() || !grid.on[at])  // (a vertex on the grid: small·(L / G), made when a test needs it, Engine::pt)
        for (int k = 0; k < 3; ++k) pts[at][k] = sc(vs[i][k]);
    });
    first += vs.size();
  }
  if (cam.perspective) {
    view = {sc(cam.eye[0]), sc(cam.eye[1]), sc(cam.eye[2])};
  } else {
    mpz_class s[3];
    direction_gmp(cam, s, false);
    for (int k = 0; k < 3; ++k) view[k] = s[k];
  }
  scale = Rational(L);
}

// An engine on the scaled points, sharing its view-independent work through `share` when given.
template <class P>
LineDrawing run_engine(const std::vector<const Polyhedron*>& bodies, const Camera& camera, const LineOptions& opt, const FaceRouteHooks& hooks,
                       std::vector<Vec<P>> pts, Vec<P> view, Rational scale, FaceRouteShare* share, int policy, SceneGrid grid = {}) {
  auto prep = std::make_shared<face_route::Prepared<P>>();
  prep->X = std::move(pts);
  prep->scale = std::move(scale);
  prep->on_grid = std::move(grid.on);
  prep->small = std::move(grid.small);
  prep->grid = grid.G;
  if (share) share->bodies = bodies, share->policy = policy, share->prepared = prep;
  return face_route::Engine<P>(bodies, camera, opt, hooks, std::move(prep), std::move(view), share != nullptr).run();
}

// A further orthographic view of the shared bodies on the policy they were prepared on; none
// when its view direction does not fit that policy.
template <class P>
std::optional<LineDrawing> run_again(const std::vector<const Polyhedron*>& bodies, const Camera& camera, const LineOptions& opt,
                                     const FaceRouteHooks& hooks, FaceRouteShare& share) {
  Vec<P> view{};
  bool fits = true;
  if constexpr (std::is_same_v<P, Big>) {
    mpz_class s[3];
    direction_gmp(camera, s, false);
    for (int k = 0; k < 3; ++k) view[k] = s[k];
  } else if constexpr (std::is_same_v<P, Wide>) {
    fits = direction_wide(camera, view);
  } else {
    fits = direction_fast<P>(camera, P::kBits, view);
  }
  if (!fits) return std::nullopt;
  auto prep = std::static_pointer_cast<face_route::Prepared<P>>(share.prepared);
  return face_route::Engine<P>(bodies, camera, opt, hooks, std::move(prep), std::move(view), true).run();
}

}  // namespace

LineDrawing face_occluders(const std::vector<const Polyhedron*>& bodies, const Camera& camera, const LineOptions& opt, const FaceRouteHooks& hooks) {
  // Shared work: orthographic views only (a perspective view's scale takes in its eye).
  FaceRouteShare* share = hooks.share && !camera.perspective ? hooks.share.get() : nullptr;
  if (share && share->prepared && share->bodies == bodies) {
    std::optional<LineDrawing> again;
    switch (share->policy) {
      case 0:
        again = run_again<Fast>(bodies, camera, opt, hooks, *share);
        break;
      case 1:
        again = run_again<Fast40>(bodies, camera, opt, hooks, *share);
        break;
      case 2:
        again = run_again<Wide>(bodies, camera, opt, hooks, *share);
        break;
      default:
        again = run_again<Big>(bodies, camera, opt, hooks, *share);
        break;
    }
    if (again) return std::move(*again);
  }
  {
    std::vector<Vec<Fast>> pts;
    Vec<Fast> view{};
    Rational scale;
    if (scale_fast<Fast>(bodies, camera, Fast::kBits, pts, view, scale, opt.threads))
      return run_engine<Fast>(bodies, camera, opt, hooks, std::move(pts), view, std::move(scale), share, 0);
  }
  {
    std::vector<Vec<Fast40>> pts;
    Vec<Fast40> view{};
    Rational scale;
    if (scale_fast<Fast40>(bodies, camera, Fast40::kBits, pts, view, scale, opt.threads))
      return run_engine<Fast40>(bodies, camera, opt, hooks, std::move(pts), view, std::move(scale), share, 1);
  }
  {
    std::vector<Vec<Wide>> pts;
    Vec<Wide> view{};
    Rational scale;
    SceneGrid grid;
    if (scale_wide(bodies, camera, pts, view, scale, grid, opt.threads))
      return run_engine<Wide>(bodies, camera, opt, hooks, std::move(pts), view, std::move(scale), share, 2, std::move(grid));
  }
  std::vector<Vec<Big>> pts;
  Vec<Big> view;
  Rational scale;
  SceneGrid grid;
  scale_big(bodies, camera, pts, view, scale, grid, opt.threads);
  return run_engine<Big>(bodies, camera, opt, hooks, std::move(pts), std::move(view), std::move(scale), share, 3, std::move(grid));
}

}  // namespace hlr
