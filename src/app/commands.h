#pragma once
/// \file
/// The commands of `prt` (docs/CLI.md). Each command lives in its own `cmd_<name>.cpp`: its
/// option table (CommandSpec, which both the parser and `prt help` use) and its run function,
/// which reads its options through Args and returns the process exit code.

#include <string>
#include <vector>

#include "app/args.h"
#include "app/option_table.h"

namespace prt {

struct Command {
  const char* name;
  const char* summary;       ///< one line for `prt help`
  CommandSpec (*spec)();     ///< every option with its default: the parser's table and the help
  int (*run)(const std::vector<std::string>& tokens);
};

/// All commands, in the order `prt help` lists them.
const std::vector<Command>& Commands();
/// The command called `name`, or nullptr.
const Command* FindCommand(const std::string& name);
/// Every command name, in help order.
std::vector<std::string> CommandNames();

int RunDemo(const std::vector<std::string>& tokens);
int RunRender(const std::vector<std::string>& tokens);
int RunPrecompute(const std::vector<std::string>& tokens);
int RunLight(const std::vector<std::string>& tokens);
int RunView(const std::vector<std::string>& tokens);
int RunReference(const std::vector<std::string>& tokens);
int RunReport(const std::vector<std::string>& tokens);
int RunDiff(const std::vector<std::string>& tokens);
int RunBench(const std::vector<std::string>& tokens);
int RunBasis(const std::vector<std::string>& tokens);
int RunSampleFiles(const std::vector<std::string>& tokens);
int RunHelp(const std::vector<std::string>& tokens);

CommandSpec DemoSpec();
CommandSpec RenderSpec();
CommandSpec PrecomputeSpec();
CommandSpec LightSpec();
CommandSpec ViewSpec();
CommandSpec ReferenceSpec();
CommandSpec ReportSpec();
CommandSpec DiffSpec();
CommandSpec BenchSpec();
CommandSpec BasisSpec();
CommandSpec SampleFilesSpec();
CommandSpec HelpSpec();

/// "'<name>': unknown command (did you mean render?)" for a name no command has.
std::string UnknownCommandMessage(const std::string& name);

/// True when `tokens` ask for the command's help (`--help` or `-h`).
bool WantsHelp(const std::vector<std::string>& tokens);

}  // namespace prt
