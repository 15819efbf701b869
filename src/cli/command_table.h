#pragma once
/// \file
/// The table of prt's commands: app/'s (app/commands.h), bench's (bench/cmd_bench.h) and help,
/// in the order `prt help` lists them. cli/ is the top floor: main.cpp and the help read the
/// table, and nothing below names it.

#include <string>
#include <vector>

#include "options/option_table.h"

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

int RunHelp(const std::vector<std::string>& tokens);
CommandSpec HelpSpec();

/// "'<name>': unknown command (did you mean render?)" for a name no command has.
std::string UnknownCommandMessage(const std::string& name);

/// True when `tokens` ask for the command's help (`--help` or `-h`).
bool WantsHelp(const std::vector<std::string>& tokens);

}  // namespace prt
