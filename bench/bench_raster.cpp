// Placeholder until the issue that builds `prt bench raster` lands.
#include "bench/bench.h"
#include "core/error.h"

namespace prt::bench {

int BenchRaster(Args&) { throw Error("prt bench raster: not available in this build yet"); }

}  // namespace prt::bench
