#pragma once
/// \file
/// The render options of CLI.md on the command line (render/render_options.h holds the values):
/// their table entries, documented with the command's own defaults, and their reader. Every
/// value, the camera included, is checked here, before any file is loaded.

#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "app/args.h"
#include "app/scene_options.h"
#include "render/render_options.h"

namespace prt {

/// Every render option in help order: what `render` and `demo` take.
const std::vector<std::string>& AllRenderOptionNames();

/// The table entries of the render options in `names`, documented with `defaults`' values.
OptionGroup RenderOptionGroup(const RenderOptions& defaults, const std::vector<std::string>& names,
                              const std::string& title = "render options");

/// True if `file` names a file of the output folder that the run writes or owns itself (a frame,
/// `.prt-*`, the transport cache): --video and --vertex-radiance may not take that name.
bool IsFolderOwnName(const std::string& file, const RenderOptions& o);

/// True if `file` has a control character (a newline would break the folder's list of outputs).
bool HasControlCharacter(const std::string& file);

/// Reads `--cpca C,K | off` into `o` (clusters 0 for off); a malformed value is a usage error.
void ReadCpca(Args& args, RenderOptions& o);

/// A usage error when `--cpca`'s terms exceed the (lmax+1)^4 numbers of a transfer matrix.
void CheckCpcaTerms(Args& args, const RenderOptions& o, int lmax);

/// Reads the render options the command's table lists, with `defaults` for what is not given.
RenderOptions ReadRenderOptions(Args& args, const RenderOptions& defaults);

/// Checks what depends on both option sets (a transport coefficient the lmax does not have)
/// and gives the embedded scene the demo's camera when no camera option was given.
RenderOptions CompleteRenderOptions(Args& args, RenderOptions render, const SceneOptions& scene);

}  // namespace prt
