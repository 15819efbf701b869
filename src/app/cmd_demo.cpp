// Placeholder (being written in issue 2).
#include "app/commands.h"
#include "core/error.h"

namespace prt {

const char* const kDemoHelp = "usage: prt demo ...\n";

int RunDemo(const std::vector<std::string>&) { throw Error("prt demo: not available in this build yet"); }

}  // namespace prt
