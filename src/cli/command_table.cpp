#include "cli/command_table.h"

#include "app/commands.h"
#include "bench/cmd_bench.h"

namespace prt {

const std::vector<Command>& Commands() {
  static const std::vector<Command> commands = {
      {"demo", "the main job on the embedded default scene", DemoSpec, RunDemo},
      {"render", "precompute (or reuse the cache), then write rotating-light frames", RenderSpec, RunRender},
      {"precompute", "write light.txt and transport.txt in the course's format", PrecomputeSpec, RunPrecompute},
      {"farm", "run a command as a Slurm job of shards and a merge", FarmSpec, RunFarm},
      {"merge", "assemble a farm job's shards into what one precompute writes", MergeSpec, RunMerge},
      {"video", "assemble the frames a render wrote (or its --frame-range tasks) into one video", VideoCommandSpec,
       RunVideo},
      {"light", "print an environment's SH coefficients", LightSpec, RunLight},
      {"view", "serve a page that relights the scene live in a browser", ViewSpec, RunView},
      {"reference", "ground truth without SH truncation", ReferenceSpec, RunReference},
      {"report", "error against run time, and the stiff and extreme cases", ReportSpec, RunReport},
      {"diff", "compare two images", DiffSpec, RunDiff},
      {"bench", "performance measurements", BenchSpec, RunBench},
      {"basis", "draw the real SH basis functions as a grid of spheres", BasisSpec, RunBasis},
      {"sample-files", "write a sample mesh, HDR sky and cubemap to try the commands on", SampleFilesSpec,
       RunSampleFiles},
      {"help", "show help for a command", HelpSpec, RunHelp},
  };
  return commands;
}

const Command* FindCommand(const std::string& name) {
  for (const auto& c : Commands())
    if (name == c.name) return &c;
  return nullptr;
}

std::vector<std::string> CommandNames() {
  std::vector<std::string> names;
  for (const auto& c : Commands()) names.push_back(c.name);
  return names;
}

std::string UnknownCommandMessage(const std::string& name) {
  std::vector<std::string> names = CommandNames();
  names.insert(names.end(), {"--version", "--help"});
  const std::string near = NearestName(name, names);
  return "'" + name + "': unknown command (" +
         (near.empty() ? std::string("expected one that prt help lists") : "did you mean " + near + "?") + ")";
}

bool WantsHelp(const std::vector<std::string>& tokens) {
  for (const auto& t : tokens)
    if (t == "--help" || t == "-h") return true;
  return false;
}

}  // namespace prt
