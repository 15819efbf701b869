#include "app/commands.h"
#include "app/pipeline.h"

namespace prt {

const char* const kDemoHelp =
    "usage: prt demo [--out DIR] [scene and render options]\n"
    "  The main job on the embedded default scene, no files needed: a torus knot on a ground\n"
    "  plane under the built-in HDR sky with a sun, interreflection with 1 bounce, lmax 4, a\n"
    "  full turn of the light in 120 frames of 640x480 written to DIR (default out/demo).\n"
    "  Every option of `prt render` may override a default.\n";

int RunDemo(const std::vector<std::string>& tokens) {
  Args args("demo", tokens, SceneFlags());
  SceneOptions scene_defaults;
  scene_defaults.transport = "interreflection";
  scene_defaults.bounces = 1;
  scene_defaults.lmax = 4;
  scene_defaults.samples = 512;
  RenderOptions render_defaults;
  render_defaults.out = "out/demo";
  const SceneOptions scene = ReadSceneOptions(args, scene_defaults);
  const RenderOptions render = ReadRenderOptions(args, render_defaults);
  args.Finish();
  RenderJob(scene, render, render.out + "/transport.cache");
  return 0;
}

}  // namespace prt
