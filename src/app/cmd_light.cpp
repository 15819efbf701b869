#include <cstdio>

#include "app/commands.h"
#include "app/pipeline.h"
#include "io/light_txt.h"

namespace prt {

const char* const kLightHelp =
    "usage: prt light [--env ENV] [--lmax L] [--window W] [--games202-faces]\n"
    "  Prints the environment's SH coefficients to stdout: (L+1)^2 lines `R G B` (the course's\n"
    "  light.txt format, 9 significant digits), nothing else. The run summary goes to stderr.\n"
    "  --env ENV          cubemap folder, equirectangular .hdr/.exr/.png/.jpg, or furnace[:C],\n"
    "                     sky[:sun=3,elevation=40,azimuth=35,radius=2] (default sky)\n"
    "  --lmax L           highest band, 0..64 (default 2: 9 coefficients)\n"
    "  --window W         none | hann | lanczos | auto (default none)\n"
    "  --games202-faces   the course's cubemap face mapping and pow(x, 2.2) decoding\n"
    "  --threads N        worker threads (default: all cores)\n"
    "  --quiet            nothing on stderr but errors\n";

int RunLight(const std::vector<std::string>& tokens) {
  Args args("light", tokens, SceneFlags());
  SceneOptions defaults;
  const SceneOptions options = ReadSceneOptions(args, defaults);
  args.Finish();
  const auto env = LoadSceneEnvironment(options);
  const ShRgb light = ComputeLight(*env, options);
  std::fputs(FormatLightTxt(light).c_str(), stdout);
  return std::fflush(stdout) == 0 ? 0 : 1;
}

}  // namespace prt
