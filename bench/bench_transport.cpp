// Placeholder until the issue that builds `prt bench transport` lands.
#include "bench/bench.h"
#include "core/error.h"

namespace prt::bench {

int BenchTransport(Args&) { throw Error("prt bench transport: not available in this build yet"); }

}  // namespace prt::bench
