// The line drawing (see line_drawing.hpp): segment ends, pieces from hidden spans, names.
#include "algorithms/model/line_drawing.hpp"

#include <algorithm>

namespace hlr {

const char* to_string(LineKind k) {
  switch (k) {
    case LineKind::Boundary: return "boundary";
    case LineKind::Crease: return "crease";
    case LineKind::Silhouette: return "silhouette";
    case LineKind::Intersection: return "intersection";
    case LineKind::Cut:
      return "cut";
    case LineKind::Hatch:
      return "hatch";
    case LineKind::Overhead:
      return "overhead";
    case LineKind::SectionLine:
      return "section-line";
    case LineKind::SectionMark:
      return "section-mark";
    case LineKind::Polyline:
      return "polyline";
    case LineKind::Tangent:
      return "tangent";
    case LineKind::Tone1:
      return "tone-1";
    case LineKind::Tone2:
      return "tone-2";
    case LineKind::Tone3:
      return "tone-3";
    case LineKind::Tone4:
      return "tone-4";
    case LineKind::Tone5:
      return "tone-5";
    case LineKind::Tone6:
      return "tone-6";
    case LineKind::Tone7:
      return "tone-7";
    case LineKind::Tone8:
      return "tone-8";
    case LineKind::Edge: break;
  }
  return "edge";
}

const char* to_string(Method m) {
  switch (m) {
    case Method::Faces: return "faces";
    case Method::RobertsPieces: return "roberts-pieces";
    case Method::Horizon: return "horizon";
    case Method::Roberts: break;
  }
  return "roberts";
}

Point3 Segment::at(const Rational& t) const {
  if (const PointStore* store = store_ends()) {  // the two points alone, not the store's every point
    Point3 a = store->point(static_cast<std::size_t>(v0));
    if (t == 0) return a;
    Point3 b = store->point(static_cast<std::size_t>(v1));
    if (t == 1) return b;
    return a + t * (b - a);
  }
  if (t == 0) return from();
  if (t == 1) return to();
  return from() + t * (to() - from());
}

static_assert(sizeof(Segment) <= 56, "a segment of a mesh edge costs 56 bytes");

// Every field; the owned ends copied (the copy owns its own).
Segment::Segment(const Segment& o)
    : kind(o.kind),
      line(o.line),
      self_hidden(o.self_hidden),
      body(o.body),
      body2(o.body2),
      v0(o.v0),
      v1(o.v1),
      face0(o.face0),
      face1(o.face1),
      pieces(o.pieces),
      ends_(o.ends_) {
  if (o.owned()) {
    ends_ = 0;
    set_ends((*o.own())[0], (*o.own())[1]);
  }
}

Segment& Segment::operator=(const Segment& o) {
  if (this != &o) Segment(o).swap(*this);
  return *this;
}

void Segment::swap(Segment& o) noexcept {
  std::swap(kind, o.kind);
  std::swap(line, o.line);
  std::swap(self_hidden, o.self_hidden);
  std::swap(body, o.body);
  std::swap(body2, o.body2);
  std::swap(v0, o.v0);
  std::swap(v1, o.v1);
  std::swap(face0, o.face0);
  std::swap(face1, o.face1);
  std::swap(pieces, o.pieces);
  std::swap(ends_, o.ends_);
}

void Segment::set_ends(Point3 a, Point3 b) {
  const auto* own = new const std::array<Point3, 2>{std::move(a), std::move(b)};
  release();
  ends_ = reinterpret_cast<std::uintptr_t>(own) | 1;
}

namespace {

int flags_of(const Piece& p) {
  return (p.visible ? 1 : 0) | (p.behind_eye ? 2 : 0) | (p.clipped ? 4 : 0) | (p.through ? 8 : 0);
}

// The sixteen one-piece lists' piece [0, 1], one per combination of flags; never freed (the
// number pool may be gone when static destructors run).
const Piece* whole_pieces() {
  static const Piece* table = [] {
    auto* t = new Piece[16];
    for (int f = 0; f < 16; ++f) {
      t[f].t0 = 0;
      t[f].t1 = 1;
      t[f].visible = (f & 1) != 0;
      t[f].behind_eye = (f & 2) != 0;
      t[f].clipped = (f & 4) != 0;
      t[f].through = (f & 8) != 0;
    }
    return t;
  }();
  return table;
}

}  // namespace

const Piece* PieceList::begin() const {
  if (whole()) return whole_pieces() + flags();
  return many() ? many()->data() : nullptr;
}

bool PieceList::operator==(const PieceList& o) const {
  if (size() != o.size()) return false;
  for (std::size_t i = 0; i < size(); ++i) {
    const Piece& a = (*this)[i];
    const Piece& b = o[i];
    if (a.t0 != b.t0 || a.t1 != b.t1 || !a.same_kind(b)) return false;
  }
  return true;
}

void PieceList::set_whole(const Piece& kind) {
  const auto w = (static_cast<std::uintptr_t>(flags_of(kind)) << 1) | 1;  // before `kind` may go with the vector
  clear();
  word_ = w;
}

void PieceList::assign(std::vector<Piece> v) {
  if (v.size() == 1 && v[0].t0 == 0 && v[0].t1 == 1) {
    set_whole(v[0]);
    return;
  }
  if (v.empty()) clear();
  else if (many()) *many() = std::move(v);
  else word_ = reinterpret_cast<std::uintptr_t>(new std::vector<Piece>(std::move(v)));
}

std::vector<Piece>& PieceList::edit() {
  if (whole()) word_ = reinterpret_cast<std::uintptr_t>(new std::vector<Piece>(1, whole_pieces()[flags()]));
  else if (!many()) word_ = reinterpret_cast<std::uintptr_t>(new std::vector<Piece>());
  return *many();
}

void PieceList::compact() {
  std::vector<Piece>* v = many();
  if (!v) return;
  if (v->empty()) clear();
  else if (v->size() == 1 && (*v)[0].t0 == 0 && (*v)[0].t1 == 1) set_whole((*v)[0]);
}

std::vector<Piece> pieces_from_hidden(std::vector<std::pair<Rational, Rational>> hidden,
                                      const std::optional<std::pair<Rational, Rational>>& depth) {
  // Common cases without any arithmetic: nothing hidden, or one span over the whole edge (the
  // piece built in place: a braced list copies its GMP numbers, six allocations per edge).
  auto whole = [](bool visible) {
    std::vector<Piece> out(1);
    out[0].t1 = 1;
    out[0].visible = visible;
    return out;
  };
  if (!depth && hidden.empty()) return whole(true);
  if (!depth && hidden.size() == 1 && hidden[0].first == 0 && hidden[0].second == 1) return whole(false);
  std::sort(hidden.begin(), hidden.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::pair<Rational, Rational>> merged;
  for (auto& s : hidden) {
    // Touching open intervals leave a single visible point between them: not a line, merged.
    if (!merged.empty() && s.first <= merged.back().second) {
      if (s.second > merged.back().second) merged.back().second = s.second;
    } else {
      merged.push_back(std::move(s));
    }
  }
  if (!depth) {
    // The merged spans are disjoint, in order, inside [0, 1] and not touching: the pieces
    // alternate between the gaps (visible) and the spans (hidden), built without arithmetic.
    std::vector<Piece> pieces;
    pieces.reserve(2 * merged.size() + 1);
    Rational prev = 0;
    for (auto& m : merged) {
      if (prev < m.first) {
        pieces.emplace_back();
        pieces.back().t0 = std::move(prev);
        pieces.back().t1 = m.first;
      }
      pieces.emplace_back();
      pieces.back().t0 = std::move(m.first);
      pieces.back().t1 = m.second;
      pieces.back().visible = false;
      prev = std::move(m.second);
    }
    if (prev < 1) {
      pieces.emplace_back();
      pieces.back().t0 = std::move(prev);
      pieces.back().t1 = 1;
    }
    return pieces;
  }
  std::vector<Rational> cuts = {Rational(0), Rational(1)};
  for (auto& s : merged) {
    cuts.push_back(s.first);
    cuts.push_back(s.second);
  }
  // Perspective: depth(t) = d0 + t (d1 - d0); the part with depth <= 0 is behind the eye.
  if (depth && depth->first != depth->second) {
    Rational t = depth->first / (depth->first - depth->second);
    if (t > 0 && t < 1) cuts.push_back(t);
  }
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  std::vector<Piece> pieces;
  std::size_t k = 0;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    Rational mid = (cuts[i] + cuts[i + 1]) / 2;
    while (k < merged.size() && merged[k].second <= mid) ++k;
    bool hidden_here = k < merged.size() && merged[k].first < mid && mid < merged[k].second;
    bool behind = depth && depth->first + mid * (depth->second - depth->first) <= 0;
    Piece p{cuts[i], cuts[i + 1], !hidden_here && !behind, behind};
    if (!pieces.empty() && pieces.back().visible == p.visible && pieces.back().behind_eye == p.behind_eye)
      pieces.back().t1 = p.t1;
    else
      pieces.push_back(p);
  }
  return pieces;
}

}  // namespace hlr
