// Placeholder (being written in issue 2).
#include "bench/bench.h"
#include "core/error.h"

namespace prt::bench {

int BenchLight(Args&) { throw Error("prt bench light: not available in this build yet"); }

}  // namespace prt::bench
