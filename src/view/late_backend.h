#pragma once
/// \file
/// The backend of a server that listens before its scene is ready: `prt view` takes its port
/// (refusing a taken one at once) and serves the page while its first transport is computed.
/// Until Ready(), every request about the scene is NotReady (409, "starting: ..."), and /state is
///
///   {"starting": true, "progress": {"label", "fraction", "active"}}
///
/// (core/progress.h's latest bar), from which the page shows the progress; then every call goes
/// to the scene.

#include <atomic>

#include "view/view_server.h"

namespace prt {

class LateBackend : public ViewBackend {
 public:
  /// From now on, `scene` answers (it must outlive this server's serving).
  void Ready(ViewBackend& scene) { scene_.store(&scene, std::memory_order_release); }

  const ViewLimits& Limits() const override { return Scene().Limits(); }
  const FrameRequest& Defaults() const override { return Scene().Defaults(); }
  std::string StateJson() const override;
  Image8 Frame(const FrameRequest& request, double* draw_ms) override { return Scene().Frame(request, draw_ms); }
  void Compute(const std::string& basis, const std::string& mode) override { Scene().Compute(basis, mode); }
  void MeasureReference(const FrameRequest& request) override { Scene().MeasureReference(request); }
  std::string ErrorJson(const FrameRequest& request) override { return Scene().ErrorJson(request); }
  std::string Command(const FrameRequest& request) const override { return Scene().Command(request); }

 private:
  /// The scene; NotReady while it is being made.
  ViewBackend& Scene() const;

  std::atomic<ViewBackend*> scene_{nullptr};
};

}  // namespace prt
