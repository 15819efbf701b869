#pragma once
/// \file
/// One pass over an OBJ file's text before tinyobjloader [1] parses it, for what that parser
/// does not say: it reads `nan` as 0, skips lines it does not understand, resolves face indices
/// without telling the user which one they wrote, and names materials it cannot find in its own
/// words. The pass works on the text in memory: 0.12 s for a 100 MB, 1M-triangle file, a tenth
/// of tinyobjloader's parse of it.
///
/// What it checks, line by line (statements as in the OBJ specification [2]):
///  - `v` and `vn`: three coordinates, each a number finite as a float; an error otherwise
///    (fewer than three, a word where a number belongs: tinyobjloader would read it as 0 and
///    put the vertex elsewhere without a word). What follows the three (a `w`, vertex colours,
///    other text) is ignored, as tinyobjloader ignores it.
///  - `f`, `l`, `p`: each corner is `v`, `v/vt`, `v//vn` or `v/vt/vn` with whole numbers, and
///    each index exists: 0 is never valid; a positive i needs at least i `v` (`vt`, `vn`) lines
///    in the file; a negative i counts back from the line, so needs at least |i| before it.
///    Faces need three corners, and a polygon of four or more may not use a vertex defined
///    after it (tinyobjloader cuts polygons into triangles by their positions at the end of
///    their group). Each failure is an error quoting the index as written.
///  - any other keyword that is not an OBJ statement, and `mtllib` without a file name, is
///    counted as not understood; comments and blank lines are fine.
/// It also counts the faces of each `usemtl` name, so that a missing material is reported once,
/// with the number of faces it leaves at the default albedo (obj_materials.h), and keeps each
/// `mtllib` line whole.
///
/// Line numbers follow tinyobjloader's: a line ends at `\n`, `\r\n` or a lone `\r`.
///
/// References
///  [1] S. Fujita, "tinyobjloader", https://github.com/tinyobjloader/tinyobjloader (2.0.0rc10).
///  [2] Wavefront Technologies, "Object Files (.obj)", Advanced Visualizer manual, appendix B1.

#include <cstddef>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace prt {

/// What one pass over an OBJ file found.
struct ObjScan {
  std::size_t skipped_lines = 0;       ///< lines not understood (see the file comment)
  std::size_t first_skipped_line = 0;  ///< 1-based; 0 when none
  std::string first_skipped_text;      ///< cut to kQuotedLineLength bytes, printable
  /// Faces after each `usemtl NAME`, until the next `usemtl` (faces before the first have none);
  /// NAME is the whole rest of the line, blanks trimmed (material_names.h).
  std::map<std::string, std::size_t> faces_by_material;
  /// The whole rest of each `mtllib` line, blanks trimmed at both ends, in file order: a library
  /// whose name has spaces (`mtllib My Scene.mtl`, as Blender names it after the .blend), which
  /// tinyobjloader splits into names at the blanks (obj_materials.h).
  std::vector<std::string> mtllib_lines;
};

/// Longest excerpt of a line quoted in messages, in bytes (then "...").
inline constexpr std::size_t kQuotedLineLength = 40;

/// Scans `text`, the content of the OBJ file `path` (named in messages). Throws prt::Error
/// `<path>: line N: <problem> (<expected>)` for a non-finite coordinate, a malformed corner, an
/// index that does not exist or a face of fewer than three corners. `advance`, when given, is
/// told every few megabytes how many more bytes were scanned.
ObjScan ScanObj(std::string_view text, const std::string& path,
                const std::function<void(std::size_t)>& advance = {});

/// `line` as a message may quote it: at most kQuotedLineLength bytes, cut at a character
/// boundary and marked "...", with control bytes and invalid UTF-8 shown as '?'.
std::string QuoteLine(std::string_view line);

}  // namespace prt
