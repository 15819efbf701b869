#include "geometry/orientation.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <utility>

#include <glm/geometric.hpp>

#include "core/constants.h"
#include "geometry/mesh_ops.h"  // Bounds3
#include "geometry/position_ids.h"

namespace prt {
namespace {

// "Most of the area": strictly more than half, so normals split evenly are left as they are.
constexpr double kMostArea = 0.5;
// A closed part whose file normals point inward on more than a quarter of its area (but not
// most of it) is reported: sharp features make a few percent ordinary, a quarter is an export
// problem, and negating them all would break the other three quarters.
constexpr double kMixedArea = 0.25;
// The sign of a closed part's volume decides its winding only when |V| > ratio * A^(3/2) (A its
// area). A sphere has V / A^(3/2) = 1 / (6 sqrt(pi)) ~ 0.094, a square slab of width w and
// thickness t about t / (3 w). Below 1e-6 (a slab 3e-6 of its width thick, its two sides a few
// float ulps apart) the part is as good as a sheet sealed onto itself, two copies of one surface
// back to back, which has no inside; its sign may be rounding.
constexpr double kFlatVolumeRatio = 1e-6;

// The constant of the isoperimetric inequality: a closed curve of length L bounds a plane
// region of area at most L^2 / (4 pi), and any region it bounds that is smaller.

// A part with holes is judged only when flat caps of its holes would cover at most this share of
// its area: a scan open at its base, not a bowl or a dome (whose cap is half its area), which is
// as often seen from either side.
constexpr double kSmallHoles = 0.2;

constexpr std::uint32_t kNone = ~0u;

// Disjoint sets over position ids: union by size, path halving (Tarjan 1975).
class DisjointSets {
 public:
  explicit DisjointSets(std::size_t n) : parent_(n), size_(n, 1) {
    for (std::size_t i = 0; i < n; ++i) parent_[i] = static_cast<std::uint32_t>(i);
  }
  std::uint32_t Find(std::uint32_t x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  void Union(std::uint32_t a, std::uint32_t b) {
    a = Find(a), b = Find(b);
    if (a == b) return;
    if (size_[a] < size_[b]) std::swap(a, b);
    parent_[b] = a;
    size_[a] += size_[b];
  }

 private:
  std::vector<std::uint32_t> parent_, size_;
};

// A connected part of the mesh: what was measured, then what is decided.
struct Part {
  bool has_edges = false;  // some triangle has three distinct positions
  bool watertight = true;  // every position edge used by exactly two triangles
  bool consistent = true;  // ... once in each direction
  bool manifold = true;    // no position edge used by more than two triangles
  double boundary = 0.0;   // length of the edges used once (the rims of its holes)
  double caps = 0.0;       // sum over its holes of (rim length)^2 / (4 pi): flat caps' area, at most
  double radius = 0.0;     // largest distance of its vertices from the bounding-box centre
  std::size_t triangles = 0;
  double volume = 0.0, area = 0.0;
  double file_area = 0.0, file_against = 0.0, file_agree = 0.0;  // faces with a file normal
  bool flip_winding = false, flip_file_normals = false;
};

// A boundary edge, directed as its one triangle runs along it.
struct Rim {
  std::uint32_t from, to;
  double length;
};

// Follows the boundary edges around each hole and adds (rim length)^2 / (4 pi) per hole to its
// part's caps. Where a rim cannot be followed (a position where two holes touch), the part's
// total boundary length stands for one hole: (sum L_h)^2 bounds sum L_h^2.
template <class PartOf>
void AddHoleCaps(const std::vector<Rim>& rims, PartOf part_of) {
  std::unordered_map<std::uint32_t, std::size_t> leaving;
  std::vector<std::uint32_t> pinched;
  for (std::size_t i = 0; i < rims.size(); ++i)
    if (!leaving.emplace(rims[i].from, i).second) pinched.push_back(rims[i].from);
  std::vector<std::uint8_t> done(rims.size(), 0);
  for (std::size_t i = 0; i < rims.size(); ++i) {
    if (done[i]) continue;
    double length = 0.0;
    bool closed = false;
    for (std::size_t at = i; !done[at];) {
      done[at] = 1;
      length += rims[at].length;
      const auto next = leaving.find(rims[at].to);
      if (next == leaving.end()) break;
      at = next->second;
      closed = at == i;
    }
    if (closed) part_of(rims[i].from).caps += length * length / (4.0 * kPi);
    else pinched.push_back(rims[i].from);
  }
  for (const std::uint32_t id : pinched) {
    auto& part = part_of(id);
    part.caps = std::max(part.caps, part.boundary * part.boundary / (4.0 * kPi));
  }
}

std::string Percent(double fraction) { return std::to_string(std::lround(100.0 * fraction)) + "%"; }

// Joins clauses as the run summary writes them after a label: "a; b; c".
std::string Clauses(const std::vector<std::string>& clauses) {
  std::string s;
  for (const std::string& c : clauses) s += (s.empty() ? "" : "; ") + c;
  return s;
}

}  // namespace

OrientationReport OrientMesh(Mesh& mesh, const std::vector<std::uint8_t>& normal_from_file) {
  OrientationReport report;
  auto from_file = [&](std::uint32_t v) { return v < normal_from_file.size() && normal_from_file[v] != 0; };
  const std::vector<std::uint32_t> ids = PositionIds(mesh);

  // Parts: triangles linked through shared positions, numbered in order of first triangle.
  DisjointSets sets(ids.size());
  for (const auto& t : mesh.triangles) sets.Union(ids[t[0]], ids[t[1]]), sets.Union(ids[t[0]], ids[t[2]]);
  std::vector<std::uint32_t> part_of_root(ids.size(), kNone), part_of_triangle(mesh.triangle_count());
  std::vector<Part> parts;
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    const std::uint32_t root = sets.Find(ids[mesh.triangles[t][0]]);
    if (part_of_root[root] == kNone) {
      part_of_root[root] = static_cast<std::uint32_t>(parts.size());
      parts.emplace_back();
    }
    part_of_triangle[t] = part_of_root[root];
    ++parts[part_of_root[root]].triangles;
  }

