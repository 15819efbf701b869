#pragma once
/// \file
/// The pinhole camera: look-at placement and a perspective projection, world Y up.
///
/// Clip space follows OpenGL [1] as built by glm::lookAt / glm::perspective [2]: the camera looks
/// down its -Z axis, clip w = distance in front of the eye along the view axis, and NDC x, y are
/// in [-1, 1] with +y up. The rasterizer clips at w = near_plane and has no far plane; the far
/// plane only matters to OpenGL comparisons (ProjectionMatrix).
///
/// Automatic framing (FramePoints). Fix the view direction and write every point in the camera's
/// basis: x_i = p_i . s (right), y_i = p_i . u (up), z_i = p_i . f (forward); the eye is
/// e = x_e s + y_e u + z_e f. With th = tan(half horizontal fov) and tv = tan(half vertical fov),
/// point i is inside the left and right frustum planes when |x_i - x_e| <= th (z_i - z_e), i.e.
///     x_i - th z_i <= x_e - th z_e    and    -x_i - th z_i <= -x_e - th z_e.
/// Let A = max_i (x_i - th z_i) and B = max_i (-x_i - th z_i). The eye farthest forward that
/// satisfies both makes both tight, so some point touches each side plane:
///     x_e = (A - B) / 2,    z_e = -(A + B) / (2 th),
/// and likewise y_e, z_e' from C = max (y_i - tv z_i), D = max (-y_i - tv z_i). The eye takes
/// the farther of the two depths, min(z_e, z_e'), so every point fits both ways; on that
/// (tighter) axis the image touches both edges, so it is centred. On the other axis the eye
/// stands farther back than that axis needed, where (A - B) / 2 no longer centres the image
/// (the points are at different depths), so its offset is solved again at the chosen depth:
/// the offset whose widest projected point on the right equals the one on the left, found by
/// bisection (the sum of the two extreme projections falls monotonically as the offset grows).
/// The margin is applied by using th / (1 + kFrameMargin) and tv / (1 + kFrameMargin) in place
/// of th and tv. A third bound keeps the eye at least 5% of the set's size before its nearest
/// point: a set with no extent across the view (one point, a segment along the view axis)
/// would otherwise put the apex of the frustum on a point (both axes are then re-centred).
///
/// References:
///  [1] The OpenGL Graphics System 4.6 (Core Profile), sections 13.6-13.8 (coordinate
///      transformations), and the gluLookAt / gluPerspective man pages.
///  [2] GLM 0.9.9, glm/ext/matrix_transform.inl (lookAtRH) and matrix_clip_space.inl
///      (perspectiveRH_NO).

#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace prt {

/// Where the camera is and what it sees. Units are world units, angles in degrees.
struct Camera {
  glm::vec3 eye{0.f, 0.f, 5.f};   ///< camera position
  glm::vec3 target{0.f};          ///< point looked at (the centre of the image)
  glm::vec3 up{0.f, 1.f, 0.f};    ///< approximate up; must not be parallel to target - eye
  float fov_deg = 35.f;           ///< vertical field of view, in (0, 180)
  float near_plane = 0.01f;       ///< clipping distance along the view axis, > 0
  float far_plane = 1000.f;       ///< only for ProjectionMatrix (OpenGL); > near_plane
};

/// Throws Error naming the CLI option (`--eye`, `--up`, `--fov`) when the camera is unusable:
/// eye == target, up parallel to the view direction, fov outside (0, 180), bad clip planes.
void CheckCamera(const Camera& camera);

/// World -> camera space (right-handed, camera looks down -Z). Precondition: CheckCamera passes.
glm::mat4 ViewMatrix(const Camera& camera);

/// Camera -> clip space, OpenGL convention (z in [-w, w]). aspect = width / height > 0.
glm::mat4 ProjectionMatrix(const Camera& camera, float aspect);

/// The camera's ray directions, precomputed for many pixels.
struct ViewRays {
  glm::vec3 forward{0.f, 0.f, -1.f};  ///< unit view axis
  glm::vec3 right{1.f, 0.f, 0.f};     ///< scaled so that ndc_x = 1 is the right image edge
  glm::vec3 up{0.f, 1.f, 0.f};        ///< scaled so that ndc_y = 1 is the top image edge
  /// Unit world-space direction through normalised device coordinates (ndc_x, ndc_y), both in
  /// [-1, 1] with +y up.
  glm::vec3 Direction(float ndc_x, float ndc_y) const;
};
/// Ray directions for a width / height ratio `aspect`. Precondition: CheckCamera passes.
ViewRays MakeViewRays(const Camera& camera, float aspect);

/// MakeViewRays(camera, aspect).Direction(ndc_x, ndc_y), for one ray (e.g. the background).
glm::vec3 ViewDirection(const Camera& camera, float aspect, float ndc_x, float ndc_y);

/// Sets near_plane and far_plane so that the bounding box [min, max] lies between them: near is
/// half the depth (distance along the view axis) of the box's nearest corner, never below 1e-3
/// of the box's half-diagonal, so a camera inside the box still gets a positive near plane; far
/// is the centre's depth plus twice the half-diagonal (beyond every corner). Deterministic in
/// (eye, target, box): a camera given on the command line gets the same planes as the
/// automatically framed one, so a printed camera reproduces the same image.
Camera FitClipPlanes(Camera camera, const glm::vec3& min, const glm::vec3& max);

/// The camera turned `degrees` (right-handed) about the line through its target along its up
/// direction: the eye circles the target at its distance and height, still looking at it.
/// Clip planes refitted to the box [min, max].
Camera Orbit(const Camera& camera, double degrees, const glm::vec3& min, const glm::vec3& max);

/// A pleasant 3/4 view of the box [min, max]: from the front-right (+Z, +X) and 20 degrees above,
/// looking at the box centre, far enough that the box's bounding sphere fits the view with a 5%
/// margin at the given aspect (width / height). Clip planes fitted with FitClipPlanes. Wasteful
/// for tall or flat boxes (the sphere is much larger than the box's image); FramePoints fits
/// the image itself.
Camera FrameBounds(const glm::vec3& min, const glm::vec3& max, float aspect);

/// Relative margin FramePoints leaves around the points' image: the outermost point projects
/// to |ndc| = 1 / (1 + kFrameMargin) on the tighter axis.
constexpr float kFrameMargin = 0.05f;

/// The view of FrameBounds (from the front-right, 30 degrees around Y from +Z, 20 degrees above
/// the horizon, up = world +Y, vertical field of view fov_deg) placed so that the points'
/// projection fills the frame exactly, up to kFrameMargin, on the tighter of the two axes, and is
/// centred on both (the closed form above). The target lies on the view axis at the depth of the
/// points' centroid; clip planes come from FitClipPlanes on the points' bounding box, as for a
/// camera given on the command line.
/// Deterministic. Degenerate sets (empty, one point, all equal, a segment along the view axis)
/// get a finite camera that stands at least 5% of the set's size (1 when it has none) before the
/// nearest point. Preconditions: aspect > 0, fov_deg in (0, 180).
Camera FramePoints(const std::vector<glm::vec3>& points, float aspect, float fov_deg = 35.f);

/// The camera in the command-line syntax of CLI.md, exact enough to reproduce it:
/// `--eye X,Y,Z --target X,Y,Z --up X,Y,Z --fov DEGREES`.
std::string CameraArgs(const Camera& camera);

}  // namespace prt
