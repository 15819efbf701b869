#pragma once
/// \file
/// The scene behind `prt view`'s page (view/view_server.h's ViewBackend): the mesh and its
/// camera, every environment of the command line, and each transport the page has asked for,
/// kept once computed. What a frame costs after the first:
///
///   lmax L <= the bands computed   the light's bands above L zeroed: SH bands nest, so this is
///                                   the frame of a transport computed at L with the same
///                                   directions (the command line gives them: --samples)
///   another axis                    the kept frame light turned about it (FrameLight::SetAxis): a
///                                   drag turns about a new axis at every move
///   another env, lmax, wavelet      a new frame light of the same transport (PreparedBasis::Light),
///   light terms or quality          kept for the next frames
///   another basis or mode           that transport computed in the background on first use
///                                   (409 for its frames meanwhile, progress in /state), then kept
///   the error against prt reference the reference's per-vertex radiance under the unturned
///                                   environment, measured in the background when the page asks
///                                   (precompute/reference.h, --reference-samples directions), then
///                                   each setting's relative RMS error over every vertex
///   the camera                      nothing: a diffuse transport does not depend on it (a glossy
///                                   one was computed for the command line's eye, which stays)
///
/// Frames are drawn one at a time (the frame loop's buffers are shared); the page asks for the
/// next when the last has arrived. The background work runs on kViewWorkers threads
/// (core/task_pool.h), each job kept as the std::shared_future of its result: not asked for
/// (no future), still running (not ready) or done (its result, or its error rethrown).

#include <future>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "app/pipeline.h"
#include "app/scene_options.h"
#include "core/task_pool.h"
#include "precompute/reference.h"
#include "raster/rasterizer.h"
#include "view/view_server.h"

namespace prt {

/// The threads of `prt view`'s background work: two, so that the reference the page asks for is
/// measured while another transport is computed (the error figures need both). Further jobs
/// queue ("computing" in /state) rather than each taking a thread of its own: ParallelFor's
/// threads go to one job at a time and the others run alone (core/parallel.h), so more jobs at
/// once would mostly contend for the same cores, and a page could start threads without bound.
inline constexpr int kViewWorkers = 2;

/// Frame lights kept between frames: a setting's still and interactive lights, and those of the
/// one before (lmax or basis switched back and forth).
inline constexpr std::size_t kKeptLights = 4;

/// What `prt view` was given.
struct ViewSetup {
  SceneOptions scene;                  ///< the first transport's options (its basis and mode)
  RenderOptions draw;                  ///< the first frame
  std::vector<std::string> envs;       ///< --env, then the extra environments
  std::string cache;                   ///< --cache: the first transport's cache file ("none": none)
  int reference_samples = 1024;        ///< --reference-samples: directions a vertex of the measured reference
  /// The options as typed that the render command line repeats as they are (those the page does
  /// not set and render takes).
  std::vector<std::string> kept_tokens;
};

class ViewScene : public ViewBackend {
 public:
  /// Loads the mesh and environments (their errors thrown here, before any long work).
  explicit ViewScene(ViewSetup setup);
  /// Computes the first transport (said on the run summary) and, without --exposure, the
  /// exposure of the first frame; the run fails with its error. The other calls need it done.
  void ComputeFirst();
  /// Waits for the background jobs that are running; those still queued are dropped.
  ~ViewScene() override = default;

  const ViewLimits& Limits() const override { return limits_; }
  const FrameRequest& Defaults() const override { return defaults_; }
  std::string StateJson() const override;
  Image8 Frame(const FrameRequest& request, double* draw_ms) override;
  void Compute(const std::string& basis, const std::string& mode) override;
  std::string Command(const FrameRequest& request) const override;
  void MeasureReference(const FrameRequest& request) override;
  std::string ErrorJson(const FrameRequest& request) override;

 private:
  /// One transport the page asked for, computed.
  struct Prepared {
    std::unique_ptr<PreparedBasis> basis;
    SceneOptions scene;
  };
  /// The job of (basis, mode)'s transport; not valid() when never asked for.
  std::shared_future<Prepared> Find(const std::string& basis, const std::string& mode) const;
  /// Computes (basis, mode)'s transport, on whatever thread calls it.
  Prepared Prepare(const std::string& basis, const std::string& mode) const;
  /// (basis, mode)'s transport once computed (kept as long as the scene: a job is never
  /// forgotten); NotReady before, its error as Error.
  const Prepared& Transport(const std::string& basis, const std::string& mode) const;
  /// The reference of `mode` under environment `env` once measured (kept as long as the scene);
  /// NotReady before, its error as Error.
  const Reference& MeasuredReference(const std::string& mode, int env) const;
  const ShRgb& Light(int env, int lmax, View view, const SceneOptions& scene);
  SceneOptions SceneOf(const std::string& basis, const std::string& mode) const;

  ViewSetup setup_;
  Mesh mesh_;
  Camera camera_;
  std::vector<std::shared_ptr<const Environment>> envs_;
  ViewLimits limits_;
  FrameRequest defaults_;

  mutable std::mutex mutex_;  ///< guards prepared_ and references_ (the maps; a future guards its own result)
  std::map<std::string, std::shared_future<Prepared>> prepared_;    ///< by basis and mode
  std::map<std::string, std::shared_future<Reference>> references_;  ///< by mode and env
  std::map<std::string, std::string> errors_;                        ///< ErrorJson by setting; under draw_mutex_

  /// The frame light of one setting (all but the axis, which SetAxis changes).
  struct KeptLight {
    std::unique_ptr<FrameLight> light;
    glm::dvec3 axis;
  };
  /// The frame light of `request`'s setting, turning about its axis.
  FrameLight& FrameLightOf(const FrameRequest& request, const Prepared& slot);

  std::mutex draw_mutex_;  ///< one frame at a time: what follows is the frame loop's
  std::map<std::string, ShRgb> lights_;
  /// The frame lights of the last settings drawn (a still and an interactive one of the same
  /// setting alternate), at most kKeptLights.
  std::map<std::string, KeptLight> frame_lights_;
  Rasterizer rasterizer_;

  /// Last, so destroyed first: its destructor waits for the running jobs, which read the members
  /// above and write their futures' results.
  TaskPool pool_{kViewWorkers};
};

}  // namespace prt
