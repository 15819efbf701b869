// prt farm slurm COMMAND [its options] --tasks N: a command as a Slurm job (farm/slurm_script.h):
// its options checked here as each task would check them, then the job script written beside
// the output folder and submitted with sbatch (or printed, --dry-run).
#include <algorithm>
#include <filesystem>

#include "app/commands.h"
#include "app/precompute_shard.h"
#include "app/render_args.h"
#include "app/reference_shard.h"
#include "app/render_shard.h"
#include "app/scene_options.h"
#include "core/atomic_file.h"
#include "core/child_process.h"
#include "core/error.h"
#include "core/log.h"
#include "core/output_folder.h"
#include "farm/shard_id.h"
#include "farm/slurm_script.h"

namespace prt {
namespace {

namespace fs = std::filesystem;

/// The value of `name` in `tokens` (`--name VALUE` or `--name=VALUE`), removed from them; "" when absent.
std::string Take(std::vector<std::string>& tokens, const std::string& name, bool flag = false) {
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    if (tokens[i] == name) {
      std::string value = flag ? "1" : (i + 1 < tokens.size() ? tokens[i + 1] : "");
      tokens.erase(tokens.begin() + std::ptrdiff_t(i), tokens.begin() + std::ptrdiff_t(flag || i + 1 >= tokens.size() ? i + 1 : i + 2));
      if (value.empty()) throw UsageError(name + ": needs a value", "farm");
      return value;
    }
    if (!flag && tokens[i].rfind(name + "=", 0) == 0) {
      std::string value = tokens[i].substr(name.size() + 1);
      tokens.erase(tokens.begin() + std::ptrdiff_t(i));
      return value;
    }
  }
  return "";
}

/// The words of `text` split at spaces.
std::vector<std::string> Words(const std::string& text) {
  std::vector<std::string> words;
  std::string word;
  for (char c : text + " ") {
    if (c != ' ') word += c;
    else if (!word.empty()) words.push_back(word), word.clear();
  }
  return words;
}

/// `value` of option `name` as a task count, 1..kMaxShards (a usage error otherwise).
int ParseCount(const std::string& name, const std::string& value) {
  try {
    return ParseShard("0/" + value).count;
  } catch (const Error&) {
    throw UsageError(name + " " + value + ": expected a whole number 1.." + std::to_string(kMaxShards), "farm");
  }
}

/// A render's job past its transport: the shards' merge renders frame 0 with the cache, an
/// array of `frame_tasks` tasks (at most one a frame) renders the frames in ranges, and
/// `prt video` assembles --video from them. `tokens` are render's options without the farm's.
void PlanRenderFrames(const std::vector<std::string>& tokens, SlurmJob& job, int frame_tasks) {
  std::vector<std::string> options = tokens;
  const std::string video = Take(options, "--video"), fps = Take(options, "--fps");
  std::vector<std::string> read = options;
  const std::string frames_text = Take(read, "--frames");
  int frames = RenderJobOptions{}.draw.frames;
  if (!frames_text.empty()) {
    try {
      frames = std::stoi(frames_text);
    } catch (const std::exception&) {
      frames = 0;
    }
    if (frames < 1) throw UsageError("--frames " + frames_text + ": expected a whole number 1..100000", "render");
  }
  job.frame_tasks = std::min(frame_tasks, frames);
  // The merge writes frame 0 (and the cache) only; the first range writes it again, the same bytes.
  job.options = options;
  job.options.insert(job.options.end(), {"--frame-range", "0-0"});
  // The frames' tasks: frame 0's --vertex-radiance is the merge's alone.
  std::vector<std::string> frame_options = options;
  Take(frame_options, "--vertex-radiance");
  job.frame_options = frame_options;
  if (!video.empty()) {
    job.video = {"--video", video, "--frames", std::to_string(frames)};
    if (!fps.empty()) job.video.insert(job.video.end(), {"--fps", fps});
  }
}

}  // namespace

CommandSpec FarmSpec() {
  return {"prt farm slurm COMMAND [its options] --tasks N [--sbatch \"OPTIONS\"] [--wait] [--dry-run]",
          "Runs COMMAND (precompute, render or reference) as a Slurm job: an array job of N tasks, each computing "
          "one block of the vertices (COMMAND --shard auto), and a job that runs prt merge once every task has succeeded "
          "(sbatch --dependency=afterok). Interreflection chains such a pair for its direct pass and for each "
          "bounce, each array after the merge before it. A render's merge writes the cache and frame 0, "
          "an array of --frame-tasks tasks the frames in ranges (render --frame-range auto), and with --video a last job "
          "assembles the video from them (prt video). A submission that fails cancels the jobs submitted "
          "before it. The result in the command's --out DIR is what the command run on one "
          "machine writes there, byte for byte. The jobs run in this folder with this prt binary, so every machine "
          "of the cluster needs them at the same paths (a shared file system). The job script and the jobs' logs "
          "go to DIR.farm/ beside DIR. COMMAND's options are checked here, before anything is submitted.",
          {{"options",
            {{"--tasks", "N", "the number of shards (array tasks), 1..99999, at most the mesh's vertex count", "required"},
             {"--frame-tasks", "M", "render: the frames in M ranges, an array of M tasks after the merge; at most one a "
              "frame", "--tasks"},
             {"--sbatch", "\"OPTIONS\"",
              "options given to every sbatch, as one word (e.g. \"--partition=long --time=2:00:00 --mem-per-cpu=2G\")",
              "none"},
             {"--wait", "", "wait for the last merge (its state asked of scontrol every second) and exit 0 only when it "
              "completed", "off: exit once submitted"},
             {"--dry-run", "", "print the job script on stdout instead of submitting it", "off"},
             QuietOption()}}}};
}

