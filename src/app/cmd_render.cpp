#include "app/commands.h"
#include "app/frame_range.h"
#include "app/precompute_shard.h"
#include "app/render_shard.h"
#include "app/pipeline.h"
#include "app/render_look.h"
#include "core/log.h"

namespace prt {
namespace {

/// Render's scene defaults: SceneOptions', with the window chosen where the frames would ring.
SceneOptions RenderScene() {
  SceneOptions s;
  s.window = kDefaultWindow;
  return s;
}

/// The render options of `prt render`: --look (render's own) first, then those it shares with demo.
OptionGroup RenderGroup() {
  OptionGroup group = RenderOptionGroup(RenderJobOptions{}, AllRenderOptionNames());
  group.options.insert(group.options.begin(), LookOption());
  group.options.push_back(FrameRangeOption());
  for (const OptionSpec& o : ShardOptions("DIR/transport.cache.shard-IIIII-of-NNNNN (no frames)",
                                          "renders as one run renders"))
    group.options.push_back(o);
  return group;
}

}  // namespace

CommandSpec RenderSpec() {
  return {"prt render [scene options] [render options]",
          "Precomputes the transport (or reuses the cache), then writes DIR/frame_0000.png ... of the mesh under "
          "the environment light turning about the axis. Without --mesh, the embedded demo scene is seen with the "
          "demo's camera.\n\nThe run summary on stderr says what each stage did and left out, the camera in "
          "option syntax and the exposure chosen, so a run can be repeated exactly.\n\n--look course renders what "
          "the GAMES202 homework-2 WebGL viewer shows of prt precompute's files; the defaults below are those of "
          "--look default, and options given on the command line win over either look.",
          {SceneOptionGroup(RenderScene(), AllSceneOptionNames()), RenderGroup(), {"other options", {QuietOption()}}}};
}

int RunRender(const std::vector<std::string>& tokens) { return Render(tokens, {}); }

int Render(const std::vector<std::string>& tokens, const ShardedTransport& sharded, bool check_only) {
  Args args("render", tokens, RenderSpec());
  // The look first: it gives the defaults that the options on the command line override.
  const Look look = ReadLook(args);
  const SceneOptions scene = ReadSceneOptions(args, LookSceneDefaults(look, RenderScene()));
  RenderJobOptions defaults;
  defaults.draw = LookRenderDefaults(look, defaults.draw);
  RenderJobOptions render = CompleteRenderOptions(args, ReadRenderOptions(args, defaults), scene);
  const std::string range_line = ReadFrameRange(args, render);
  const std::optional<ShardTask> task = ReadShardTask(args, scene);
  const std::string look_line = CheckLook(args, look, scene);
  args.Finish();
  if (task && render.draw.view == View::kLight && render.vertex_radiance.empty())
    args.Fail("--shard: --view light computes no transport to split (expected another --view, or no --shard)");
  if (check_only) return 0;
  if (!look_line.empty()) Summary(look_line);
  if (task) return RunRenderShard(scene, render, task->shard, ShardCommand("render", tokens), task->stage);
  if (!range_line.empty()) Summary(range_line);
  RenderJob(scene, render, sharded);
  return 0;
}

}  // namespace prt
