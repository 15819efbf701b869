#pragma once
/// \file
/// Material names with blanks (`usemtl Sphere Mat` and `newmtl Sphere Mat`, as an exporter writes
/// a material its user named with a space). The OBJ and MTL formats [1] name a material with the
/// rest of the statement's line. tinyobjloader [2] reads `newmtl` so, but `usemtl` only up to its
/// first blank, so the faces of "Sphere Mat" looked for a material "Sphere" and lost their colour
/// and texture. prt reads both as the whole rest of the line, blanks trimmed at both ends (as it
/// reads `mtllib`, obj_scan.h), and hands tinyobjloader each name with its inner blanks replaced
/// by control bytes that no name in a text file holds; the names tinyobjloader gives back are
/// shown with their blanks again.
///
/// References
///  [1] Wavefront Technologies, "Object Files (.obj)" and "Material Library Files (.mtl)",
///      Advanced Visualizer manual, appendices B1 and B2.
///  [2] S. Fujita, "tinyobjloader", https://github.com/tinyobjloader/tinyobjloader (2.0.0rc10).

#include <string>
#include <string_view>

namespace prt {

/// The name a `usemtl` or `newmtl` statement gives: `rest`, what follows its keyword, with the
/// blanks (spaces, tabs) at both ends trimmed.
std::string_view MaterialNameOf(std::string_view rest);

/// Rewrites in place, at the same length, each line of `text` whose statement is `keyword`
/// (`usemtl` in an OBJ file, `newmtl` in an MTL file) whose name has a blank in it: the keyword,
/// one space, the name with each inner space and tab hidden, then the blanks the line had
/// elsewhere. Lines end at `\n`, `\r\n` or a lone `\r`, as tinyobjloader's do.
void HideNameBlanks(std::string& text, std::string_view keyword);

/// `name`, as tinyobjloader gives back a name HideNameBlanks rewrote, with its blanks shown again.
std::string ShowNameBlanks(std::string name);

}  // namespace prt
