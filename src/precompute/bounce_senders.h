#pragma once
/// \file
/// The surfaces that send bounced light, split finely for the bounce pass only.
///
/// A bounce gathers, at each blocked direction's hit point, the light that point sends out, and
/// reads it (transport.h) barycentrically from the hit triangle's three vertices. On a coarse
/// triangle that interpolation is wrong wherever the light varies inside it: a ground made of one
/// quad has its four corners in full sun, so a bounce ray that hits the ground in the knot's
/// shadow reads full sun, and the knot receives too much bounced light at any lmax (the sample
/// scene of `prt sample-files`, one bounce, lmax 16: 11.2 % RMS from `prt reference`, mean 5.6 %
/// too bright; with the ground in 40 x 40 quads, 3.7 %).
///
/// So for interreflection the transport is computed on a copy of the mesh whose edges longer
/// than kSenderEdge of the bounding-box diagonal are split (geometry/subdivide.h: conforming,
/// the original vertices first and unchanged, the surface the same), and only the original
/// vertices' transport is kept: the output has the mesh's own vertices, while the light a bounce
/// reads is interpolated over short edges. The added vertices trace as many directions as the
/// vertices the camera does not see: they only send light. A mesh whose every edge is already
/// short (the demo scene, the course's meshes) is used as it is, at no cost.
///
/// Measured on the sample scene (knot and one-quad ground, its sky.hdr, one bounce, lmax 16,
/// 4096 directions, against `prt reference` with 8192 directions, whose own error is 0.67 %):
/// with the split 4.59 % RMS and no bias in the mean; on the knot's vertices 4.61 %, against
/// 4.62 % with the ground made of 40 x 40 quads. On the course's mary under GraceCathedral (lmax
/// 8): 3.61 % without, 2.20 % with. The test "bounce senders" (tests/precompute/
/// test_bounce_senders.cpp) checks the independence from the ground's triangles.

#include <cstddef>
#include <optional>

#include "geometry/mesh.h"

namespace prt {

/// Longest edge of a light-sending triangle, as a share of the bounding-box diagonal.
constexpr double kSenderEdge = 0.02;
/// The split copy may have at most this many times the mesh's triangles (and at least this
/// many more allowed: kSenderMinTriangles); beyond it the mesh is used as it is and the run
/// summary says how to split it (--max-edge).
constexpr std::size_t kSenderTriangleFactor = 4;
constexpr std::size_t kSenderMinTriangles = 200'000;

/// What RefineSenders did, for the run summary.
struct SenderRefinement {
  bool needed = false;          ///< some edge is longer than the limit
  bool done = false;            ///< the copy was made
  float max_edge = 0.0f;        ///< the limit, world units
  std::size_t vertices_added = 0;
  std::size_t triangles_estimate = 0;  ///< when not done: the triangles the split would have made
};

/// The copy of `mesh` with every edge longer than kSenderEdge of its diagonal split, or nothing
/// when no edge is that long or the copy would be too large (`report` says which).
std::optional<Mesh> RefineSenders(const Mesh& mesh, SenderRefinement& report);

}  // namespace prt
