#include "view/late_backend.h"

#include <nlohmann/json.hpp>

#include "core/progress.h"

namespace prt {

ViewBackend& LateBackend::Scene() const {
  ViewBackend* scene = scene_.load(std::memory_order_acquire);
  if (!scene) throw NotReady("starting: the first transport is being computed (its progress is in /state)");
  return *scene;
}

std::string LateBackend::StateJson() const {
  if (ViewBackend* scene = scene_.load(std::memory_order_acquire)) return scene->StateJson();
  const ProgressReading p = LatestProgress();
  const nlohmann::ordered_json state{
      {"starting", true},
      {"progress", {{"label", p.label}, {"fraction", p.fraction}, {"active", p.active}}}};
  return state.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

}  // namespace prt