int RunFarm(const std::vector<std::string>& given) {
  std::vector<std::string> tokens = given;
  const auto usage = [](const std::string& message) { throw UsageError(message, "farm"); };
  if (tokens.empty() || tokens[0] != "slurm")
    usage("expected a scheduler, slurm, then a command (prt farm slurm precompute ... --tasks N)");
  if (tokens.size() < 2 || (tokens[1] != "precompute" && tokens[1] != "render" && tokens[1] != "reference"))
    usage(std::string("farm slurm: ") + (tokens.size() < 2 ? "no command" : "'" + tokens[1] + "'") +
          " (expected precompute, render or reference)");
  SlurmJob job;
  job.command = tokens[1];
  tokens.erase(tokens.begin(), tokens.begin() + 2);
  const std::string tasks = Take(tokens, "--tasks");
  const bool wait = !Take(tokens, "--wait", true).empty();
  const bool dry_run = !Take(tokens, "--dry-run", true).empty();
  job.sbatch = Words(Take(tokens, "--sbatch"));
  if (tasks.empty()) usage("--tasks N is required (the number of array tasks)");
  for (const std::string& t : tokens) {
    if (t == "--shard" || t.rfind("--shard=", 0) == 0) usage("--shard: prt farm gives each task its own (--shard auto)");
    if (t == "--frame-range" || t.rfind("--frame-range=", 0) == 0)
      usage("--frame-range: prt farm gives each task its own range of the frames");
  }
  const std::string frame_tasks = Take(tokens, "--frame-tasks");
  if (!frame_tasks.empty() && job.command != "render") usage("--frame-tasks: only with render (its frames' tasks)");
  job.tasks = ParseCount("--tasks", tasks);
  const bool quiet = !Take(tokens, "--quiet", true).empty();  // the farm's own: its tasks and merges always are
  // Interreflection: its direct pass, then each bounce, as stages (precompute/bounce_stages.h).
  std::vector<std::string> read = tokens;
  const std::string transport = Take(read, "--transport"), bounces = Take(read, "--bounces");
  job.out = Take(read, "--out");
  if (job.command == "render") {
    if (job.out.empty()) job.out = RenderJobOptions{}.out;  // render's default, named for the merge and the video
    PlanRenderFrames(tokens, job, frame_tasks.empty() ? job.tasks : ParseCount("--frame-tasks", frame_tasks));
  } else {
    job.options = tokens;
  }
  // The command's options, checked as the first task will run them.
  std::vector<std::string> check = job.options;
  check.insert(check.end(), {"--shard", "0/" + std::to_string(job.tasks), "--quiet"});
  // Interreflection's transport runs in stages; a reference path-traces each vertex's bounces
  // in one pass.
  const bool staged = transport == "interreflection" && job.command != "reference";
  if (staged) check.insert(check.end(), {"--bounce-stage", "0"});
  if (job.command == "reference") {
    ReferenceCommand(check, nullptr, true);
  } else if (job.command == "render") {
    Render(check, {}, true);
  } else {
    Precompute(check, {}, true);
  }
  SetQuiet(quiet);
  if (staged) job.stages = 1 + (bounces.empty() ? SceneOptions{}.bounces : std::stoi(bounces));
  job.wait = wait;
  job.prt = fs::canonical("/proc/self/exe").string();
  job.workdir = fs::current_path().string();
  const std::string script = SlurmScript(job);
  if (dry_run) {
    std::fputs(script.c_str(), stdout);
    return 0;
  }
  for (const char* tool : {"sbatch", "scancel", "scontrol"})
    if ((std::string(tool) != "scontrol" || wait) && !FindProgram(tool))
      throw Error(std::string(tool) + ": not found on PATH (expected Slurm's client tools, Debian's slurm-client; "
                  "--dry-run prints the job script instead)");
  CreateFolder(FarmFolder(job.out));
  const std::string path = FarmFolder(job.out) + "/submit.sh";
  WriteFileAtomic(path, script);
  const std::string log = FarmFolder(job.out) + "/submit.log";
  Summary("farm: " + job.command + " as " + std::to_string(job.tasks) + " shards" +
          (job.stages > 1 ? " a stage (" + std::to_string(job.stages) + " stages)" : std::string()) +
          " and a merge, submitted by " + path + (wait ? "; waiting for the last job" : ""));
  // The script's own messages and sbatch's errors go to its log, whose last line a failure quotes.
  const ProgramResult run = RunProgram({"/bin/bash", "-c", "exec /bin/bash \"$0\" 2>\"$1\"", path, log});
  if (run.status != 0)
    throw Error(path + ": " + (wait ? "the job" : "submitting") + " failed (exit " + std::to_string(run.status) + ": " +
                LastLine(log) + "; logs in " + FarmFolder(job.out) + "/)");
  const std::string last = run.out.substr(0, run.out.find('\n'));
  const std::string what = !job.video.empty() ? "video" : job.frame_tasks > 0 ? "frames" : "merge";
  Summary("farm: " + what + " job " + last + (wait ? " succeeded: " + job.out + " is written" : " submitted; it writes " + job.out));
  return 0;
}

}  // namespace prt
