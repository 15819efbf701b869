#pragma once
/// \file
/// The scene behind `prt view`'s page (view/view_server.h's ViewBackend): the mesh and its
/// camera, every environment of the command line, and each transport the page has asked for,
/// kept once computed. What a frame costs after the first:
///
///   lmax L <= the bands computed   the light's bands above L zeroed: SH bands nest, so this is
///                                   the frame of a transport computed at L with the same
///                                   directions (the command line gives them: --samples)
///   another axis, env, lmax or      a new frame light of the same transport (PreparedBasis::relight)
///   wavelet light terms
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
/// next when the last has arrived.

#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "app/pipeline.h"
#include "app/scene_options.h"
#include "raster/rasterizer.h"
#include "view/view_server.h"

namespace prt {

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
  /// Loads the mesh and environments and computes the first transport (said on the run summary).
  explicit ViewScene(ViewSetup setup);
  ~ViewScene() override;

  const ViewLimits& Limits() const override { return limits_; }
  const FrameRequest& Defaults() const override { return defaults_; }
  std::string StateJson() const override;
  Image8 Frame(const FrameRequest& request, double* draw_ms) override;
  void Compute(const std::string& basis, const std::string& mode) override;
  std::string Command(const FrameRequest& request) const override;
  void MeasureReference(const FrameRequest& request) override;
  std::string ErrorJson(const FrameRequest& request) override;

 private:
  struct Prepared;
  std::shared_ptr<Prepared> Find(const std::string& basis, const std::string& mode) const;
  void Prepare(const std::shared_ptr<Prepared>& slot, const std::string& basis, const std::string& mode);
  const ShRgb& Light(int env, int lmax, View view, const SceneOptions& scene);
  SceneOptions SceneOf(const std::string& basis, const std::string& mode) const;

  ViewSetup setup_;
  Mesh mesh_;
  Camera camera_;
  std::vector<std::unique_ptr<Environment>> envs_;
  ViewLimits limits_;
  FrameRequest defaults_;

  mutable std::mutex mutex_;  ///< guards prepared_ and the workers
  std::map<std::string, std::shared_ptr<Prepared>> prepared_;
  std::vector<std::thread> workers_;
  struct Measured;
  std::map<std::string, std::shared_ptr<Measured>> references_;  ///< by mode and env; under mutex_
  std::map<std::string, std::string> errors_;                    ///< ErrorJson by setting; under draw_mutex_

  std::mutex draw_mutex_;  ///< one frame at a time: what follows is the frame loop's
  std::map<std::string, ShRgb> lights_;
  std::string light_key_;
  std::unique_ptr<FrameLight> light_;
  Rasterizer rasterizer_;
};

}  // namespace prt
