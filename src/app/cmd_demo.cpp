#include "app/commands.h"
#include "app/pipeline.h"

namespace prt {

const char* const kDemoHelp =
    "usage: prt demo [--out DIR] [scene and render options]\n"
    "  The main job on the embedded default scene, no files needed: a torus knot on a ground\n"
    "  plane under the built-in HDR sky with a sun, interreflection with 1 bounce, lmax 4, a\n"
    "  full turn of the light in 120 frames of 640x480 written to DIR (default out/demo), seen\n"
    "  with --eye 6,3.2,9 --target 0,1.5,0 --fov 36 --tonemap aces --exposure -0.5.\n"
    "  Every option of `prt render` may override a default.\n";

int RunDemo(const std::vector<std::string>& tokens) {
  Args args("demo", tokens, SceneFlags());
  SceneOptions scene_defaults;
  scene_defaults.transport = "interreflection";
  scene_defaults.bounces = 1;
  scene_defaults.lmax = 4;
  scene_defaults.samples = 1024;
  RenderOptions render_defaults;
  render_defaults.out = "out/demo";
  // A three-quarter view of the knot with the horizon in frame, and a filmic tone curve for
  // the HDR sun.
  render_defaults.eye = glm::dvec3(6.0, 3.2, 9.0);
  render_defaults.target = glm::dvec3(0.0, 1.5, 0.0);
  render_defaults.fov = 36.0;
  render_defaults.tonemap = ToneCurve::kAces;
  render_defaults.exposure = -0.5;
  const SceneOptions scene = ReadSceneOptions(args, scene_defaults);
  const RenderOptions render = ReadRenderOptions(args, render_defaults);
  args.Finish();
  RenderJob(scene, render, render.out + "/transport.cache");
  return 0;
}

}  // namespace prt
