#pragma once
/// \file
/// `prt bench WHAT`: the benchmarks' command (cmd_bench.cpp), listed by cli/command_table.cpp.

#include <string>
#include <vector>

#include "options/option_table.h"

namespace prt {

int RunBench(const std::vector<std::string>& tokens);
CommandSpec BenchSpec();

}  // namespace prt
