#pragma once
/// \file
/// `prt render --frame-range A-B | auto | auto/N`: the frames of one sequence that this run
/// writes, as a render farm splits a sequence by range (a task of `prt farm slurm render`, or
/// any scheduler's). Frame i of the range is frame i of the whole `--frames N` sequence: named
/// FrameName(i, N), its light at FrameAngle(i), its camera orbited by i / N, its exposure the
/// one measured on frame 0 (drawn and not written when the range starts later), so its file is
/// the full run's byte for byte. A range run writes its frames into the output folder as a part
/// of it (core/output_folder.h, "Parts of one folder at once"): ranges run at once into one
/// folder, and none removes another's frames.
///
/// `auto` takes the task's index I and count N from the scheduler (farm/shard_id.h) and writes
/// block I of N of the frames (farm/vertex_blocks.h, each frame one unit of work).

#include "app/render_args.h"
#include "options/args.h"

namespace prt {

/// The option's table entry.
OptionSpec FrameRangeOption();

/// Reads --frame-range into job.draw.first_frame and last_frame, after --frames and the other
/// render options: a usage error for a malformed or empty range, one past the last frame, with
/// --video (the whole sequence's: `prt video` assembles it from the frames afterwards) or
/// --vertex-radiance on a range that does not start at frame 0. Returns the summary's line
/// saying the range and where `auto` found it ("" without the option).
std::string ReadFrameRange(Args& args, RenderJobOptions& job);

}  // namespace prt
