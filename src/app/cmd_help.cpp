#include <cstdio>

#include "app/commands.h"
#include "core/error.h"

namespace prt {

const char* const kHelpHelp =
    "usage: prt help [COMMAND]\n"
    "  Lists the commands, or documents every option of COMMAND with its default.\n";

int RunHelp(const std::vector<std::string>& tokens) {
  Args args("help", tokens);
  const auto positionals = args.TakePositionals();
  args.Finish();
  if (positionals.size() > 1) throw UsageError("expected at most one command name", "help");
  if (positionals.empty()) {
    std::printf("prt %s: precomputed radiance transfer on the CPU\n\nusage: prt COMMAND [options]\n\n",
                PRT_VERSION);
    for (const auto& c : Commands()) std::printf("  %-11s %s\n", c.name, c.summary);
    std::printf("\n  prt --version   print the version\n"
                "Run 'prt help COMMAND' for the options of one command.\n");
    return 0;
  }
  const Command* c = FindCommand(positionals[0]);
  if (!c) throw UsageError("'" + positionals[0] + "': unknown command", "help");
  std::printf("%s", c->help);
  return 0;
}

}  // namespace prt
