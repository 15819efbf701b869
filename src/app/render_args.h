#pragma once
/// \file
/// The render options of CLI.md on the command line (render/render_options.h holds the values):
/// their table entries, documented with the command's own defaults, and their reader. Every
/// value, the camera included, is checked here, before any file is loaded.

#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "app/render_video.h"
#include "app/scene_options.h"
#include "options/args.h"
#include "cpca/cpca.h"
#include "render/render_options.h"

namespace prt {

/// The options of the main job (render and demo; reference and precompute take some): what the
/// frames draw, which is all that render/ reads, and beside it what each other stage reads.
struct RenderJobOptions {
  RenderOptions draw;              ///< render/: what the frames show and how
  std::string out = "out/render";  ///< the output folder (core/output_folder.h)
  /// --replace: files in `out` that prt did not write may be replaced (kept as NAME.orig).
  bool replace = false;
  /// The transport cache to reuse and update (PlanCache, app/pipeline.h): empty for the basis's
  /// own in the output folder ("DIR/transport.cache", "DIR/wavelet.cache"), "none" for none.
  std::string cache;
  /// --cpca: the transfer matrices of a glossy --orbit compressed by clustered PCA (app/scene_cpca.cpp)
  /// into `clusters` clusters of a mean and `terms` principal matrices; 0 clusters: the full
  /// matrices (--cpca off). The defaults (cpca/cpca.h's) were measured on the demo scene.
  CpcaOptions cpca;
  /// Where frame 0's per-vertex linear radiance is written (precompute_io/transport_txt.h); empty: nowhere.
  std::string vertex_radiance;
  VideoOptions video;  ///< --video, --fps (app/render_video.h)
};

/// Every render option in help order: what `render` and `demo` take.
const std::vector<std::string>& AllRenderOptionNames();

/// The table entries of the render options in `names`, documented with `defaults`' values.
OptionGroup RenderOptionGroup(const RenderJobOptions& defaults, const std::vector<std::string>& names,
                              const std::string& title = "render options");

/// True if `file` names a file of the output folder that the run writes or owns itself (a frame,
/// `.prt-*`, the transport cache of any basis, or the --cache file): --video and
/// --vertex-radiance may not take that name.
bool IsFolderOwnName(const std::string& file, const RenderJobOptions& o);

/// True if `file` has a control character (a newline would break the folder's list of outputs).
bool HasControlCharacter(const std::string& file);

/// Reads `--cpca C,K | off` into `o` (clusters 0 for off); a malformed value is a usage error.
void ReadCpca(Args& args, CpcaOptions& o);

/// A usage error when `--cpca`'s terms exceed the (lmax+1)^4 numbers of a transfer matrix.
void CheckCpcaTerms(Args& args, const CpcaOptions& o, int lmax);

/// Reads the render options the command's table lists, with `defaults` for what is not given.
RenderJobOptions ReadRenderOptions(Args& args, const RenderJobOptions& defaults);

/// Checks what depends on both option sets (a transport coefficient the lmax does not have)
/// and gives the embedded scene the demo's camera when no camera option was given.
RenderJobOptions CompleteRenderOptions(Args& args, RenderJobOptions render, const SceneOptions& scene);

/// Reads --video and --fps into `job.video` (after --size and --out): the extension names a
/// format, the rate suits it, the size suits H.264, the name is not one of the run's other
/// outputs, and ffmpeg with its encoder is installed for .mp4 and .webm. Throws UsageError
/// (through `args`) or Error.
void ReadVideoOptions(Args& args, RenderJobOptions& job, const RenderJobOptions& defaults);

}  // namespace prt
