#include "precompute/bounce_stages.h"

#include <optional>

#include "geometry/bvh.h"
#include "precompute/bounce_senders.h"
#include "sh/coeffs.h"

namespace prt {

BounceScene MakeBounceScene(const Mesh& mesh, const TransportOptions& options) {
  BounceScene s;
  SenderRefinement senders;
  std::optional<Mesh> refined = RefineSenders(mesh, senders);
  s.own = mesh.vertex_count();
  s.options = options;
  if (refined) {
    // As ComputeInterreflection (transport.cpp): the added vertices only send light.
    if (s.options.seen.empty() && s.options.hidden_samples && s.options.hidden_samples != s.options.samples)
      s.options.seen.assign(s.own, 1);
    if (!s.options.seen.empty()) s.options.seen.resize(refined->vertex_count(), 0);
    s.mesh = std::move(*refined);
  } else {
    s.mesh = mesh;
  }
  const TransportOptions& o = s.options;
  s.plan = MakeDirectionPlan(o.sampler, o.samples, o.hidden_samples ? o.hidden_samples : o.samples, o.direction_sets,
                             o.seed, o.seen, s.mesh.vertex_count());
  s.channels = TransportChannels(s.mesh, TransportMode::kInterreflection);
  s.count = CoeffCount(o.lmax);
  return s;
}

DirectResult DirectStage(const BounceScene& scene, const VertexBlock& block) {
  const Bvh bvh = Bvh::Build(scene.mesh);
  return ComputeDirect(scene.mesh, bvh, scene.plan, scene.options.lmax, true, block);
}

}  // namespace prt
