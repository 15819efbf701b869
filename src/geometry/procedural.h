#pragma once
/// \file
/// Meshes generated in code, for the embedded demo scene and for tests. Every builder returns
/// a complete `Mesh`: unit normals and an albedo per vertex, triangles counter-clockwise seen
/// from the side the normals point to.
///
/// References
///  [1] "Torus knot", https://en.wikipedia.org/wiki/Torus_knot (parametrisation of the (p, q)
///      knot on a torus).

#include <glm/vec3.hpp>

#include "geometry/mesh.h"
#include "geometry/mesh_ops.h"

namespace prt {

/// Latitude-longitude sphere: `segments` (>= 3) steps around the Y axis, segments / 2 (>= 2)
/// rings from pole to pole, one vertex at each pole. Vertices lie on the sphere and their normal
/// is the exact radial direction, so the tangent plane at every vertex supports the mesh.
/// Triangles: 2 * segments * (segments / 2 - 1); segments = 320 gives 101,760.
Mesh MakeSphere(int segments, float radius = 1.0f, const glm::vec3& center = glm::vec3(0.0f),
                const glm::vec3& albedo = glm::vec3(kDefaultAlbedo));

/// Square in the plane y = `height`, centred on the Y axis, side `size`, split into
/// divisions x divisions quads; normal +Y.
Mesh MakePlane(float size, int divisions = 1, float height = 0.0f,
               const glm::vec3& albedo = glm::vec3(kDefaultAlbedo));

/// Which way the faces of a box look.
enum class BoxFacing {
  kOutward,  ///< a solid block seen from outside
  kInward,   ///< a closed room seen from inside (normals point into the box)
};

/// Closed axis-aligned box [lo, hi], each face split into divisions x divisions quads. Faces do
/// not share vertices (a flat normal per face, 4 * (divisions + 1)^2 vertices per face).
/// The inward variant is a closed room: a point inside it is fully occluded.
Mesh MakeBox(const glm::vec3& lo, const glm::vec3& hi, BoxFacing facing = BoxFacing::kOutward,
             int divisions = 1, const glm::vec3& albedo = glm::vec3(kDefaultAlbedo));

/// Tube of radius `tube_radius` swept along the (p, q) torus knot [1]
///   c(phi) = ((2 + cos(q phi)) cos(p phi), (2 + cos(q phi)) sin(p phi), sin(q phi)) / 3,
/// phi in [0, 2 pi): the curve winds p times around the Z axis and q times through the hole.
/// Its lobes shadow each other deeply. `segments` steps along the curve, `sides` around the
/// tube; closed and seamless (2 * segments * sides triangles). The curve lies within radius 1.
Mesh MakeTorusKnot(int p = 2, int q = 3, float tube_radius = 0.16f, int segments = 512,
                   int sides = 48, const glm::vec3& albedo = glm::vec3(kDefaultAlbedo));

/// Scales `mesh` uniformly to `height` units tall and moves it up or down so that its lowest
/// point is at y = `lift`: an object standing on (or `lift` above) a ground at y = 0.
void StandUpright(Mesh& mesh, float height, float lift = 0.0f);

/// A (2, 3) torus knot standing upright (facing +Z) on a square ground at y = 0, merged into one
/// mesh: the scene of the demo, the report and the wavelet study, each with its own sizes.
struct KnotOverGround {
  int segments = 512, sides = 48;                       ///< the knot's tube (MakeTorusKnot)
  glm::vec3 knot_albedo{0.80f, 0.38f, 0.20f};
  float height = 3.4f;                                  ///< the knot's height (StandUpright)
  float lift = 0.0f;                                    ///< its lowest point above the ground
  float ground_size = 12.0f;                            ///< the ground's side
  int ground_quads = 96;                                ///< quads along each side
  glm::vec3 ground_albedo{0.7f, 0.7f, 0.7f};
  bool ground_first = true;                             ///< the ground's vertices before the knot's
};
Mesh MakeKnotOverGround(const KnotOverGround& scene);

/// The embedded demo scene: MakeKnotOverGround's defaults, a knot about 3.4 units tall on a
/// 12 x 12 ground. Sized like the course's mary model so the course camera (0, 8, 22) ->
/// (0, 1, 1) frames it.
Mesh MakeDemoScene();

}  // namespace prt
