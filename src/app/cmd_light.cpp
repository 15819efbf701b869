#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>

#include "app/commands.h"
#include "app/pipeline.h"
#include "core/constants.h"
#include "core/log.h"
#include "core/text.h"
#include "precompute_io/light_txt.h"
#include "sh/dering.h"
#include "sh/rotation.h"

namespace prt {
namespace {

struct Turn {
  glm::dvec3 axis;
  double degrees;
};

/// "X,Y,Z:DEGREES" -> axis and angle; any other text, a zero axis or a number that is not
/// finite is a usage error.
Turn ReadTurn(Args& args, const std::string& text) {
  const std::string expected = " (expected X,Y,Z:DEGREES, an axis and a right-handed angle, such as 0,0,1:90)";
  const auto colon = text.find(':');
  if (colon == std::string::npos) args.Fail("--rotate: '" + text + "' has no ':DEGREES'" + expected);
  const auto axis = ParseVec3(text.substr(0, colon));
  if (!axis) args.Fail("--rotate: '" + text + "': the axis is not three numbers" + expected);
  const auto degrees = ParseNumber(text.substr(colon + 1));
  if (!degrees) args.Fail("--rotate: '" + text + "': the angle is not a number" + expected);
  if (!(glm::length(*axis) > 1e-300) || !std::isfinite(glm::length(*axis)))
    args.Fail("--rotate: '" + text + "': the axis is zero" + expected);
  return {*axis, *degrees};
}

/// `light` stores no per-vertex transport: it goes as far as the basis and rotation are exact.
SceneOptions LightDefaults() {
  SceneOptions d;
  d.max_lmax = kMaxBasisLmax;
  return d;
}

}  // namespace

CommandSpec LightSpec() {
  return {"prt light [--env ENV] [--lmax L] [--rotate X,Y,Z:DEGREES] [options]",
          "Prints the environment's SH coefficients to stdout: (L+1)^2 lines `R G B` (the course's light.txt "
          "format, 9 significant digits), nothing else. The run summary goes to stderr.",
          {SceneOptionGroup(LightDefaults(), LightOptionNames(), "light options"),
           {"other options",
            {{"--rotate", "X,Y,Z:DEGREES",
              "print the light turned by DEGREES, right-handed, about the axis X,Y,Z: light that came from "
              "direction d comes from R d afterwards (exact to lmax " +
                  std::to_string(kMaxBasisLmax) + ")",
              "not turned"},
             QuietOption()}}}};
}

int RunLight(const std::vector<std::string>& tokens) {
  Args args("light", tokens, LightSpec());
  const SceneOptions options = ReadSceneOptions(args, LightDefaults());
  std::optional<Turn> turn;
  if (const auto text = args.String("--rotate")) turn = ReadTurn(args, *text);
  if (options.window == "auto" && options.lmax > kMaxAutoWindowLmax)
    args.Fail(Formatted("--window auto: works to lmax %d, not %d (use hann or lanczos, or a lower --lmax)",
                        kMaxAutoWindowLmax, options.lmax));
  args.Finish();
  const auto env = LoadSceneEnvironment(options);
  ShRgb light = ComputeLight(*env, options);
  if (turn) {
    const glm::dvec3 axis = glm::normalize(turn->axis);
    light = ShRotation(AxisAngle(axis, turn->degrees * kPi / 180.0), options.lmax).Apply(light);
    Summary(Formatted("rotate: %g degrees about (%g, %g, %g), band matrices from Wigner's d (sh/rotation.h)",
                      turn->degrees, axis.x, axis.y, axis.z));
  }
  std::fputs(FormatLightTxt(light).c_str(), stdout);
  return std::fflush(stdout) == 0 ? 0 : 1;
}

}  // namespace prt
