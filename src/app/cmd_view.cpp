// `prt view`: the scene relit live in a browser, by prt's own renderer (app/view_scene.h behind
// view/view_server.h).
#include <cstdio>
#include <set>
#include <thread>

#include "app/commands.h"
#include "app/render_args.h"
#include "app/scene_options.h"
#include "app/view_scene.h"
#include "core/log.h"
#include "view/late_backend.h"
#include "view/request_guard.h"
#include "view/view_server.h"

namespace prt {
namespace {

/// The render options view takes: what the first frame shows (the page changes them after).
const std::vector<std::string> kViewRenderOptions = {"--size",  "--axis", "--start-angle", "--background",
                                                     "--tonemap", "--exposure", "--ssaa", "--view", "--eye",
                                                     "--target", "--up",  "--fov", "--cache"};
/// Options the page sets itself, or view's own: not repeated as typed in the render command line.
const std::set<std::string> kNotRepeated = {"--lmax", "--transport", "--basis", "--env", "--samples",
                                            "--hidden-samples", "--size", "--axis", "--start-angle", "--tonemap",
                                            "--exposure", "--ssaa", "--view", "--eye", "--target", "--up", "--fov",
                                            "--cache", "--port", "--bind", "--quiet", "--threads", "--light-terms",
                                            "--reference-samples"};

SceneOptions ViewSceneDefaults() {
  SceneOptions s;
  s.window = kDefaultWindow;
  s.lmax = 4;
  return s;
}

/// The options of `tokens` that the render command line repeats as typed (see kNotRepeated).
std::vector<std::string> KeptTokens(const std::vector<std::string>& tokens, const CommandSpec& spec) {
  std::vector<std::string> kept;
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    const std::string& t = tokens[i];
    if (t.rfind("--", 0) != 0) continue;  // a positional: an extra environment
    const std::string name = t.substr(0, t.find('='));
    const OptionSpec* option = spec.Find(name);
    const bool separate_value = option && !option->value.empty() && t.find('=') == std::string::npos;
    if (!kNotRepeated.count(name)) {
      kept.push_back(t);
      if (separate_value && i + 1 < tokens.size()) kept.push_back(tokens[i + 1]);
    }
    i += separate_value;
  }
  return kept;
}

/// The summary's line on whom the server serves.
std::string ServingLine(const ViewServer& server, const std::string& bind) {
  const std::string line = "view: serving " + server.Address();
  if (IsLoopback(bind)) return line + " to this machine only (--bind ADDRESS serves others)";
  std::string also;
  if (IsWildcard(bind))
    for (const std::string& host : server.Hosts()) also += (also.empty() ? "" : ", ") + host;
  return line + " on " + bind + " (--bind)" + (also.empty() ? "" : ", as " + also) +
         ": any machine that reaches it may open the page";
}

}  // namespace

CommandSpec ViewSpec() {
  RenderJobOptions job;
  job.cache = "none";
  return {"prt view [scene options] [render options] [--port N] [--bind ADDRESS] [ENV ...]",
          "Serves a page at once, showing the progress while the scene's transport is computed (or read from "
          "--cache), on which the scene is then relit live by prt's own renderer, frames pushed as they are drawn "
          "(while the light or camera moves at an interactive quality, then the frame prt render draws): drag to turn the light about any axis (the environment behind turns with it), "
          "right-drag or shift-drag to orbit the camera, the wheel to zoom; switch lmax (up to --lmax: SH bands "
          "nest), the transport mode and basis (each computed on first use, then kept), the view, exposure and tone "
          "curve, and the environment among --env and the ENV arguments after the options. The page shows the frame "
          "time and rate, saves the frame as PNG and gives the `prt render` command line that draws the same frame.\n\n"
          "The address is printed alone on a line of stdout: http://127.0.0.1:PORT/. It serves until SIGINT (Ctrl-C) "
          "or SIGTERM, and only to this machine unless --bind names another address. Requests whose Host is not the "
          "address served, or that come from another site, are refused.",
          {SceneOptionGroup(ViewSceneDefaults(), AllSceneOptionNames()),
           RenderOptionGroup(job, kViewRenderOptions, "render options (the first frame; the page changes them)"),
           {"view options",
            {{"--port", "N", "the port to listen on, 0..65535; 0 takes any free one", "8202"},
             {"--bind", "ADDRESS", "the address to listen on: 127.0.0.1 serves this machine only; 0.0.0.0 every "
              "network this machine is on (anyone who can reach it may use the page)", "127.0.0.1"},
             {"--reference-samples", "N", "directions a vertex of the reference the page measures when asked (its "
              "error figures: each setting against prt reference), 2..1048576", "1024"},
             QuietOption()}}}};
}

int RunView(const std::vector<std::string>& tokens) {
  const CommandSpec spec = ViewSpec();
  Args args("view", tokens, spec);
  const SceneOptions scene = ReadSceneOptions(args, ViewSceneDefaults());
  RenderJobOptions defaults;
  defaults.cache = "none";
  const RenderJobOptions job = CompleteRenderOptions(args, ReadRenderOptions(args, defaults), scene);
  const int port = args.Int("--port", 8202, 0, 65535);
  const std::string bind = args.String("--bind", "127.0.0.1");
  const int reference_samples = args.Int("--reference-samples", 1024, 2, 1 << 20);
  ViewSetup setup{scene, job.draw, {scene.env}, job.cache, reference_samples, KeptTokens(tokens, spec)};
  // Each is loaded (and so checked) with --env's, before any transport is computed.
  for (const std::string& env : args.TakePositionals()) setup.envs.push_back(env);
  args.Finish();

  // The mesh and environments loaded (and so checked), then the port taken and the page served
  // at once, showing the first transport's progress until it is ready (view/late_backend.h).
  ViewScene view(setup);
  LateBackend backend;
  ViewServer server(backend, bind, port);
  Summary(ServingLine(server, bind));
  std::printf("%s\n", server.Address().c_str());
  std::fflush(stdout);
  std::thread serving([&server] { server.Serve(); });
  try {
    view.ComputeFirst();
  } catch (...) {
    server.Stop();
    serving.join();
    throw;
  }
  backend.Ready(view);
  serving.join();  // until SIGINT or SIGTERM ends the run
  return 0;
}

}  // namespace prt
