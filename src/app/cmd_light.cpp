#include <cstdio>

#include "app/commands.h"
#include "app/pipeline.h"
#include "io/light_txt.h"

namespace prt {

CommandSpec LightSpec() {
  return {"prt light [--env ENV] [--lmax L] [options]",
          "Prints the environment's SH coefficients to stdout: (L+1)^2 lines `R G B` (the course's light.txt "
          "format, 9 significant digits), nothing else. The run summary goes to stderr.",
          {SceneOptionGroup(SceneOptions{}, LightOptionNames(), "light options"), {"other options", {QuietOption()}}}};
}

int RunLight(const std::vector<std::string>& tokens) {
  Args args("light", tokens, LightSpec());
  const SceneOptions options = ReadSceneOptions(args);
  args.Finish();
  const auto env = LoadSceneEnvironment(options);
  const ShRgb light = ComputeLight(*env, options);
  std::fputs(FormatLightTxt(light).c_str(), stdout);
  return std::fflush(stdout) == 0 ? 0 : 1;
}

}  // namespace prt
