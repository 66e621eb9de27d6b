// Tile files (one drawing on many machines): `hlr render --tile I/N` writes the exact
// pieces of its tile (picture_tiles.hpp) with the render command's arguments; `hlr merge`
// reads every tile of the split, checks they belong together, runs the same render for the
// segments alone and puts the tiles' pieces in: the whole drawing, exactly. A text format, one
// record per line (docs/output-format.md):
//   hlr-tile 1
//   tile I N                       (1-based)
//   arg TEXT                       (one per render argument, in order)
//   segments COUNT FINGERPRINT     (the drawing's segment list: count and a hash of it)
//   counters PAIRS SKIPPED RATIONAL COMPARISONS IDENTICAL EXACT   (the visibility's work)
//   piece SEGMENT T0 T1 KIND       (exact rationals; KIND: v or h, then b behind the eye,
//                                   c clipped, t seen through)
//   end
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "algorithms/model/line_drawing.hpp"

namespace hlr {

/// The most tiles a split may have (`--tile I/N`: N at most this).
inline constexpr int kMaxTiles = 1000000;

struct TileFile {
  int index = 0, count = 1;        // 0-based index
  std::vector<std::string> args;   // the render command's arguments (inputs and options)
  std::size_t segments = 0;
  std::uint64_t fingerprint = 0;
  std::size_t pairs_tested = 0, pairs_skipped = 0, pairs_rational = 0;
  std::size_t comparisons = 0, comparisons_identical = 0, comparisons_exact = 0;
  std::vector<std::pair<std::size_t, Piece>> pieces;
};

/// A hash of the drawing's segment list (kinds, bodies, vertices, faces; not the pieces): two
/// runs with the same input and options give the same.
std::uint64_t segment_fingerprint(const LineDrawing& drawing);

/// The tile of `drawing` (cut to tile `index` of `count`) as a tile file's text.
std::string tile_text(const LineDrawing& drawing, int index, int count, const std::vector<std::string>& args);

/// Reads a tile file; throws InputError (file, line, what is wrong).
TileFile read_tile(const std::string& path);
/// The same from the file's text (`path` names it in errors).
TileFile read_tile_text(const std::string& text, const std::string& path);

/// Puts the pieces of `tiles` (every tile of one split, each once) into `drawing` (the same
/// render's segments: segments_only) and adds their work counters to its statistics. Throws
/// InputError when the tiles do not belong together or do not cover a segment exactly once.
/// Joins on `threads` cores (0: all).
void merge_tiles(LineDrawing& drawing, const std::vector<TileFile>& tiles, const std::vector<std::string>& paths,
                 unsigned threads = 0);

}  // namespace hlr
