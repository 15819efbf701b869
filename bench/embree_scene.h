#pragma once
/// \file
/// Embree 3 for the benchmarks only (`prt bench bvh`, bench/embree_precompute.cpp, built with
/// -DPRT_BENCH_EMBREE=ON): one scene of a mesh's triangles, and rays in Embree's layout.
#include <cstddef>
#include <limits>
#include <stdexcept>

#include <embree3/rtcore.h>
#include <glm/vec3.hpp>

#include "geometry/mesh.h"

namespace prt::bench {

/// The Embree scene of `mesh`'s triangles.
struct EmbreeScene {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  explicit EmbreeScene(const Mesh& mesh) {
    device = rtcNewDevice(nullptr);
    if (!device) throw std::runtime_error("rtcNewDevice failed");
    scene = rtcNewScene(device);
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                         3 * sizeof(float), mesh.vertex_count()));
    for (std::size_t i = 0; i < mesh.vertex_count(); ++i)
      for (int a = 0; a < 3; ++a) v[3 * i + a] = mesh.positions[i][a];
    auto* t = static_cast<unsigned*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                            3 * sizeof(unsigned), mesh.triangle_count()));
    for (std::size_t i = 0; i < mesh.triangle_count(); ++i)
      for (int c = 0; c < 3; ++c) t[3 * i + c] = mesh.triangles[i][c];
    rtcCommitGeometry(g);
    rtcAttachGeometry(scene, g);
    rtcReleaseGeometry(g);
    rtcCommitScene(scene);
  }
  ~EmbreeScene() {
    rtcReleaseScene(scene);
    rtcReleaseDevice(device);
  }
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;
  RTCRay MakeRay(const glm::vec3& o, const glm::vec3& d) const {
    RTCRay r{};
    r.org_x = o.x, r.org_y = o.y, r.org_z = o.z, r.dir_x = d.x, r.dir_y = d.y, r.dir_z = d.z;
    r.tnear = 0.0f, r.tfar = std::numeric_limits<float>::infinity(), r.mask = 0xFFFFFFFFu;
    return r;
  }
};

}  // namespace prt::bench
