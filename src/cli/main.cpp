/// \file
/// Entry point: finds the command, prints its help for `--help` or `-h`, runs it, and turns
/// every error into one line on stderr and an exit code (0 success, 1 failure, 2 usage, 75 an
/// output folder in use by another run: try again). Nothing below app/ prints usage or exits.
/// First of all, SIGINT, SIGTERM and SIGHUP are handed to the cleanup of temporary files
/// (core/signal_cleanup.h).

#include <cstdio>
#include <exception>
#include <new>
#include <string>
#include <vector>

#include "cli/command_table.h"
#include "core/error.h"
#include "core/output_folder.h"  // FolderBusy
#include "core/signal_cleanup.h"
#include "core/simd.h"  // CheckCpuLevelRequest

int main(int argc, char** argv) {
  using namespace prt;
  InstallSignalCleanup();  // before any thread starts
  const std::vector<std::string> all(argv + 1, argv + argc);
  if (all.empty()) {
    std::fprintf(stderr, "prt: error: no command given (see prt help)\n");
    return 2;
  }
  if (all[0] == "--version" || all[0] == "version") {
    if (all.size() > 1) {
      std::fprintf(stderr, "prt: error: '%s': unexpected argument (prt --version takes none) (see prt help)\n",
                   all[1].c_str());
      return 2;
    }
    std::printf("prt %s\n", PRT_VERSION);
    return 0;
  }
  const std::string name = (all[0] == "--help" || all[0] == "-h") ? "help" : all[0];
  const Command* command = FindCommand(name);
  if (!command) {
    std::fprintf(stderr, "prt: error: %s (see prt help)\n", UnknownCommandMessage(name).c_str());
    return 2;
  }
  const std::vector<std::string> tokens(all.begin() + 1, all.end());
  if (name != "help" && WantsHelp(tokens)) {
    std::printf("%s", FormatHelp(command->spec()).c_str());
    return 0;
  }
  try {
    CheckCpuLevelRequest();  // PRT_CPU_LEVEL: refused before any work when unknown or unrunnable
    return command->run(tokens);
  } catch (const UsageError& e) {
    const std::string about = e.command().empty() ? name : e.command();
    std::fprintf(stderr, "prt: error: %s (see prt help%s)\n", e.what(), about == "help" ? "" : (" " + about).c_str());
    return 2;
  } catch (const FolderBusy& e) {
    std::fprintf(stderr, "prt: error: %s\n", e.what());
    return kExitFolderBusy;
  } catch (const Error& e) {
    std::fprintf(stderr, "prt: error: %s\n", e.what());
    return 1;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "prt: error: out of memory\n");
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "prt: error: internal error: %s\n", e.what());
    return 1;
  }
}
