#include <string>

#include "app/commands.h"
#include "app/pipeline.h"

namespace prt {

const char* const kRenderHelp =
    "usage: prt render [scene options] [render options] [--cache PATH]\n"
    "  Precomputes the transport (or reuses the cache), then writes DIR/frame_0000.png ... of\n"
    "  the mesh under the environment light turning about the axis.\n"
    "  --cache PATH       transport cache to reuse and update (default DIR/transport.cache;\n"
    "                     `none` disables it)\n";

int RunRender(const std::vector<std::string>& tokens) {
  Args args("render", tokens, SceneFlags());
  const SceneOptions scene = ReadSceneOptions(args);
  const RenderOptions render = ReadRenderOptions(args, RenderOptions{});
  std::string cache = args.String("--cache", render.out + "/transport.cache");
  args.Finish();
  if (cache == "none") cache.clear();
  RenderJob(scene, render, cache);
  return 0;
}

}  // namespace prt
