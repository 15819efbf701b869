#include "app/commands.h"
#include "app/pipeline.h"

namespace prt {
namespace {

/// Render's scene defaults: SceneOptions', with the window chosen where the frames would ring.
SceneOptions RenderScene() {
  SceneOptions s;
  s.window = kDefaultWindow;
  return s;
}

}  // namespace

CommandSpec RenderSpec() {
  return {"prt render [scene options] [render options]",
          "Precomputes the transport (or reuses the cache), then writes DIR/frame_0000.png ... of the mesh under "
          "the environment light turning about the axis. Without --mesh, the embedded demo scene is seen with the "
          "demo's camera.\n\nThe run summary on stderr says what each stage did and left out, the camera in "
          "option syntax and the exposure chosen, so a run can be repeated exactly.",
          {SceneOptionGroup(RenderScene(), AllSceneOptionNames()),
           RenderOptionGroup(RenderOptions{}, AllRenderOptionNames()),
           {"other options", {QuietOption()}}}};
}

int RunRender(const std::vector<std::string>& tokens) {
  Args args("render", tokens, RenderSpec());
  const SceneOptions scene = ReadSceneOptions(args, RenderScene());
  const RenderOptions render = CompleteRenderOptions(args, ReadRenderOptions(args, RenderOptions{}), scene);
  args.Finish();
  RenderJob(scene, render);
  return 0;
}

}  // namespace prt
