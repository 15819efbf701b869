// Placeholder until the issue that builds `prt precompute` lands: it fails cleanly instead of crashing.
#include "app/commands.h"
#include "core/error.h"

namespace prt {

const char* const kPrecomputeHelp = "usage: prt precompute ...\n  Not available in this build yet.\n";

int RunPrecompute(const std::vector<std::string>&) {
  throw Error("prt precompute: not available in this build yet");
}

}  // namespace prt
