#pragma once
/// \file
/// The stages of prt as the commands chain them (docs/ARCHITECTURE.md):
///
///   args -> SceneOptions, RenderJobOptions         (checked before any work)
///        -> OutputFolder (created, locked)
///        -> LoadSceneMesh -> Mesh (oriented, split)  -> SceneCamera
///        -> LoadSceneEnvironment -> ComputeLight -> light SH
///        -> the basis's Prepare (basis/basis.h): its transport, from its cache when it can
///           (basis/cache_plan.h), owned by the prepared basis, whose Light() turns each frame's
///           light; the light view's PrepareLight: the light alone
///        -> RenderFrames -> frame_0000.png ...     -> OutputFolder::Finish
///
/// Each stage is a function from const inputs to a returned value and reports what it did (and
/// what it left out, and why) on the run summary.

#include <memory>
#include <optional>
#include <string>

#include "app/render_args.h"
#include "app/scene_options.h"
#include "core/output_folder.h"
#include "env/environment.h"
#include "geometry/mesh.h"
#include "precompute/transport_types.h"
#include "raster/camera.h"
#include "render/render_frames.h"
#include "sh/coeffs.h"

namespace prt {

/// The environment named by the options (the one --lmax auto loaded, when it did), described on
/// the run summary. With a `folder`, the file or cubemap folder read is recorded as an input of
/// its run (OutputFolder::KeepInput).
std::shared_ptr<const Environment> LoadSceneEnvironment(const SceneOptions& options, OutputFolder* folder = nullptr);

/// The camera of the options for `mesh` (ChooseCamera), said on the run summary in option syntax
/// (with the up chosen when world up was parallel to the view).
Camera SceneCamera(const Mesh& mesh, const RenderOptions& render);

/// Says the automatic exposure `ev` on the run summary, measured on `what`, in the option
/// syntax that repeats it (and when it hit its limit).
void ReportAutoExposure(double ev, const std::string& what);

/// The environment's SH coefficients for bands 0..options.lmax, windowed as asked
/// (`auto` picks the mildest window that keeps the reconstruction non-negative and says why).
/// kDefaultWindow is resolved for the frames of `view` (app/seen_ringing.h): the auto window
/// where they would show the light's ringing, said on the run summary with what went negative,
/// else none; the wavelet basis keeps its SH bounce light unwindowed.
ShRgb ComputeLight(const Environment& env, const SceneOptions& options, View view = View::kRadiance);

/// The mesh of `--mesh` (or the embedded demo scene): an inside-out mesh turned right way out
/// where that is unambiguous (geometry/orientation.h), `--albedo` applied, triangles split by
/// `--max-edge`; each repair and anything suspicious reported on the run summary. With a
/// `folder`, the OBJ and material libraries read are recorded as inputs of its run.
Mesh LoadSceneMesh(const SceneOptions& options, OutputFolder* folder = nullptr);

/// What the scene options change in any mesh: `--albedo`, then the `--max-edge` split (refused
/// with an Error before splitting when it would make an unreasonable number of triangles; the
/// faces as read stay in `file_triangles`, on the vertices they had, for --vertex-radiance).
void ApplySceneEdits(Mesh& mesh, const SceneOptions& options);

/// Ends a successful run's use of `folder` (OutputFolder::Finish): removes what an earlier run
/// of the same command wrote there and this one did not, keeps the files prt did not write that
/// --replace replaced as NAME.orig, and says so on the run summary.
void FinishOutputs(OutputFolder& folder);

/// What the main job loads before its transport: the mesh and its camera, whether a glossy
/// orbit needs transfer matrices (their memory checked), the environment, and the transport's
/// options with the vertices the frames show (`seen`).
struct RenderInputs {
  Mesh mesh;
  Camera camera;
  bool matrices = false;
  TransportOptions transport_options;
  std::shared_ptr<const Environment> env;
  bool transport = true;  ///< false: the light view, which computes no transport
};

/// The main job's inputs (above), each stage said on the run summary; with a `folder`, the
/// files read are recorded as inputs of its run.
RenderInputs LoadRenderInputs(const SceneOptions& scene, const RenderJobOptions& job, OutputFolder* folder);

/// The whole main job: the output folder (job.out), mesh, camera, light, transport, frames,
/// then the folder finished; each stage reports on the run summary, and frame files there that
/// prt has no record of are counted. Used by `render` and `demo`. With `sharded` (prt merge of
/// a render's shards), the transport is the shards'.
void RenderJob(const SceneOptions& scene, const RenderJobOptions& job, const ShardedTransport& sharded = {});

}  // namespace prt
