// prt report: error against run time (report_sweep.h, report_write.h), with --basis NAME the
// basis's own study where it has one (basis/study.h; the wavelets': SH against Haar wavelets), or
// with --stability the stiff and extreme cases (stability.h).
#include <algorithm>
#include <cstdio>
#include <set>

#include "app/commands.h"
#include "app/pipeline.h"
#include "bases/list.h"
#include "basis/study.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/log.h"
#include "core/text.h"
#include "render/render_frames.h"
#include "report/report_glossy.h"
#include "report/report_image.h"
#include "report/report_sweep.h"
#include "report/report_write.h"
#include "report/stability.h"
#include "texture/albedo_limit.h"

namespace prt {
namespace {
std::string Fmt(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3g", v);
  return b;
}

/// What --stability reads: its cases are fixed, so every scene and sweep option would be ignored.
const std::set<std::string> kStabilityOptions = {"--stability", "--out", "--replace", "--quiet", "--threads"};

/// The report scene under a coat of `ks`: albedo + KS <= 1 kept per vertex by the rule a
/// textured mesh keeps per texel (texture/albedo_limit.h), hue kept. Returns the summary line, empty if none was, and
/// in `note` what the report's scene name adds.
std::string FitReportSceneToCoat(Mesh& mesh, double ks, std::string& note) {
  const float limit = static_cast<float>(1.0 - ks);
  std::size_t scaled = 0;
  glm::vec3 example(0.f), fitted(0.f);
  for (glm::vec3& a : mesh.albedo) {
    const glm::vec3 fit = LimitAlbedo(a, limit);
    if (fit == a) continue;
    if (scaled++ == 0) example = a, fitted = fit;
    a = fit;
  }
  if (!scaled) return "";
  note = Formatted(", albedo fitted under the coat: %zu vertices scaled to 1 - KS = %.3g, hue kept", scaled, double(limit));
  return Formatted("report: the report scene's albedo fitted to the coat: albedo + KS <= 1 kept per vertex, "
                   "%zu vertices brighter than 1 - KS = %.3g scaled down to it with their hue (e.g. %.3g,%.3g,%.3g -> "
                   "%.3g,%.3g,%.3g); --albedo sets another",
                   scaled, double(limit), example.x, example.y, example.z, fitted.x, fitted.y, fitted.z);
}
}  // namespace

CommandSpec ReportSpec() {
  OptionGroup report{"report options",
                     {{"--out", "DIR", "output folder, created if missing; one run at a time", "required"},
                      {"--quick", "", "shadowed only, 16..256 directions, lmax 1..4, smaller references (well under a minute)", ""},
                      {"--max-samples", "N", "largest directions per vertex of the sweep, 16..1048576", "16384; 256 with --quick"},
                      {"--max-lmax", "L", "highest lmax of the sweep, 1..32 (the sample rule's evidence needs the high bands)",
                       "8; 4 with --quick"},
                      {"--stability", "",
                       "run the stiff and extreme cases instead: DIR/stability.csv and DIR/report.md, pass/fail on "
                       "stderr; exit 1 if any fails. Its cases are fixed: it takes --out, --replace, --quiet and "
                       "--threads, and refuses every other option",
                       ""},
                      ReplaceOption(), QuietOption()}};
  OptionGroup scene = SceneOptionGroup(SceneOptions{}, {"--mesh", "--env", "--bounces", "--albedo", "--material",
                                                         "--seed", "--threads", "--games202-faces", "--max-edge",
                                                         "--basis"});
  scene.options[0].default_text = "a small torus knot on a 12 x 12 plane, about 2,700 vertices";
  // --basis: the list's names, then what each basis's own study adds (basis/study.h).
  std::string names, studies, described;
  for (const std::string& name : BasisNames()) names += (names.empty() ? "" : " | ") + name;
  for (const Basis* basis : Bases())
    if (const BasisStudy* study = basis->Study()) {
      studies += (studies.empty() ? "" : "; ") + study->ReportOptionHelp();
      described += " " + study->ReportHelp();
    }
  for (OptionSpec& o : scene.options)
    if (o.name == "--basis") o.help = names + (studies.empty() ? "" : ": " + studies);
  return {"prt report [scene options] --out DIR [--quick] [--stability]",
          "Error against run time: sweeps sampler (uniform, stratified, fibonacci) x directions per vertex (16 .. "
          "16384, doubling) x lmax (1..8, or 1..--max-lmax) x transport mode (unshadowed closed form, shadowed, interreflection), "
          "scoring each against the converged transport (sampling error) and against prt reference's ground truth "
          "(total error) and its picture (PSNR); then light projection against cubemap resolution. Writes "
          "DIR/report.csv, DIR/report.md and DIR/error_vs_time.png. Without --mesh the scene is a small knot on a "
          "plane (about 2,700 vertices). The sweep sets lmax, samples, sampler and transport itself, and times "
          "every configuration together in round robin (median and range of at least 5 samples; report.md says at "
          "its top when a busy machine made the times untrustworthy). With --material "
          "phong:N,KS (e.g. --quick --material phong:100,0.3; without --mesh or --albedo the report scene's albedo "
          "is fitted under the coat) a glossy section follows: Phong lobes of N = 10, 100, 1000 and N, with KS, unshadowed and "
          "shadowed: the fixed-camera vector path's error against lmax and its precompute time, the lmax each N "
          "needs beside sqrt(N), and the transfer matrices against the vector path (DIR/glossy_error_vs_lmax.png "
          "too)." + described,
          {scene, report}};
}

int RunReport(const std::vector<std::string>& tokens) {
  Args args("report", tokens, ReportSpec());
  if (args.Has("--stability"))
    args.RejectOutside(kStabilityOptions, "not used by report --stability, whose cases are fixed (it takes --out, "
                                          "--replace, --quiet and --threads)");
  const SceneOptions scene = ReadSceneOptions(args);
  const auto out = args.String("--out");
  const bool quick = args.Flag("--quick");
  const bool stability = args.Flag("--stability");
  const bool replace = args.Flag("--replace");
  const int max_samples = args.Int("--max-samples", quick ? 256 : 16384, 16, 1 << 20);
  const int max_lmax = args.Int("--max-lmax", quick ? 4 : 8, 1, 32);
  args.Finish();
  if (!out) args.Fail("--out DIR is required");
  OutputPlan plan{"report", {"report.md"}, replace};
  if (stability) plan.names.push_back("stability.csv");
  else plan.names.insert(plan.names.end(), {"report.csv", "error_vs_time.png"});
  if (!stability && scene.material.glossy) plan.names.push_back("glossy_error_vs_lmax.png");
  const BasisStudy* study = stability ? nullptr : scene.basis->Study();
  if (study) plan.names.push_back("basis_error.png");
  OutputFolder folder(*out, plan);

  if (stability) {
    const std::vector<StabilityCase> cases = RunStabilityCases();
    int failed = 0;
    for (const auto& c : cases) {
      Summary(std::string(c.pass ? "pass " : "FAIL ") + c.name + ": " + Fmt(c.figure) +
              (c.note.empty() ? "" : " (" + c.note + ")"));
      failed += !c.pass;
    }
    WriteFileAtomic(folder.Output("stability.csv"), StabilityCsv(cases));
    WriteFileAtomic(folder.Output("report.md"), StabilityMarkdown(cases));
    Summary("stability: " + std::to_string(cases.size() - failed) + " of " + std::to_string(cases.size()) +
            " cases pass; wrote " + *out + "/stability.csv and report.md");
    FinishOutputs(folder);
    return failed ? 1 : 0;
  }

  const auto env = LoadSceneEnvironment(scene, &folder);
  Mesh mesh;
  std::string scene_name;
  if (scene.mesh.empty()) {
    mesh = MakeReportScene();
    // Our own scene takes the coat: its albedo is fitted rather than the run refused (--albedo,
    // checked against KS when read, replaces it).
    std::string fit_note;
    if (!scene.albedo && scene.material.glossy) {
      const std::string fitted = FitReportSceneToCoat(mesh, scene.material.ks, fit_note);
      if (!fitted.empty()) Summary(fitted);
    }
    ApplySceneEdits(mesh, scene);
    scene_name = "report scene (torus knot 128x16 on a 24x24 plane" + fit_note + ")";
  } else {
    mesh = LoadSceneMesh(scene, &folder);
    scene_name = scene.mesh;
  }
  ReportConfig config;
  config.seed = scene.seed;
  config.bounces = scene.bounces;
  config.max_samples = max_samples;
  if (quick) {
    config.modes = {TransportMode::kShadowed};
    config.converged_samples = 4096;
    config.reference_samples = 2048;
    config.face_sizes = {8, 16, 32, 64};
  }
  config.max_lmax = max_lmax;
  // The converged transport must stay well beyond the sweep's largest run to stand for the limit.
  config.converged_samples = std::max(config.converged_samples, 4 * max_samples);
  const RenderOptions picture = ReportRenderOptions(config.image_width, config.image_height);
  ReportData data = RunReportSweep(mesh, *env, scene.env, config, picture);
  data.scene = scene_name;
  if (scene.material.glossy) {
    // The glossy study sees the scene from the camera of the report's pictures.
    const glm::dvec3 eye(ChooseCamera(mesh, picture).eye);
    data.glossy = RunGlossyStudy(mesh, *env, eye,
                                 MakeGlossyConfig(quick, scene.material.lobe.exponent, scene.material.ks, scene.seed));
  }
  if (study) {
    // The basis's own study, on its own scene unless --mesh is given (basis/study.h).
    Mesh own_scene;
    if (scene.mesh.empty()) {
      own_scene = study->OwnScene(quick);
      ApplySceneEdits(own_scene, scene);
    }
    data.basis_study = study->Run({scene.mesh.empty() ? own_scene : mesh,
                                   scene.mesh.empty() ? study->OwnSceneName(quick) : scene.mesh, *env, scene.env,
                                   quick, scene.bounces, scene.seed});
  }
  // Visible noise: frame 0 as `render` draws it, per way of spending directions (report_noise.h).
  NoiseConfig noise;
  noise.seed = scene.seed;
  noise.bounces = scene.bounces;
  if (quick) {
    noise.mode = TransportMode::kShadowed;
    noise.converged_samples = 32768;
    noise.repeats = 1;
  }
  RenderOptions frame;
  frame.frames = 1;
  data.noise = RunNoiseStudy(mesh, *env, noise, frame);
  WriteReport(folder, data);
  FinishOutputs(folder);
  return 0;
}

}  // namespace prt
