#include "precompute/transport.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <future>
#include <limits>
#include <optional>

#include <glm/geometric.hpp>

#include "core/constants.h"
#include "core/error.h"
#include "core/log.h"
#include "core/parallel.h"
#include "precompute/bounce_senders.h"
#include "precompute/transfer_matrix.h"
#include "precompute/transport_bounce.h"
#include "precompute/transport_direct.h"
#include "precompute/transport_glossy.h"
#include "sh/basis.h"
#include "sh/zonal.h"

namespace prt {
namespace {

std::vector<float> ToFloat(const std::vector<double>& v) { return std::vector<float>(v.begin(), v.end()); }

/// The glossy transfer of `options.material` into `transport`: the fixed view's vector
/// (transport_glossy.cpp) or the matrices for any view (transfer_matrix.h).
void AddGlossy(const Mesh& mesh, const Bvh* bvh, const DirectionPlan* plan, const DirectResult* direct,
               const TransportOptions& options, const std::vector<double>* hits, Transport& transport,
               TransportReport& r) {
  if (options.matrices) {
    const auto t0 = std::chrono::steady_clock::now();
    ComputeTransferMatrices(mesh, plan, direct, options.lmax, hits, transport, options.block);
    r.matrix_seconds = SecondsSince(t0);
    return;
  }
  if (!options.eye) throw Error("glossy transfer needs the camera's eye (internal: TransportOptions::eye unset)");
  const auto t0 = std::chrono::steady_clock::now();
  transport.glossy = ToFloat(ComputeGlossy(mesh, bvh, options, hits, transport.channels, r));
  r.glossy_seconds = SecondsSince(t0);
}

/// Shadowed or interreflected transport of every vertex of `mesh`; the report's vertex counts
/// cover its first `counted` vertices (all by default: the rest only send bounced light).
/// With `bounced_only`, the transfer keeps what the bounces add and drops the direct part.
Transport ComputeTraced(const Mesh& mesh, const TransportOptions& options, TransportReport& r,
                        std::size_t counted = std::numeric_limits<std::size_t>::max(), bool bounced_only = false) {
  Transport transport;
  transport.material = options.material;
  transport.lmax = options.lmax;
  transport.vertices = mesh.vertex_count();
  counted = std::min(counted, mesh.vertex_count());

  // The BVH and the direction pool do not depend on each other: with more than one thread they
  // are built at the same time (the BVH on a thread of its own), else one after the other.
  auto t0 = std::chrono::steady_clock::now();
  const auto build_bvh = [&mesh, &r] {
    const auto tb = std::chrono::steady_clock::now();
    Bvh built = Bvh::Build(mesh);
    r.bvh_seconds = SecondsSince(tb);
    return built;
  };
  std::future<Bvh> bvh_future;
  if (ThreadCount() > 1) bvh_future = std::async(std::launch::async, build_bvh);
  const DirectionPlan plan =
      MakeDirectionPlan(options.sampler, options.samples, options.hidden_samples ? options.hidden_samples : options.samples,
                        options.direction_sets, options.seed, options.seen, mesh.vertex_count());
  const Bvh bvh = bvh_future.valid() ? bvh_future.get() : build_bvh();
  r.bvh_built = true;
  r.directions_per_vertex = static_cast<int>(plan.pools[0].size());
  if (plan.pools.size() > 1) {
    r.hidden_directions = static_cast<int>(plan.pools[1].size());
    for (std::size_t v = 0; v < counted; ++v) r.hidden_vertices += plan.pool_of[v];
  }
  // Bounces gather from the hits; transfer matrices are built from them.
  const bool bounces = options.mode == TransportMode::kInterreflection;
  const bool keep_hits = bounces || (options.material.glossy && options.matrices);
  DirectResult direct = ComputeDirect(mesh, bvh, plan, options.lmax, keep_hits, options.block);
  r.rays = direct.rays;
  r.basis_evaluations = direct.basis_evaluations;
  for (std::size_t v = 0; v < counted; ++v) r.closed_form_vertices += direct.unoccluded[v];
  r.direct_seconds = SecondsSince(t0);

  if (!bounces) {
    transport.coeffs = ToFloat(direct.transfer);
    if (options.material.glossy) AddGlossy(mesh, &bvh, &plan, &direct, options, nullptr, transport, r);
    return transport;
  }

  t0 = std::chrono::steady_clock::now();
  BounceResult bounced = AddBounces(mesh, plan, direct, options, r, options.material.glossy, counted);
  r.bounce_seconds = SecondsSince(t0);
  transport.channels = bounced.channels;
  if (bounced_only) {
    const std::size_t count = CoeffCount(options.lmax);
    for (std::size_t v = 0; v < mesh.vertex_count(); ++v)
      for (int c = 0; c < bounced.channels; ++c)
        for (std::size_t k = 0; k < count; ++k)
          bounced.transfer[(v * bounced.channels + c) * count + k] -= direct.transfer[v * count + k];
  }
  transport.coeffs = ToFloat(bounced.transfer);
  if (options.material.glossy) AddGlossy(mesh, &bvh, &plan, &direct, options, &bounced.before_last, transport, r);
  return transport;
}

/// Interreflection: on a copy whose light-sending triangles are split finely (bounce_senders.h),
/// the output the mesh's own vertices, which come first in the copy and are unchanged.
Transport ComputeInterreflection(const Mesh& mesh, const TransportOptions& options, TransportReport& r,
                                 bool bounced_only) {
  const std::optional<Mesh> refined = RefineSenders(mesh, r.senders);
  if (!refined) return ComputeTraced(mesh, options, r, std::numeric_limits<std::size_t>::max(), bounced_only);
  TransportOptions o = options;
  const std::size_t nv = mesh.vertex_count();
  if (o.seen.empty() && o.hidden_samples && o.hidden_samples != o.samples) o.seen.assign(nv, 1);
  if (!o.seen.empty()) o.seen.resize(refined->vertex_count(), 0);  // the added vertices only send light
  Transport transport = ComputeTraced(*refined, o, r, nv, bounced_only);
  const std::size_t count = CoeffCount(options.lmax);
  const std::size_t stride = std::size_t(transport.channels) * count;
  transport.vertices = nv;
  transport.coeffs.resize(nv * stride);
  if (!transport.glossy.empty()) transport.glossy.resize(nv * stride);
  if (!transport.matrices.empty()) transport.matrices.resize(nv * stride * count);
  return transport;
}

}  // namespace

std::vector<double> EstimateUnshadowed(const std::vector<glm::dvec3>& dirs, const glm::dvec3& normal, int lmax) {
  std::vector<double> t(CoeffCount(lmax), 0.0), y(CoeffCount(lmax));
  const double weight = 4.0 * kPi / double(dirs.size()) / kPi;
  for (const auto& d : dirs) {
    const double c = glm::dot(normal, d);
    if (c <= 0.0) continue;
    EvalBasis(lmax, d, y.data());
    for (std::size_t k = 0; k < t.size(); ++k) t[k] += weight * c * y[k];
  }
  return t;
}

Transport ComputeTransport(const Mesh& mesh, const TransportOptions& options, TransportReport* report) {
  TransportReport local;
  TransportReport& r = report ? *report : local;
  r = TransportReport{};

  Transport transport;
  transport.material = options.material;
  transport.lmax = options.lmax;
  transport.vertices = mesh.vertex_count();
  const int count = CoeffCount(options.lmax);

  // Unshadowed: the closed form at every vertex; nothing to trace.
  if (options.mode == TransportMode::kUnshadowed) {
    const auto t0 = std::chrono::steady_clock::now();
    transport.coeffs.resize(transport.vertices * count);
    const std::size_t first = std::min(options.block.begin, transport.vertices);
    const std::size_t last = std::min(options.block.end, transport.vertices);
    ParallelFor(last - first, 256, [&](std::size_t begin, std::size_t end) {
      std::vector<double> t(count);
      for (std::size_t v = first + begin; v < first + end; ++v) {
        UnshadowedTransfer(options.lmax, glm::dvec3(mesh.normals[v]), t.data());
        for (int k = 0; k < count; ++k) transport.coeffs[v * count + k] = static_cast<float>(t[k]);
      }
    });
    r.closed_form_vertices = last - first;
    r.direct_seconds = SecondsSince(t0);
    if (options.material.glossy) AddGlossy(mesh, nullptr, nullptr, nullptr, options, nullptr, transport, r);
    return transport;
  }

  if (options.mode != TransportMode::kInterreflection) return ComputeTraced(mesh, options, r);
  return ComputeInterreflection(mesh, options, r, false);
}

Transport ComputeBouncedTransport(const Mesh& mesh, const TransportOptions& options, TransportReport* report) {
  TransportReport local;
  TransportReport& r = report ? *report : local;
  r = TransportReport{};
  TransportOptions o = options;
  o.mode = TransportMode::kInterreflection;
  o.material = Material{};
  o.matrices = false;
  return ComputeInterreflection(mesh, o, r, true);
}

}  // namespace prt
