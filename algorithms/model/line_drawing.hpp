// The exact line drawing every hidden-line route returns (course notes, sections
// 26-28 for the words: facing and non-facing faces, self-hidden edges, intersection lines).
// A drawing is a list of segments (a body's edges and the intersection lines where bodies
// cross), each cut into pieces [t0, t1] of its parameter, every piece visible or hidden,
// decided exactly. Renderers fill it; the 2D stage (drawing_2d.hpp) and the writers read it.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "kernel/geometry.hpp"
#include "kernel/point_store.hpp"

namespace hlr {

/// A maximal piece [t0, t1] of a segment, t0 < t1.
struct Piece {
  Rational t0, t1;
  bool visible = true;
  bool behind_eye = false;  // perspective: behind the eye, never drawn
  bool clipped = false;     // outside the clipping volume or nearer than the near plane
  bool through = false;     // hidden only by see-through (transparent) faces: seen through them
  bool same_kind(const Piece& o) const {
    return visible == o.visible && behind_eye == o.behind_eye && clipped == o.clipped && through == o.through;
  }
};

/// A segment's pieces in order of t: a vector's interface for reading, mutations named. Most
/// segments of a large mesh are one piece over [0, 1] (wholly visible, or wholly hidden): such a
/// list holds no numbers, only the piece's four flags, and reads as a shared [0, 1] piece. Any
/// list that becomes one piece over [0, 1] is stored that way. 8 bytes: one word that is 0
/// (empty), the flags of the one [0, 1] piece shifted left with the lowest bit set, or the
/// address of the list's own vector (heap blocks are aligned: its lowest bit is 0).
class PieceList {
 public:
  PieceList() = default;
  PieceList(std::vector<Piece> v) { assign(std::move(v)); }  // NOLINT: implicit, like the vector
  PieceList(std::initializer_list<Piece> l) { assign(std::vector<Piece>(l)); }
  PieceList(const PieceList& o) : word_(o.many() ? reinterpret_cast<std::uintptr_t>(new std::vector<Piece>(*o.many())) : o.word_) {}
  PieceList(PieceList&& o) noexcept : word_(o.word_) { o.word_ = 0; }
  PieceList& operator=(const PieceList& o) {
    if (this != &o) *this = PieceList(o);
    return *this;
  }
  PieceList& operator=(PieceList&& o) noexcept {
    if (this != &o) {
      clear();
      word_ = o.word_;
      o.word_ = 0;
    }
    return *this;
  }
  PieceList& operator=(std::vector<Piece> v) {
    assign(std::move(v));
    return *this;
  }
  PieceList& operator=(std::initializer_list<Piece> l) {
    assign(std::vector<Piece>(l));
    return *this;
  }
  ~PieceList() { delete many(); }  // reads only: a moved-from list whose pages were given back stays untouched

  std::size_t size() const { return whole() ? 1 : (many() ? many()->size() : 0); }
  bool empty() const { return size() == 0; }
  const Piece* begin() const;
  const Piece* end() const { return begin() + size(); }
  const Piece& operator[](std::size_t i) const { return begin()[i]; }
  const Piece& front() const { return *begin(); }
  const Piece& back() const { return end()[-1]; }
  /// The pieces as a vector (a copy).
  std::vector<Piece> to_vector() const { return std::vector<Piece>(begin(), end()); }
  bool operator==(const PieceList& o) const;

  /// One piece over [0, 1] of the kind of `kind` (its t0, t1 are not read).
  void set_whole(const Piece& kind);
  /// One piece over [0, 1], visible or hidden (no other flag).
  void set_whole(bool visible) {
    clear();
    word_ = visible ? 3 : 1;
  }
  void assign(std::vector<Piece> v);
  void clear() {
    delete many();
    word_ = 0;
  }
  void push_back(Piece p) { edit().push_back(std::move(p)); }
  /// The pieces as a vector to change in place (a one-piece list is unpacked first); call
  /// compact() after changing to pack a list that became one piece over [0, 1].
  std::vector<Piece>& edit();
  void compact();

