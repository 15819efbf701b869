#pragma once
/// \file
/// The pinhole camera: look-at placement and a perspective projection, world Y up.
///
/// Clip space follows OpenGL [1] as built by glm::lookAt / glm::perspective [2]: the camera looks
/// down its -Z axis, clip w = distance in front of the eye along the view axis, and NDC x, y are
/// in [-1, 1] with +y up. The rasterizer clips at w = near_plane and has no far plane; the far
/// plane only matters to OpenGL comparisons (ProjectionMatrix).
///
/// References:
///  [1] The OpenGL Graphics System 4.6 (Core Profile), sections 13.6-13.8 (coordinate
///      transformations), and the gluLookAt / gluPerspective man pages.
///  [2] GLM 0.9.9, glm/ext/matrix_transform.inl (lookAtRH) and matrix_clip_space.inl
///      (perspectiveRH_NO).

#include <string>

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

/// Sets near_plane and far_plane so that the bounding box [min, max] lies between them (near is
/// half the distance to the box's bounding sphere, never below 1e-3 of its radius). Deterministic
/// in (eye, target, box): a camera given on the command line gets the same planes as the
/// automatically framed one, so a printed camera reproduces the same image.
Camera FitClipPlanes(Camera camera, const glm::vec3& min, const glm::vec3& max);

/// A pleasant 3/4 view of the box [min, max]: from the front-right (+Z, +X) and 20 degrees above,
/// looking at the box centre, far enough that the box's bounding sphere fits the view with a 5%
/// margin at the given aspect (width / height). Clip planes fitted with FitClipPlanes.
Camera FrameBounds(const glm::vec3& min, const glm::vec3& max, float aspect);

/// The camera in the command-line syntax of CLI.md, exact enough to reproduce it:
/// `--eye X,Y,Z --target X,Y,Z --up X,Y,Z --fov DEGREES`.
std::string CameraArgs(const Camera& camera);

}  // namespace prt
