// prt video DIR --video FILE: the frames a render wrote into DIR (a whole run's, or the ranges
// of `render --frame-range` that a farm's tasks wrote) as one video, the bytes that `prt render
// --video FILE` writes in one run: each frame's PNG file is read back and handed to the same
// video writer (app/render_video.h) in frame order, an animated PNG taking the file's own bytes.
// The video is an output of the folder's render (listed under it), written as a part of the
// folder (core/output_folder.h): not while a whole run writes there.
#include <filesystem>
#include <set>

#include "app/commands.h"
#include "app/pipeline.h"
#include "app/render_args.h"
#include "app/render_video.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/log.h"
#include "core/progress.h"
#include "io/png_io.h"
#include "render/render_frames.h"

namespace prt {
namespace {

namespace fs = std::filesystem;

/// The frame count of the sequence in `dir`: `given` when the option was given (> 0), else the number
/// of frame files there. Every frame 0..N-1 must be there under FrameName(i, N): a gap is an
/// Error naming the first missing frame and how many are missing.
int SequenceLength(const std::string& dir, int given) {
  std::set<std::string> names;
  std::error_code ec;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (IsFrameName(name)) names.insert(name);
  }
  if (ec) throw Error(dir + ": cannot read the folder (" + ec.message() + ")");
  const int n = given > 0 ? given : int(names.size());
  if (n == 0) throw Error(dir + ": holds no frames (expected frame_0000.png ... that prt render wrote there)");
  int missing = 0;
  std::string first;
  for (int i = 0; i < n; ++i) {
    if (names.count(FrameName(i, n))) continue;
    if (missing++ == 0) first = FrameName(i, n);
  }
  if (missing)
    throw Error(dir + "/" + first + ": missing (" + std::to_string(missing) + " of the " +
                std::to_string(n) + (given > 0 ? " frames --frames gives" : " frames counted from the files") +
                " are missing) (expected every frame of the sequence: the ranges of prt render --frame-range that wrote them all " +
                "ended successfully" + (given > 0 ? "" : ", or --frames N") + ")");
  return n;
}

}  // namespace

CommandSpec VideoCommandSpec() {
  return {"prt video DIR --video FILE",
          "The frames prt render wrote into DIR (frame_0000.png ...; a farm's --frame-range tasks each wrote a range "
          "of them) as one video, byte for byte the one prt render --video FILE --fps F writes in one run of the same "
          "sequence. Every frame 0..N-1 must be there, all of one size; a missing frame is refused with its name "
          "before anything is written.",
          {{"options",
            {{"--video", "FILE",
              ".png or .apng an animated PNG that loops (written by prt, plays in every browser), .mp4 H.264 or .webm "
              "VP9 through Debian's ffmpeg program; in DIR it is one of the folder's render outputs",
              "required"},
             {"--fps", "F", "frames per second, 0.1..240 (at most 90 for an animated PNG)", "30"},
             {"--frames", "N", "the sequence's frame count (1..100000), checked to be all there",
              "the number of frame files in DIR"},
             {"--replace", "", "a file in DIR that prt did not write may be replaced (kept as NAME.orig)", "off"},
             QuietOption()}}}};
}

int RunVideo(const std::vector<std::string>& tokens) {
  Args args("video", tokens, VideoCommandSpec());
  SetQuiet(args.Flag("--quiet"));
  const std::vector<std::string> dirs = args.TakePositionals();
  if (dirs.size() != 1) args.Fail("expected one folder, DIR (got " + std::to_string(dirs.size()) + ")");
  if (!args.Has("--video")) args.Fail("--video: required (expected the video's file, such as DIR/turn.png)");
  // 0: not given (a plain number: the compiler cannot follow an optional through here)
  const int given = args.Has("--frames") ? args.Int("--frames", 1, 1, 100000) : 0;
  RenderJobOptions job;
  job.out = dirs[0];
  job.replace = args.Flag("--replace");
  if (!fs::is_directory(job.out)) throw Error(job.out + ": no such folder (expected the --out DIR of prt render)");
  job.draw.frames = SequenceLength(job.out, given);
  // The size of frame 0; every other frame is checked against it as it is read.
  const Image8 first = ReadPng(job.out + "/" + FrameName(0, job.draw.frames));
  job.draw.width = first.width;
  job.draw.height = first.height;
  ReadVideoOptions(args, job, RenderJobOptions{});
  args.Finish();

  OutputPlan plan{"render", {}, job.replace, /*part=*/true};
  if (LiesIn(job.video.path, job.out)) plan.names.push_back(fs::path(job.video.path).filename().string());
  OutputFolder folder(job.out, plan);
  RenderVideo video(job.video, job.draw, folder);
  Progress progress("video", std::size_t(job.draw.frames));
  for (int i = 0; i < job.draw.frames; ++i) {
    const std::string path = job.out + "/" + FrameName(i, job.draw.frames);
    const std::string png = ReadFile(path);
    const Image8 image = DecodePng(png, path);
    if (image.width != first.width || image.height != first.height)
      throw Error(path + ": " + std::to_string(image.width) + "x" + std::to_string(image.height) + ", not frame 0's " +
                  std::to_string(first.width) + "x" + std::to_string(first.height) +
                  " (expected the frames of one sequence)");
    video.writer()->AddFrame(i, image, png);
    progress.Advance(1);
  }
  Summary(video.Finish());
  FinishOutputs(folder);
  video.Commit();
  return 0;
}

}  // namespace prt
