// Placeholder until the issue that builds `prt render` lands: it fails cleanly instead of crashing.
#include "app/commands.h"
#include "core/error.h"

namespace prt {

const char* const kRenderHelp = "usage: prt render ...\n  Not available in this build yet.\n";

int RunRender(const std::vector<std::string>&) {
  throw Error("prt render: not available in this build yet");
}

}  // namespace prt
