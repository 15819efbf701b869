#include "app/commands.h"
#include "app/pipeline.h"

namespace prt {
namespace {

SceneOptions DemoScene() {
  SceneOptions s;
  s.transport = "interreflection";
  s.bounces = 1;
  s.lmax = 4;  // samples: the sample rule's default for lmax 4, 1024
  s.window = kDefaultWindow;
  return s;
}

/// The demo's render defaults; the demo camera itself comes from CompleteRenderOptions, only
/// for the embedded scene (a --mesh of the user's is framed automatically).
RenderJobOptions DemoRender() {
  RenderJobOptions r;
  r.out = "out/demo";
  return r;
}

/// The same with the demo camera, as its help documents the defaults.
RenderJobOptions DemoRenderWithCamera() {
  RenderJobOptions r = DemoRender();
  r.draw = WithDemoCamera(r.draw);
  return r;
}

}  // namespace

CommandSpec DemoSpec() {
  return {"prt demo [scene options] [render options]",
          "The main job on the embedded default scene, no files needed: a torus knot on a ground plane under the "
          "built-in HDR sky with a sun, interreflection with 1 bounce, lmax 4, a full turn of the light in 120 "
          "frames of 640x480 written to out/demo. Every option of prt render may override a default; the defaults "
          "below are the demo's.",
          {SceneOptionGroup(DemoScene(), AllSceneOptionNames()), RenderOptionGroup(DemoRenderWithCamera(), AllRenderOptionNames()),
           {"other options", {QuietOption()}}}};
}

int RunDemo(const std::vector<std::string>& tokens) {
  Args args("demo", tokens, DemoSpec());
  const SceneOptions scene = ReadSceneOptions(args, DemoScene());
  const RenderJobOptions render = CompleteRenderOptions(args, ReadRenderOptions(args, DemoRender()), scene);
  args.Finish();
  RenderJob(scene, render);
  return 0;
}

}  // namespace prt
