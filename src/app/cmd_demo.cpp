#include <cstdio>

#include "app/commands.h"
#include "app/pipeline.h"
#include "io/light_txt.h"

namespace prt {

const char* const kDemoHelp =
    "usage: prt demo [--out DIR] [--quiet]\n"
    "  The main job on the embedded default scene (no external files): the built-in HDR sky.\n"
    "  This build projects the default environment and prints its SH coefficients (light.txt\n"
    "  format) to stdout; rendering of the rotating-light frames arrives with the rasterizer.\n"
    "  --out DIR   output folder for frames (default out/demo)\n"
    "  --quiet     nothing on stderr but errors\n";

int RunDemo(const std::vector<std::string>& tokens) {
  Args args("demo", tokens, SceneFlags());
  SceneOptions defaults;
  defaults.lmax = 4;
  args.String("--out", "out/demo");
  const SceneOptions options = ReadSceneOptions(args, defaults);
  args.Finish();
  const auto env = LoadSceneEnvironment(options);
  const ShRgb light = ComputeLight(*env, options);
  std::fputs(FormatLightTxt(light).c_str(), stdout);
  return 0;
}

}  // namespace prt
