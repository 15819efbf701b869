#include "app/commands.h"

namespace prt {

const std::vector<Command>& Commands() {
  static const std::vector<Command> commands = {
      {"demo", "the main job on the embedded default scene", kDemoHelp, RunDemo},
      {"render", "precompute (or reuse the cache), then write rotating-light frames", kRenderHelp, RunRender},
      {"precompute", "write light.txt and transport.txt in the course's format", kPrecomputeHelp, RunPrecompute},
      {"light", "print an environment's SH coefficients", kLightHelp, RunLight},
      {"reference", "ground truth without SH truncation", kReferenceHelp, RunReference},
      {"report", "error against run time, and the stiff and extreme cases", kReportHelp, RunReport},
      {"diff", "compare two images", kDiffHelp, RunDiff},
      {"bench", "performance measurements", kBenchHelp, RunBench},
      {"basis", "draw the real SH basis functions as a grid of spheres", kBasisHelp, RunBasis},
      {"help", "show help for a command", kHelpHelp, RunHelp},
  };
  return commands;
}

const Command* FindCommand(const std::string& name) {
  for (const auto& c : Commands())
    if (name == c.name) return &c;
  return nullptr;
}

}  // namespace prt
