// Fuzzes the option parser: the input is split at newlines into command-line tokens and read
// as `prt render` reads them (Args with render's table, scene and render options, Finish). Any tokens give
// options or a UsageError/Error.
#include <sstream>
#include <string>
#include <vector>

#include "options/args.h"
#include "app/commands.h"
#include "app/render_args.h"
#include "app/scene_options.h"
#include "core/error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<std::string> tokens;
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  for (std::string token; std::getline(in, token);) tokens.push_back(token);
  try {
    prt::Args args("render", tokens, prt::RenderSpec());
    const prt::SceneOptions scene = prt::ReadSceneOptions(args);
    const prt::RenderOptions render =
        prt::CompleteRenderOptions(args, prt::ReadRenderOptions(args, prt::RenderOptions{}), scene);
    args.Finish();
    if (scene.lmax < 0 || render.frames < 1 || render.width < 1 || render.height < 1) __builtin_trap();
  } catch (const prt::Error&) {
  }
  return 0;
}
