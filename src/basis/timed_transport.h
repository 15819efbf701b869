#pragma once
/// \file
/// The transport timed as the report's studies time it (report/report_sweep.h,
/// report/report_glossy.h, and a basis's own study, basis/study.h, such as wavelet/study.h): a
/// run repeated until the repeats together last long enough that the clock's resolution plays no
/// part, its time the fastest repeat.

#include "geometry/mesh.h"
#include "precompute/transport.h"

namespace prt {

/// The glossy and wavelet studies' times (not the sweep's): a run shorter than this is repeated
/// until the repeats together last this long, and its time is the fastest repeat, so the
/// timer's resolution plays no part.
inline constexpr double kMinTimedSeconds = 0.05;
/// At most this many repeats, so a trivially fast run (unshadowed) cannot loop for long.
inline constexpr int kMaxTimedRepeats = 50;

/// The transport of `options`, timed: a run shorter than 0.05 s is repeated until the repeats
/// together last that long, and `seconds` is the fastest repeat (the clock's resolution and
/// scheduling noise then stay far below the times reported). `directions` gets the directions
/// per vertex used, `bvh_seconds` (if given) the BVH build of the fastest run.
Transport TimedTransport(const Mesh& mesh, const TransportOptions& options, double& seconds, int& directions,
                         double* bvh_seconds = nullptr);

}  // namespace prt
