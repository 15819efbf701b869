#pragma once
/// \file
/// The commands of `prt` (the contract is ../shared/CLI.md). Each command lives in its own
/// `cmd_<name>.cpp`, reads its options through Args and returns the process exit code.

#include <string>
#include <vector>

#include "app/args.h"

namespace prt {

struct Command {
  const char* name;
  const char* summary;  ///< one line for `prt help`
  const char* help;     ///< every option with its default, for `prt help NAME`
  int (*run)(const std::vector<std::string>& tokens);
};

/// All commands, in the order `prt help` lists them.
const std::vector<Command>& Commands();
/// The command called `name`, or nullptr.
const Command* FindCommand(const std::string& name);

int RunDemo(const std::vector<std::string>& tokens);
int RunRender(const std::vector<std::string>& tokens);
int RunPrecompute(const std::vector<std::string>& tokens);
int RunLight(const std::vector<std::string>& tokens);
int RunReference(const std::vector<std::string>& tokens);
int RunReport(const std::vector<std::string>& tokens);
int RunDiff(const std::vector<std::string>& tokens);
int RunBench(const std::vector<std::string>& tokens);
int RunBasis(const std::vector<std::string>& tokens);
int RunHelp(const std::vector<std::string>& tokens);

extern const char* const kDemoHelp;
extern const char* const kRenderHelp;
extern const char* const kPrecomputeHelp;
extern const char* const kLightHelp;
extern const char* const kReferenceHelp;
extern const char* const kReportHelp;
extern const char* const kDiffHelp;
extern const char* const kBenchHelp;
extern const char* const kBasisHelp;
extern const char* const kHelpHelp;

}  // namespace prt