 private:
  bool whole() const { return (word_ & 1) != 0; }
  int flags() const { return static_cast<int>(word_ >> 1); }  // of the one [0, 1] piece
  std::vector<Piece>* many() const { return whole() ? nullptr : reinterpret_cast<std::vector<Piece>*>(word_); }
  std::uintptr_t word_ = 0;
};
static_assert(sizeof(PieceList) == 8);

/// What a drawn line is: a boundary edge of an open surface, a crease (dihedral angle over the
/// threshold), a silhouette (one face toward the viewer, the other not), an intersection line
/// where two surfaces cross, or any mesh edge (`--edges all`); with a section, a cut line (an
/// edge of a cap, where the cutting plane meets a body's surface), a hatch line on a cap, and in
/// a floor plan an overhead line (what the section removed, seen from below: drawn dashed); on
/// a sheet, a section line's narrow chain and its wide ends and arrows (ISO 128-40: marks that
/// are not lines of the scene, made on the page).
/// Hatch: a section cap's hatching; Tone1..Tone8: tone hatching of the visible faces by their
/// shade, one kind per tone level (1 the lightest hatched level); Polyline: the user's own 3D
/// lines, hidden by the bodies. Tangent: an edge where two surfaces of a CAD model meet
/// tangentially (G1; face_surfaces.hpp), a narrow line of its own (ISO 128, as TechDraw and Make2D).
enum class LineKind : std::uint8_t {
  Edge,
  Boundary,
  Crease,
  Silhouette,
  Intersection,
  Cut,
  Hatch,
  Overhead,
  SectionLine,
  SectionMark,
  Polyline,
  Tone1,
  Tone2,
  Tone3,
  Tone4,
  Tone5,
  Tone6,
  Tone7,
  Tone8,
  Tangent
};
const char* to_string(LineKind k);
/// The tone levels' kinds: tone_kind(1) is Tone1; is_tone(k) for any of them.
inline constexpr int kMaxToneLevels = 8;
inline LineKind tone_kind(int level) { return static_cast<LineKind>(static_cast<int>(LineKind::Tone1) + level - 1); }
inline bool is_tone(LineKind k) { return k >= LineKind::Tone1 && k <= LineKind::Tone8; }
/// Every kind in the order a drawing's layers come in (cut lines first: the widest pen).
inline constexpr LineKind kLayerKinds[] = {
    LineKind::Cut,      LineKind::Silhouette, LineKind::Boundary, LineKind::Crease,   LineKind::Tangent,     LineKind::Intersection, LineKind::Edge,
    LineKind::Polyline, LineKind::Hatch,      LineKind::Tone1,    LineKind::Tone2,    LineKind::Tone3,       LineKind::Tone4,        LineKind::Tone5,
    LineKind::Tone6,    LineKind::Tone7,      LineKind::Tone8,    LineKind::Overhead, LineKind::SectionLine, LineKind::SectionMark};

/// Which edges a renderer draws.
enum class EdgeSelection { All, Feature };

struct Segment;

/// What every hidden-line route takes (the render pipeline's options add the rest).
struct LineOptions {
  EdgeSelection edges = EdgeSelection::Feature;  // Feature: boundaries, silhouettes, creases
  Rational crease_degrees = 30;                   // Feature: creases over this angle
  bool continue_creases = true;                   // Feature: a crease line that ends goes on along the straightest
                                                  // edge over half the angle (docs/design.md, "Crease lines")
  bool intersections = true;                      // per-face route: intersection lines (and self)
  bool classify_all = false;                      // All: still name silhouettes, boundaries, creases
  bool prefilter = true;                          // Roberts: spatial pre-filter of (edge, body) pairs
  unsigned threads = 0;                           // 0: all cores
};

struct Segment {
  enum class Kind : std::uint8_t { Edge, Intersection };
  Kind kind = Kind::Edge;
  LineKind line = LineKind::Edge;
  bool self_hidden = false;      // both faces non-facing (notes' Stage 1)
  int body = -1;                 // Edge: the body; Intersection: the first body
  int body2 = -1;                // Intersection: the second body
  int v0 = -1, v1 = -1;          // Edge: input vertex indices, from v0 toward v1
  int face0 = -1, face1 = -1;    // Edge: its two faces; Intersection: the facets' faces
  PieceList pieces;              // in order of t, covering [0, 1]
  /// The point at t in [0, 1] from from() to to() (a compact store makes only the two ends).
  Point3 at(const Rational& t) const;

  Segment() = default;
  Segment(const Segment& o);
  Segment(Segment&& o) noexcept : Segment() { swap(o); }
  Segment& operator=(const Segment& o);
  Segment& operator=(Segment&& o) noexcept {
    Segment(std::move(o)).swap(*this);
    return *this;
  }
  ~Segment() { release(); }

  /// The ends, world coordinates (set before use).
  const Point3& from() const { return end(v0, 0); }
  const Point3& to() const { return end(v1, 1); }
  /// Ends owned by the segment.
  void set_ends(Point3 a, Point3 b);
  /// Ends borrowed from storage that outlives the segment (a body's vertices): vertices[v0]
  /// and vertices[v1] (set v0 and v1 first). A segment of a million-edge mesh then costs no
  /// exact numbers of its own.
  void borrow_ends(const std::vector<Point3>& vertices) {
    release();
    ends_ = reinterpret_cast<std::uintptr_t>(vertices.data());
  }
  /// The same from a vertex store (kernel/point_store.hpp): from() and to() make a compact
  /// store's exact points; store_ends() reads the ends' bounds without them.
  void borrow_ends(const PointStore& vertices) {
    release();
    ends_ = reinterpret_cast<std::uintptr_t>(&vertices) | kStoreTag;
  }
  /// The vertices the ends are borrowed from (from() is borrowed()[v0]), or nullptr when the
  /// segment owns its ends or borrows them from a store.
  const Point3* borrowed() const { return (ends_ & kTags) == 0 ? base() : nullptr; }
  /// The store the ends are borrowed from (point v0 is from()), or nullptr.
  const PointStore* store_ends() const { return (ends_ & kTags) == kStoreTag ? store() : nullptr; }

