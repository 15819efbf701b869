// Placeholder (being written in issue 2).
#include "app/commands.h"
#include "core/error.h"

namespace prt {

const char* const kLightHelp = "usage: prt light ...\n";

int RunLight(const std::vector<std::string>&) { throw Error("prt light: not available in this build yet"); }

}  // namespace prt
