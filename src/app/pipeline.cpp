#include "app/pipeline.h"

#include <chrono>
#include <cstdio>

#include "core/log.h"
#include "env/load_environment.h"
#include "precompute/light.h"
#include "sh/window.h"

namespace prt {
namespace {

double SecondsSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

std::string Format(const char* fmt, double a, double b = 0.0) {
  char buf[256];
  std::snprintf(buf, sizeof buf, fmt, a, b);
  return buf;
}

}  // namespace

std::unique_ptr<Environment> LoadSceneEnvironment(const SceneOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  auto env = LoadEnvironment(options.env, options.layout);
  Summary("environment: " + env->Describe() + Format(" [%.3f s]", SecondsSince(t0)));
  return env;
}

ShRgb ComputeLight(const Environment& env, const SceneOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  ShRgb light = ProjectLight(env, options.lmax);
  std::string line = "light: lmax " + std::to_string(options.lmax) + " (" +
                     std::to_string(CoeffCount(options.lmax)) + " coefficients)" +
                     Format(" [%.3f s]", SecondsSince(t0));
  if (options.window == "auto") {
    const AutoWindow choice = ChooseWindow(light);
    ApplyWindow(choice.window, light);
    line += std::string("; window auto -> ") + WindowName(choice.window) +
            Format(" (lowest reconstructed radiance %.3g without, %.3g with)", choice.min_before,
                   choice.min_after);
    if (choice.window == Window::kNone) line += ", no windowing needed: already non-negative";
  } else if (options.window != "none") {
    ApplyWindow(options.window == "hann" ? Window::kHann : Window::kLanczos, light);
    line += "; window " + options.window;
  }
  Summary(line);
  return light;
}

}  // namespace prt
