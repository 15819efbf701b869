#include "app/pipeline.h"

#include <chrono>
#include <cstdio>
#include <filesystem>

#include "app/seen_ringing.h"
#include "core/error.h"
#include "core/log.h"
#include "core/text.h"
#include "env/load_environment.h"
#include "precompute/light.h"
#include "raster/exposure.h"
#include "sh/dering.h"
#include "sh/window.h"

namespace prt {
namespace {

/// Applies --window auto to `light`; its run-summary clause (sh/dering.h).
std::string ApplyAutoWindow(ShRgb& light) {
  const auto t0 = std::chrono::steady_clock::now();
  const AutoWindow choice = ChooseAutoWindow(light);
  ApplyWeights(choice.weights, light);
  return choice.Describe() + Formatted(" [%.3f s]", SecondsSince(t0));
}

/// kDefaultWindow for the frames of `view`: the auto window when they would show the light's
/// ringing (FindSeenRinging), else none; the run-summary clause ("" when nothing was checked).
std::string DefaultWindow(ShRgb& light, const SceneOptions& options, View view) {
  // A basis whose frames are not lit by the SH light (the wavelets: its SH light feeds only the
  // bounces) keeps the raw light. (kMaxLmax <= kMaxAutoWindowLmax: auto takes any lmax here.)
  static_assert(kMaxLmax <= kMaxAutoWindowLmax);
  if (!options.basis->Traits().windowed_light) return "";
  const auto t0 = std::chrono::steady_clock::now();
  const SeenRinging seen = FindSeenRinging(light, options.material, view);
  if (seen.what.empty()) return "";  // --view albedo or transport shows no light
  if (!seen.rings)
    return "; no window needed (" + seen.what + " stays non-negative" + Formatted(") [%.3f s]", SecondsSince(t0));
  const double share = seen.peak > 0 ? seen.lowest / seen.peak : 0.0;
  return "; window auto (default: " + seen.what + Formatted(" goes down to %.3g, %.3g%% of its peak", seen.lowest, 100.0 * share) +
         "; --window none keeps the raw light): " + ApplyAutoWindow(light);
}

}  // namespace

std::shared_ptr<const Environment> LoadSceneEnvironment(const SceneOptions& options, OutputFolder* folder) {
  const auto t0 = std::chrono::steady_clock::now();
  // --lmax auto loaded it already (ReadSceneOptions), unless the options now name another.
  const bool loaded = options.loaded_env && options.loaded_env_spec == options.env && options.loaded_env_layout == options.layout;
  const std::shared_ptr<const Environment> env = loaded ? options.loaded_env : LoadEnvironment(options.env, options.layout);
  std::error_code ec;
  if (folder && std::filesystem::exists(options.env, ec)) folder->KeepInput(options.env);  // not a built-in
  Summary("environment: " + env->Describe() + Formatted(" [%.3f s]", SecondsSince(t0)));
  return env;
}

ShRgb ComputeLight(const Environment& env, const SceneOptions& options, View view) {
  const auto t0 = std::chrono::steady_clock::now();
  ShRgb light = ProjectLight(env, options.lmax);
  std::string line = "light: lmax " + std::to_string(options.lmax) + " (" +
                     std::to_string(CoeffCount(options.lmax)) + " coefficients)" +
                     Formatted(" [%.3f s]", SecondsSince(t0));
  if (options.window == kDefaultWindow) {
    line += DefaultWindow(light, options, view);
  } else if (options.window == "auto") {
    line += "; window auto: " + ApplyAutoWindow(light);
  } else if (options.window != "none") {
    ApplyWindow(WindowFromName(options.window), light);
    line += "; window " + options.window;
  }
  Summary(line);
  return light;
}

Camera SceneCamera(const Mesh& mesh, const RenderOptions& render) {
  std::string up_note;
  const Camera camera = ChooseCamera(mesh, render, &up_note);
  Summary("camera: " + CameraArgs(camera) + (up_note.empty() ? "" : " (" + up_note + ")"));
  return camera;
}

void ReportAutoExposure(double ev, const std::string& what) {
  Summary(Formatted("exposure: auto -> %.1f EV, measured on %s (--exposure %.1f repeats it)", ev, what.c_str(), ev) +
          AutoExposureLimitNote(ev));
}

void FinishOutputs(OutputFolder& folder) {
  const OutputFolder::Finished f = folder.Finish();
  const auto names = [](const std::vector<std::string>& v) {
    return v.front() + (v.size() > 2 ? " ... " + v.back() : v.size() == 2 ? ", " + v.back() : "");
  };
  if (!f.kept_as_orig.empty())
    Summary("outputs: replaced " + std::to_string(f.kept_as_orig.size()) + " file" +
            (f.kept_as_orig.size() > 1 ? "s" : "") + " prt did not write in " + folder.dir() +
            " (--replace), kept as " + names(f.kept_as_orig));
  if (!f.removed.empty())
    Summary("outputs: removed " + std::to_string(f.removed.size()) + " file" + (f.removed.size() > 1 ? "s" : "") +
            " an earlier run of this command wrote in " + folder.dir() + " and this one did not (" +
            f.removed.front() + (f.removed.size() > 1 ? " ... " + f.removed.back() : "") + ")");
}

}  // namespace prt