 private:
  // One word for either end store (48 bytes a segment with the one-word piece list, not 56): the borrowed vertex array, the
  // owned pair's address with its lowest bit set, or the borrowed store's with the next bit set
  // (heap blocks and stores are aligned: those bits are 0).
  static constexpr std::uintptr_t kOwnedTag = 1, kStoreTag = 2, kTags = 3;
  std::uintptr_t ends_ = 0;
  bool owned() const { return (ends_ & kTags) == kOwnedTag; }
  const std::array<Point3, 2>* own() const { return reinterpret_cast<const std::array<Point3, 2>*>(ends_ & ~kTags); }
  const Point3* base() const { return reinterpret_cast<const Point3*>(ends_); }
  const PointStore* store() const { return reinterpret_cast<const PointStore*>(ends_ & ~kTags); }
  const Point3& end(int v, int k) const {
    switch (ends_ & kTags) {
      case kOwnedTag:
        return (*own())[k];
      case kStoreTag:
        return store()->points()[v];
      default:
        return base()[v];
    }
  }
  void release() {
    if (owned()) delete own();
    ends_ = 0;
  }
  void swap(Segment& o) noexcept;
};
static_assert(sizeof(Segment) == 48);

/// The hidden-line methods: per-face occluders (any mesh), Roberts' algorithm on convex bodies,
/// Roberts' algorithm through convex pieces (non-convex solids).
enum class Method { Faces, Roberts, RobertsPieces, Horizon };
/// "faces", "roberts", "roberts-pieces", "horizon" (the JSON's stats.method).
const char* to_string(Method m);

/// Counters of the per-face route (JSON stats, docs/output-format.md).
struct FaceRouteStats {
  std::size_t occluders = 0;             // triangles used as occluders
  std::size_t comparisons = 0;           // comparisons of split parameters
  std::size_t comparisons_identical = 0; // ... decided as equal by identical fractions
  std::size_t comparisons_exact = 0;     // ... that the double filter could not decide
  bool integer_path = true;              // coordinates fitted the 64/128-bit integer path
  std::size_t intersection_pairs = 0;    // triangle pairs tested exactly for intersection lines
};

struct DrawingStats {
  Method method = Method::Roberts;
  std::size_t edges = 0, self_hidden = 0, intersection_segments = 0;
  std::size_t pairs_tested = 0, pairs_skipped = 0;
  std::size_t pairs_rational = 0;       // tested on the rational path (an integer path did not fit)
  std::optional<FaceRouteStats> faces;  // the per-face route only
  double setup_seconds = 0, intersections_seconds = 0, visibility_seconds = 0;  // wall clock
};

/// A remark about one body for the user (e.g. drawn as an open surface): `text` follows the
/// body's name, "body 'box' " + text.
struct BodyNote {
  int body = -1;
  std::string text;
};

/// Vertices of a store that count for a drawing's frame without ending any of its segments
/// (LineDrawing::frame_ends).
struct FrameEnds {
  const PointStore* store = nullptr;
  std::vector<char> marks;  // per vertex of the store: 1 when it counts
};

struct LineDrawing {
  /// Per body and face: 1 facing, 0 edge-on, -1 non-facing (facing.hpp).
  std::vector<std::vector<signed char>> facing;
  /// Per body (per-face route): a closed solid with the eye off its surface, so no sight ray
  /// meets a non-facing face of it before a facing one (empty: not known).
  std::vector<char> back_faces_unseen;
  std::vector<Segment> segments;
  /// The ends of the segments a route left out as wholly hidden (FaceRouteHooks::back_edges
  /// off): the drawing's frame (drawing_projector) counts them, so that the drawing's doubles
  /// are those of the drawing with them.
  std::vector<FrameEnds> frame_ends;
  DrawingStats stats;
  std::vector<BodyNote> notes;
};

/// A body a renderer cannot take (not a valid solid, not convex, a non-planar face) or a bad
/// view (the eye inside it). The body and the reason are values: `reason()` follows the body's
/// name ("body 'box' " + reason); what() says "body N " + reason.
class BodyError : public std::runtime_error {
 public:
  BodyError(int body, const std::string& reason)
      : std::runtime_error("body " + std::to_string(body) + " " + reason), body_(body), reason_(reason) {}
  int body() const { return body_; }
  const std::string& reason() const { return reason_; }

 private:
  int body_;
  std::string reason_;
};

/// The pieces of [0, 1] given the hidden open spans (lo < hi, inside [0, 1], any order,
/// overlapping allowed) and, for perspective, the depths (P - E)·(target - E) at t = 0 and 1
/// (the part at depth <= 0 is behind the eye). Touching spans are merged (a single visible
/// point is not a line).
std::vector<Piece> pieces_from_hidden(std::vector<std::pair<Rational, Rational>> hidden,
                                      const std::optional<std::pair<Rational, Rational>>& depth);

}  // namespace hlr
