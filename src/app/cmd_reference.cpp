// Placeholder until the issue that builds `prt reference` lands: it fails cleanly instead of crashing.
#include "app/commands.h"
#include "core/error.h"

namespace prt {

const char* const kReferenceHelp = "usage: prt reference ...\n  Not available in this build yet.\n";

int RunReference(const std::vector<std::string>&) {
  throw Error("prt reference: not available in this build yet");
}

}  // namespace prt
