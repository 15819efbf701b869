#include <cstdio>

#include "cli/command_table.h"
#include "options/args.h"

namespace prt {

CommandSpec HelpSpec() {
  return {"prt help [COMMAND]",
          "Lists the commands, or documents every option of COMMAND with its default (the same as prt "
          "COMMAND --help).",
          {}};
}

int RunHelp(const std::vector<std::string>& tokens) {
  Args args("help", tokens, HelpSpec());
  const auto positionals = args.TakePositionals();
  args.Finish();
  if (positionals.size() > 1) args.Fail("expected at most one command name");
  if (positionals.empty()) {
    std::printf("prt %s: precomputed radiance transfer on the CPU\n\nusage: prt COMMAND [options]\n\n",
                PRT_VERSION);
    for (const auto& c : Commands()) std::printf("  %-13s %s\n", c.name, c.summary);
    std::printf("\n  prt --version   print the version\n"
                "Run 'prt help COMMAND' or 'prt COMMAND --help' for every option of one command.\n"
                "The full reference is docs/CLI.md.\n");
    return 0;
  }
  const Command* c = FindCommand(positionals[0]);
  if (!c) args.Fail(UnknownCommandMessage(positionals[0]));
  std::printf("%s", FormatHelp(c->spec()).c_str());
  return 0;
}

}  // namespace prt
