// Placeholder until the issue that builds `prt report` lands: it fails cleanly instead of crashing.
#include "app/commands.h"
#include "core/error.h"

namespace prt {

const char* const kReportHelp = "usage: prt report ...\n  Not available in this build yet.\n";

int RunReport(const std::vector<std::string>&) {
  throw Error("prt report: not available in this build yet");
}

}  // namespace prt
