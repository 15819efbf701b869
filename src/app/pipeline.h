#pragma once
/// \file
/// The stages of prt as the commands chain them (docs/ARCHITECTURE.md):
///
///   args -> SceneOptions, RenderJobOptions         (checked before any work)
///        -> OutputFolder (created, locked)
///        -> LoadSceneMesh -> Mesh (oriented, split)  -> SceneCamera
///        -> LoadSceneEnvironment -> ComputeLight -> light SH
///        -> the basis's prepare (app/basis_table.h): its transport (SH: ComputeSceneTransport,
///           wavelets: SceneWavelets, each from its cache when it can) and the FrameLight that
///           turns each frame's light; the light view's prepare_light: the light alone
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
#include "cpca/cpca_transfer.h"
#include "env/environment.h"
#include "geometry/mesh.h"
#include "precompute/bounce_summary.h"
#include "precompute/transport.h"
#include "raster/camera.h"
#include "render/render_frames.h"
#include "sh/coeffs.h"
#include "wavelet/options.h"
#include "wavelet/transport.h"

namespace prt {

/// The environment named by the options, described on the run summary. With a `folder`, the
/// file or cubemap folder read is recorded as an input of its run (OutputFolder::KeepInput).
std::unique_ptr<Environment> LoadSceneEnvironment(const SceneOptions& options, OutputFolder* folder = nullptr);

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
/// with an Error before splitting when it would make an unreasonable number of triangles).
void ApplySceneEdits(Mesh& mesh, const SceneOptions& options);

/// The transport options the scene options ask for; a glossy material's transfer is computed
/// for the camera at `eye`.
TransportOptions TransportOptionsOf(const SceneOptions& options, const std::optional<glm::dvec3>& eye = std::nullopt);

/// Where the transport cache is read and written. The cache is an optimisation: a path that
/// cannot be used is a warning (naming the cause) and the run goes on without it.
struct CachePlan {
  std::string path;     ///< empty: no cache
  bool write = true;    ///< false: read if present, never written (folder not writable)
};

/// The plan for the `--cache` value `option` ("" = the file `name` in `folder`: each basis has
/// its own, app/basis_table.h; "none" = no cache), checked before any work. A file there already
/// is replaced only when it is prt's: a cache of either basis, however damaged, or a file prt
/// listed under that name.
CachePlan PlanCache(const std::string& option, OutputFolder* folder, const std::string& name = "transport.cache");

/// The transport of `mesh`: read from the cache when that file was made from the same mesh
/// and options, else computed (and written there when the plan allows; a failed write is a
/// warning). Warns when most vertices see no light at all (an inside-out or enclosed mesh). A
/// glossy material gets its view-dependent transfer toward `camera`'s eye (required then).
/// With `matrices`, a glossy material gets transfer matrices instead (any view). `seen` marks
/// the vertices the camera sees in some frame (render/seen_vertices.h; empty: all): they take
/// --samples directions, the others --hidden-samples.
Transport ComputeSceneTransport(const Mesh& mesh, const SceneOptions& options, const CachePlan& cache,
                                const std::vector<std::uint8_t>& seen = {}, const Camera* camera = nullptr,
                                bool matrices = false);

/// The wavelet transport of `mesh` (wavelet/transport.h) for the transport options `sh` and the
/// wavelet options `w`: read from the cache (wavelet/transport_cache.h) when that file was made
/// from the same mesh and options, or from every vertex computed as a seen one when only the
/// seen vertices were asked for; else ComputeSceneWavelets (wavelet/summary.h, `env` the light its
/// truncation cost is measured under), written there when the plan allows (a failed write is a
/// warning). Said on the run summary.
WaveletTransport SceneWavelets(const Mesh& mesh, const TransportOptions& sh, const WaveletOptions& w,
                               const Environment& env, const CachePlan& cache);

/// Says on the run summary what the transfer matrices of `mesh` will take, and throws Error,
/// naming the largest lmax that fits, when that is more than the memory available allows.
void CheckMatrixMemory(const Mesh& mesh, const SceneOptions& options);

/// `transport`'s matrices compressed by clustered PCA into `clusters` clusters of `terms` terms
/// (cpca/cpca_transfer.h; fewer clusters where the mesh has fewer than clusters x (terms + 1)
/// matrices, so that the model stays smaller than them), said on the run summary with the memory, the relative error measured
/// on this mesh and the time; the full matrices are then released from `transport`.
CpcaTransfer CompressSceneMatrices(Transport& transport, int clusters, int terms);

/// Ends a successful run's use of `folder` (OutputFolder::Finish): removes what an earlier run
/// of the same command wrote there and this one did not, keeps the files prt did not write that
/// --replace replaced as NAME.orig, and says so on the run summary.
void FinishOutputs(OutputFolder& folder);

/// The whole main job: the output folder (job.out), mesh, camera, light, transport, frames,
/// then the folder finished; each stage reports on the run summary, and frame files there that
/// prt has no record of are counted. Used by `render` and `demo`.
void RenderJob(const SceneOptions& scene, const RenderJobOptions& job);

}  // namespace prt
