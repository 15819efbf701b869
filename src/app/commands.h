#pragma once
/// \file
/// The commands of `prt` that app/ runs (docs/CLI.md). Each command lives in its own
/// `cmd_<name>.cpp`: its option table (CommandSpec, which both the parser and `prt help` use)
/// and its run function, which reads its options through Args and returns the process exit
/// code. The table of every command (bench's and help's among them) is cli/command_table.h.

#include <string>
#include <vector>

#include "options/args.h"
#include "options/option_table.h"

namespace prt {

int RunDemo(const std::vector<std::string>& tokens);
int RunRender(const std::vector<std::string>& tokens);
int RunPrecompute(const std::vector<std::string>& tokens);
int RunLight(const std::vector<std::string>& tokens);
int RunView(const std::vector<std::string>& tokens);
int RunReference(const std::vector<std::string>& tokens);
int RunReport(const std::vector<std::string>& tokens);
int RunDiff(const std::vector<std::string>& tokens);
int RunBasis(const std::vector<std::string>& tokens);
int RunSampleFiles(const std::vector<std::string>& tokens);
int RunMerge(const std::vector<std::string>& tokens);
int RunFarm(const std::vector<std::string>& tokens);
int RunVideo(const std::vector<std::string>& tokens);

CommandSpec DemoSpec();
CommandSpec RenderSpec();
CommandSpec PrecomputeSpec();
CommandSpec LightSpec();
CommandSpec ViewSpec();
CommandSpec ReferenceSpec();
CommandSpec ReportSpec();
CommandSpec DiffSpec();
CommandSpec BasisSpec();
CommandSpec SampleFilesSpec();
CommandSpec MergeSpec();
CommandSpec FarmSpec();
CommandSpec VideoCommandSpec();

}  // namespace prt
