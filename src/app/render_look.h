#pragma once
/// \file
/// `prt render --look`: presets of the render and scene options. `course` renders what the
/// GAMES202 homework-2 WebGL viewer shows of the light.txt and transport.txt `prt precompute`
/// writes (per vertex light . transport without albedo, interpolated, the sRGB curve with no
/// exposure, the raw coefficients, the viewer's camera); the options a user gives win over it.

#include <string>

#include "options/args.h"
#include "app/scene_options.h"
#include "render/render_options.h"

namespace prt {

/// The presets of `prt render --look`: default (prt's own picture: ACES, automatic exposure,
/// albedo) or course (what the GAMES202 homework-2 WebGL viewer shows of the light.txt and
/// transport.txt that `prt precompute` writes: per vertex light . transport without albedo,
/// interpolated, then the sRGB curve, from the viewer's camera).
enum class Look { kDefault, kCourse };

/// The course viewer's camera in the mesh's own coordinates: three.js's PerspectiveCamera at
/// (0, 0, 100) looking at the origin with a vertical fov of 75 degrees, while the framework places
/// mary by translate(0, -35, 0) and scale 20: eye (0, 35, 100) / 20, target (0, 35, 0) / 20.
inline constexpr double kCourseEye[3] = {0.0, 1.75, 5.0};
inline constexpr double kCourseTarget[3] = {0.0, 1.75, 0.0};
inline constexpr double kCourseFov = 75.0;  ///< vertical, as prt's --fov

/// The `--look` table entry (render only).
OptionSpec LookOption();

/// Reads --look: kDefault when not given; another value is a usage error naming the valid ones.
Look ReadLook(Args& args);

/// The scene defaults under `look` (course: --window none, the raw coefficients the viewer uses).
SceneOptions LookSceneDefaults(Look look, SceneOptions defaults);

/// The render defaults under `look` (course: --view irradiance --tonemap srgb --exposure 0 and
/// the viewer's camera), so that each option given on the command line wins over the look.
RenderOptions LookRenderDefaults(Look look, RenderOptions defaults);

/// Checks `scene` against the look (course: --basis wavelet is refused, an lmax other than 2 and
/// a glossy material are warnings) and returns the run-summary line saying what the look set
/// (the options given on the command line named as kept); "" for the default look.
std::string CheckLook(Args& args, Look look, const SceneOptions& scene);

}  // namespace prt
