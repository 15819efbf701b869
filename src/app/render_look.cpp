#include "app/render_look.h"

#include <utility>

#include "bases/list.h"
#include "core/log.h"
#include "core/text.h"

namespace prt {
namespace {

glm::dvec3 Vec(const double (&v)[3]) { return {v[0], v[1], v[2]}; }

/// The highest band the course's viewer reads: 9 numbers a row.
constexpr int kCourseLmax = 2;

/// "--basis A or --basis B": the bases whose coefficients per vertex are SH transfer, as the course's
/// files hold (`sh_transfer`), or the others.
std::string BasesWhose(bool sh_transfer) {
  std::string text;
  for (const Basis* b : Bases())
    if (b->Traits().coefficient_view == sh_transfer) text += (text.empty() ? "--basis " : " or --basis ") + b->Name();
  return text;
}

}  // namespace

OptionSpec LookOption() {
  return {"--look", "LOOK",
          "default | course. course: what the GAMES202 homework-2 WebGL viewer shows of the light.txt and "
          "transport.txt that prt precompute writes for the same scene options: per vertex light.txt . transport.txt "
          "without albedo (--view irradiance), interpolated, then the sRGB curve with no exposure (--tonemap srgb "
          "--exposure 0), the raw coefficients (--window none), from the viewer's camera (--eye " +
              VecText(Vec(kCourseEye)) + " --target " + VecText(Vec(kCourseTarget)) + " --fov " +
              Formatted("%g", kCourseFov) +
              ": three.js's eye 0,0,100 and vertical fov 75 with the mesh placed as the framework places mary, "
              "translate 0,-35,0 and scale 20); frame 0 is the viewer's picture (its light does not turn). Options "
              "given on the command line win over the look, each camera value on its own. Not with " +
              BasesWhose(false) + " (the viewer reads SH files, which precompute writes with " + BasesWhose(true) +
              " only); with a glossy --material "
              "a warning, and the picture shows the diffuse part, as the viewer does with transport.txt; with --lmax "
              "other than 2 a warning (the viewer reads 9 numbers a row). Coloured interreflection shows the exact "
              "per-channel transport, where the viewer loads transport.txt's luminance mix",
          "default (prt's own picture: ACES, automatic exposure, albedo)"};
}

Look ReadLook(Args& args) {
  return args.Choice("--look", "default", {"default", "course"}) == "course" ? Look::kCourse : Look::kDefault;
}

SceneOptions LookSceneDefaults(Look look, SceneOptions d) {
  if (look == Look::kCourse) d.window = "none";
  return d;
}

RenderOptions LookRenderDefaults(Look look, RenderOptions d) {
  if (look != Look::kCourse) return d;
  d.view = View::kIrradiance;  // light . transport, albedo 1: the viewer's shader has no albedo
  d.tonemap = ToneCurve::kSrgb;
  d.exposure = 0.0;
  d.eye = Vec(kCourseEye), d.target = Vec(kCourseTarget), d.fov = kCourseFov;
  return d;
}

std::string CheckLook(Args& args, Look look, const SceneOptions& scene) {
  if (look != Look::kCourse) return "";
  if (!scene.basis->Traits().coefficient_view)
    args.Fail("--look course: shows what the course's viewer draws from light.txt and transport.txt, which hold SH "
              "coefficients; --basis " + scene.basis->Name() + " has none (expected --basis " +
              DefaultBasis()->Name() + ", or --look default)");
  if (scene.lmax != kCourseLmax)
    Warn("--look course with lmax " + std::to_string(scene.lmax) + ": the course's WebGL viewer reads exactly 9 "
         "numbers a row (lmax 2) and draws garbage, without an error, from precompute's files at any other lmax; "
         "this picture shows lmax " + std::to_string(scene.lmax) + " as it should look");
  if (scene.material.glossy)
    Warn("--look course with --material " + scene.material.Name() + ": the course's viewer shows transport.txt, "
         "the diffuse part only, and so does this picture (no highlights; --look default shows them)");
  const std::pair<const char*, std::string> set[] = {
      {"--view", "irradiance"},
      {"--tonemap", "srgb"},
      {"--exposure", "0"},
      {"--window", "none"},
      {"--eye", VecText(Vec(kCourseEye))},
      {"--target", VecText(Vec(kCourseTarget))},
      {"--fov", Formatted("%g", kCourseFov)}};
  std::string line = "look course (the GAMES202 homework-2 viewer; frame 0 is its picture):", kept;
  for (const auto& [option, value] : set)
    if (args.Has(option)) kept += std::string(" ") + option;
    else line += std::string(" ") + option + " " + value;
  return line + (kept.empty() ? "" : "; given on the command line, kept:" + kept);
}

}  // namespace prt
