#include "app/frame_range.h"

#include <cmath>
#include <cstdint>

#include "core/error.h"
#include "core/text.h"
#include "farm/shard_id.h"
#include "farm/vertex_blocks.h"

namespace prt {

OptionSpec FrameRangeOption() {
  return {"--frame-range", "A-B|auto[/N]",
          "write only frames A to B (0-based, inclusive) of the --frames sequence, each named and with the bytes "
          "the whole run writes (the exposure measured on frame 0, drawn and not written when A > 0), beside other "
          "ranges writing the same --out at once; auto: block I of N of the frames, I and N from the scheduler "
          "(SLURM_ARRAY_TASK_ID with SLURM_ARRAY_TASK_COUNT or the array's min and max; JOB_COMPLETION_INDEX with "
          "auto/N). Not with --video: prt video --out DIR assembles it from the frames",
          "all frames"};
}

std::string ReadFrameRange(Args& args, RenderJobOptions& job) {
  const auto text = args.String("--frame-range");
  if (!text) return "";
  RenderOptions& o = job.draw;
  const std::string n = std::to_string(o.frames);
  const std::string expected = " (expected A-B with 0 <= A <= B < " + n + ", the --frames count, or auto or auto/N)";
  std::string source;
  if (text->rfind("auto", 0) == 0) {
    ShardId task;
    try {
      task = ParseShard(*text);
    } catch (const Error& e) {
      args.Fail(std::string("--frame-range: ") + e.what());
    }
    if (task.count > o.frames)
      args.Fail("--frame-range " + *text + ": " + std::to_string(task.count) + " tasks for " + n +
                " frames (expected at most one task per frame: fewer tasks, or more --frames)");
    const VertexBlock block = BlockOf(std::vector<std::uint64_t>(std::size_t(o.frames), 1), task.index, task.count);
    o.first_frame = int(block.begin);
    o.last_frame = int(block.end) - 1;
    source = " (block " + std::to_string(task.index) + " of " + std::to_string(task.count) + ": " + task.source + ")";
  } else {
    const auto dash = text->find('-');
    const auto a = ParseNumber(text->substr(0, dash));
    const auto b = dash == std::string::npos ? std::nullopt : ParseNumber(text->substr(dash + 1));
    if (!a || !b || *a < 0 || *b < *a || std::floor(*a) != *a || std::floor(*b) != *b)
      args.Fail("--frame-range: '" + *text + "' is not a range" + expected);
    if (*b >= double(o.frames)) args.Fail("--frame-range: '" + *text + "' goes past the last frame, " +
                                  std::to_string(o.frames - 1) + expected);
    o.first_frame = int(*a);
    o.last_frame = int(*b);
  }
  if (!job.video.path.empty())
    args.Fail("--video: not with --frame-range (the video is the whole sequence's: once every range is written, "
              "prt video --out " + job.out + " --video FILE assembles it from the frames)");
  if (!job.vertex_radiance.empty() && o.first_frame != 0)
    args.Fail("--vertex-radiance: frame 0's, not with a --frame-range that starts at frame " +
              std::to_string(o.first_frame) + " (expected it on the range that starts at 0)");
  return "frames: " + std::to_string(o.first_frame) + " to " + std::to_string(o.last_frame) + " of " + n +
         " (--frame-range " + *text + ")" + source;
}

}  // namespace prt
