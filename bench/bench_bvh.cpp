// Placeholder until the issue that builds `prt bench bvh` lands.
#include "bench/bench.h"
#include "core/error.h"

namespace prt::bench {

int BenchBvh(Args&) { throw Error("prt bench bvh: not available in this build yet"); }

}  // namespace prt::bench
