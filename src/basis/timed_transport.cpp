#include "basis/timed_transport.h"

#include <chrono>
#include <limits>

#include "core/log.h"

namespace prt {

using Clock = std::chrono::steady_clock;

Transport TimedTransport(const Mesh& mesh, const TransportOptions& o, double& seconds, int& directions,
                         double* bvh_seconds) {
  Transport t;
  double total = 0.0;
  seconds = std::numeric_limits<double>::infinity();
  for (int repeat = 0; repeat < kMaxTimedRepeats && total < kMinTimedSeconds; ++repeat) {
    TransportReport r;
    const auto t0 = Clock::now();
    t = ComputeTransport(mesh, o, &r);
    const double run = SecondsSince(t0);
    total += run;
    if (run < seconds) {
      seconds = run;
      if (bvh_seconds) *bvh_seconds = r.bvh_seconds;
    }
    directions = r.directions_per_vertex;
  }
  return t;
}

}  // namespace prt