  // A part is closed and consistently oriented when each of its position edges is used twice,
  // once in each direction.
  std::vector<Rim> rims;
  std::vector<glm::vec3> position_of(ids.size());
  for (std::size_t v = 0; v < ids.size(); ++v) position_of[ids[v]] = mesh.positions[v];
  for (const PositionEdge& edge : PositionEdges(mesh, ids)) {
    Part& part = parts[part_of_root[sets.Find(edge.lo)]];
    part.has_edges = true;
    if (edge.uses != 2) part.watertight = false;
    else if (edge.balance != 0) part.consistent = false;
    if (edge.uses > 2) part.manifold = false;
    if (edge.uses == 1) {
      const double length = glm::length(glm::dvec3(position_of[edge.hi]) - glm::dvec3(position_of[edge.lo]));
      part.boundary += length;
      rims.push_back(edge.balance > 0 ? Rim{edge.lo, edge.hi, length} : Rim{edge.hi, edge.lo, length});
    }
  }
  AddHoleCaps(rims, [&](std::uint32_t id) -> Part& { return parts[part_of_root[sets.Find(id)]]; });

  // Volume, area and normal agreement, per part (double: float products are exact in it).
  const Bounds3 bounds = MeshBounds(mesh);
  const glm::dvec3 centre = 0.5 * (glm::dvec3(bounds.lo) + glm::dvec3(bounds.hi));
  for (std::size_t v = 0; v < ids.size(); ++v) {
    const std::uint32_t part = part_of_root[sets.Find(ids[v])];
    if (part != kNone)
      parts[part].radius = std::max(parts[part].radius, glm::length(glm::dvec3(mesh.positions[v]) - centre));
  }
  double area_all = 0.0, against_all = 0.0;
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    const auto& tri = mesh.triangles[t];
    glm::dvec3 p[3], normal_sum(0.0), file_sum(0.0);
    bool any_file = false;
    for (int c = 0; c < 3; ++c) {
      p[c] = glm::dvec3(mesh.positions[tri[c]]) - centre;
      normal_sum += glm::dvec3(mesh.normals[tri[c]]);
      if (from_file(tri[c])) file_sum += glm::dvec3(mesh.normals[tri[c]]), any_file = true;
    }
    const glm::dvec3 face = glm::cross(p[1] - p[0], p[2] - p[0]);
    const double area = 0.5 * glm::length(face);
    Part& part = parts[part_of_triangle[t]];
    part.volume += glm::dot(p[0], glm::cross(p[1], p[2])) / 6.0;
    part.area += area;
    area_all += area;
    if (glm::dot(face, normal_sum) < 0.0) against_all += area;
    if (!any_file) continue;
    part.file_area += area;
    const double agreement = glm::dot(face, file_sum);
    if (agreement < 0.0) part.file_against += area;
    if (agreement > 0.0) part.file_agree += area;
  }
  report.normals_against_winding = area_all > 0.0 ? against_all / area_all : 0.0;

