#pragma once
/// \file
/// The bases prt stores transport in, in one table: `--basis` reads its names, `prt help` lists
/// them, and every command asks the row what its basis can do instead of comparing names. A
/// basis is a folder of src/ behind basis/frame_light.h (sh_basis/, wavelet/) and one row here:
///
///   name    course  glossy  coefficient  SH light   own options                                cache
///           files           view         windowed
///   sh      yes     yes     yes          yes        -                                          transport.cache
///   wavelet no      no      no           no         --cube-size --wavelet-terms --light-terms  wavelet.cache

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "basis/frame_light.h"
#include "cpca/cpca.h"
#include "env/environment.h"
#include "geometry/mesh.h"
#include "raster/camera.h"
#include "sh/coeffs.h"

namespace prt {

struct SceneOptions;
struct CachePlan;

/// What the main job hands a basis to make its transport and its frames' light.
struct BasisInputs {
  const Mesh& mesh;
  const SceneOptions& scene;
  const glm::dvec3& axis;                 ///< the light turns about it
  const CpcaOptions& cpca;                ///< --cpca: a glossy orbit's matrices compressed (0 clusters: off)
  const Environment& env;
  const ShRgb& light;                     ///< the environment in SH (ComputeLight)
  const std::vector<std::uint8_t>& seen;  ///< the vertices some frame shows (empty: all)
  const Camera& camera;
  const CachePlan& cache;
  bool matrices;                          ///< a glossy orbit: transfer matrices wanted
};

/// A basis made ready for the frames: the frame light, and what it reads (its transport),
/// kept alive as long as the light.
struct PreparedBasis {
  std::shared_ptr<const void> transport;
  std::unique_ptr<FrameLight> light;
  /// Another frame light of the same transport: under environment `env` (whose SH projection is
  /// `light`) turning about `axis`, the wavelet light keeping its `light_terms` most important
  /// coefficients each frame (0: all; SH has no such terms and ignores it). prt view: a light
  /// dragged about any axis, another --env, SH bands above a lower lmax zeroed in `light`, another
  /// --light-terms. `env` must outlive the result, and the result must not outlive `transport`.
  std::function<std::unique_ptr<FrameLight>(const Environment& env, const ShRgb& light, const glm::dvec3& axis,
                                            int light_terms)>
      relight;
};

struct Basis {
  const char* name;          ///< the --basis value
  const char* help;          ///< what `prt help` says of it after its name ("" for the default)
  bool course_files;         ///< precompute writes the course's light.txt and transport.txt from it
  bool glossy;               ///< materials with a lobe (--material phong:N,KS)
  bool coefficient_view;     ///< its coefficients per vertex are SH transfer: --view transport, --look course
  bool windowed_light;       ///< its frames are lit by the windowed SH light, whose ringing the run reports
  bool report_study;         ///< prt report --basis NAME measures it against SH (report/report_wavelet.h)
  std::vector<std::string> options;  ///< the options that apply to this basis alone
  /// The --lmax it takes when none is given (-1: the scene options' own default), and why.
  int lmax;
  const char* lmax_why;
  /// Its transport cache's name in the output folder (PlanCache, app/pipeline.h): each basis its
  /// own, so that neither replaces the other's.
  const char* cache_name;
  /// Computes the transport (said on the run summary) and makes the frames' light.
  PreparedBasis (*prepare)(const BasisInputs& inputs);
  /// Makes the frames' light without a transport, for the light view, which draws the light as
  /// the basis keeps it and no transport (FrameLight::Kept; nothing else may be called).
  PreparedBasis (*prepare_light)(const BasisInputs& inputs);
};

/// Every basis, the default first.
const std::vector<Basis>& Bases();
/// The default basis (the first row).
const Basis* DefaultBasis();
/// The row named `name`, or nullptr.
const Basis* FindBasis(const std::string& name);
/// The names in table order.
std::vector<std::string> BasisNames();

}  // namespace prt
