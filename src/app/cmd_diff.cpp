// Placeholder until the issue that builds `prt diff` lands: it fails cleanly instead of crashing.
#include "app/commands.h"
#include "core/error.h"

namespace prt {

const char* const kDiffHelp = "usage: prt diff ...\n  Not available in this build yet.\n";

int RunDiff(const std::vector<std::string>&) {
  throw Error("prt diff: not available in this build yet");
}

}  // namespace prt