  // Decide per part, and gather what is left alone for the warning.
  report.closed = !parts.empty();
  std::size_t flipped_parts = 0, open_triangles = 0, mixed_triangles = 0, tangled_triangles = 0, holed_parts = 0;
  std::size_t undecided_triangles = 0;  // open parts shaded by their winding alone
  double open_file = 0.0, open_against = 0.0, mixed_file = 0.0, mixed_against = 0.0;
  for (Part& part : parts) {
    report.signed_volume += part.volume;
    const bool oriented = part.has_edges && part.watertight && part.consistent;
    report.closed = report.closed && oriented;
    if (part.watertight && !part.consistent) tangled_triangles += part.triangles;
    // Nearly closed: consistently wound, with holes too small to decide the sign of the volume.
    // Measured from the centre, V is the volume of the part closed by cones from the centre
    // over its holes (on a cone through the centre p.n = 0: it adds nothing to the sum). A flat
    // cap of a hole with rim length L_h has area at most L_h^2 / (4 pi) (isoperimetric
    // inequality) and lies within the part's radius R of the centre, so it changes V by at most
    // (1/3) R L_h^2 / (4 pi). When |V| exceeds (1/3) R L^2 / (4 pi), L the total rim length,
    // closing the holes flat cannot change the sign: a scanned statue with a hole in its base.
    // (With caps above kSmallHoles of the area the part is a bowl or a dome, left alone.)
    const bool holed = part.has_edges && !part.watertight && part.consistent && part.manifold &&
                       part.caps <= kSmallHoles * part.area && std::abs(part.volume) > part.radius * part.caps / 3.0;
    holed_parts += holed && part.volume < 0.0;
    if ((oriented || holed) && std::abs(part.volume) > kFlatVolumeRatio * std::pow(part.area, 1.5)) {
      part.flip_winding = part.volume < 0.0;
      flipped_parts += part.flip_winding ? 1 : 0;
      const double against = part.flip_winding ? part.file_agree : part.file_against;
      part.flip_file_normals = against > kMostArea * part.file_area;
      if (!part.flip_file_normals && against > kMixedArea * part.file_area)
        mixed_triangles += part.triangles, mixed_file += part.file_area, mixed_against += against;
    } else if (part.file_against > kMostArea * part.file_area) {
      open_triangles += part.triangles, open_file += part.file_area, open_against += part.file_against;
    } else if (part.file_area == 0.0 && part.has_edges) {
      undecided_triangles += part.triangles;
    }
  }

  // Reverse the winding of inside-out parts (swapping two corners keeps the first corner).
  std::vector<std::uint8_t> touched(mesh.vertex_count(), 0);
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    if (!parts[part_of_triangle[t]].flip_winding) continue;
    auto& tri = mesh.triangles[t];
    std::swap(tri[1], tri[2]);
    if (mesh.textured()) std::swap(mesh.corner_uv[3 * t + 1], mesh.corner_uv[3 * t + 2]);
    touched[tri[0]] = touched[tri[1]] = touched[tri[2]] = 1;
    ++report.flipped_triangles;
  }
  // Normals computed from the winding turn with it: negating them gives exactly what
  // recomputing would (SmoothNormals is odd under reversal: the face normals change sign, the
  // corner angles and the summation order do not; only the sign of a zero may differ), and
  // keeps whatever the loader chose to compute. File normals turn where their part's area says
  // so.
  std::size_t recomputed = 0, negated = 0;
  for (std::uint32_t v = 0; v < mesh.vertex_count(); ++v) {
    const std::uint32_t part = part_of_root[sets.Find(ids[v])];
    if (part == kNone) continue;  // a vertex no triangle uses
    if (from_file(v) ? parts[part].flip_file_normals : touched[v] != 0) {
      mesh.normals[v] = -mesh.normals[v];
      ++(from_file(v) ? negated : recomputed);
    }
  }
  report.flipped_normals = recomputed + negated;

  std::vector<std::string> fixed;
  if (flipped_parts > 0)
    fixed.push_back("reversed the winding of " + std::to_string(report.flipped_triangles) + " triangles in " +
                    std::to_string(flipped_parts) + " part(s) with negative volume (inside out" +
                    (holed_parts > 0 ? "; " + std::to_string(holed_parts) + " of them closed but for small holes)"
                                     : std::string(")")) +
                    (recomputed > 0 ? ", turning the " + std::to_string(recomputed) + " normals computed from it"
                                    : ""));
  if (negated > 0)
    fixed.push_back("negated " + std::to_string(negated) +
                    " normals from the file that pointed into their closed part on most of its area");
  report.fixed = Clauses(fixed);

  std::vector<std::string> warning;
  if (open_triangles > 0)
    warning.push_back("the file's normals point against the triangle winding on " + Percent(open_against / open_file) +
                      " of the area of " + std::to_string(open_triangles) +
                      " triangles of open, flat or inconsistently wound parts, whose outside cannot be told, so "
                      "nothing was changed there; shading follows the normals: make winding and normals agree "
                      "in the modelling tool, or re-export with outward normals");
  if (mixed_triangles > 0)
    warning.push_back("the file's normals point into closed parts on " + Percent(mixed_against / mixed_file) +
                      " of their area (" + std::to_string(mixed_triangles) +
                      " triangles), too little to negate them all: re-export with outward normals");
  // An open part has no inside to measure, but one exporter wound the whole file: when its closed
  // parts were inside out, its open ones (a floor) probably are too.
  if (flipped_parts > 0 && undecided_triangles > 0)
    warning.push_back(std::to_string(undecided_triangles) +
                      " triangles of open parts without normals were left as wound, since an open surface has no "
                      "inside; the closed parts of this file were inside out, so these may be too: if they render "
                      "dark, reverse their winding in the modelling tool");
  if (tangled_triangles > 0)
    warning.push_back(std::to_string(tangled_triangles) +
                      " triangles form closed surfaces wound inconsistently (neighbours disagree), so their "
                      "winding was not repaired: recalculate outward normals in the modelling tool");
  report.warning = Clauses(warning);
  return report;
}

}  // namespace prt
