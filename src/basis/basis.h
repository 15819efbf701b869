#pragma once
/// \file
/// The one interface a basis implements, and the list of them. A basis is a folder of src/ that
/// stores per-vertex transport in its own coefficients (sh_basis/, wavelet/) and gives the
/// commands everything they need of it through this class: its name and what it can do, its own
/// options (declared, documented and read in its folder), its cache's name and how to recognise
/// its cache files, and Prepare(), which returns an object that owns the transport and makes the
/// frames' light from it. The list (bases/list.h, Bases()) is the only place that names a basis;
/// every command asks the row instead of comparing names. Nothing here knows the list: what
/// needs every basis (the cache plan) is handed it.
///
/// How to add a basis: a folder with a class derived from Basis (and from BasisSettings and
/// PreparedBasis for its options and its transport), a row in src/modules.cmake, and one line in
/// bases/list.cpp. tests/basis/stub_basis/ is such a folder, built into a test program with the
/// list plus one line (tests/basis/CMakeLists.txt), so that the claim is checked.

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "basis/frame_light.h"
#include "cpca/cpca.h"
#include "env/environment.h"
#include "geometry/mesh.h"
#include "options/args.h"
#include "precompute/transport.h"
#include "raster/camera.h"
#include "sh/coeffs.h"

namespace prt {

class BasisStudy;
struct CachePlan;

/// What a basis can do, each by name: the commands ask these instead of comparing names.
struct BasisTraits {
  bool course_files = false;      ///< precompute writes the course's light.txt and transport.txt from it
  bool glossy = false;            ///< materials with a lobe (--material phong:N,KS)
  bool coefficient_view = false;  ///< its coefficients per vertex are SH transfer: --view transport, --look course
  bool windowed_light = false;    ///< its frames are lit by the windowed SH light, whose ringing the run reports
  /// Its transport splits into blocks of vertices (ComputeBlock): `--shard I/N` of a farm job.
  bool shards = false;
  /// Its frames read only the light's SH bands: a lower lmax than the transport's is shown by
  /// zeroing the bands above it (prt view's lmax).
  bool light_bands = false;
  /// Its transport casts --samples and --hidden-samples directions a vertex (the wavelets cast
  /// rays per cube texel instead).
  bool takes_samples = false;
};

/// A basis's own options as read from a command line (or its defaults). Each basis derives its
/// own and reads it back with a checked downcast (Basis::SettingsOf).
class BasisSettings {
 public:
  virtual ~BasisSettings() = default;
};

/// What the main job hands a basis to make its transport.
struct BasisInputs {
  const Mesh& mesh;
  /// The transport the scene options ask for (mode, lmax, samples, sampler, material, seed,
  /// `seen`: the vertices some frame shows, empty: all); `eye` unset (Prepare sets it from
  /// `camera` where a fixed view wants it).
  const TransportOptions& transport;
  bool samples_from_rule;         ///< the direction count is the sample rule's, said on the run summary
  const std::string& lmax_why;    ///< why lmax is the basis's own default ("": it is --lmax's)
  const BasisSettings& own;       ///< the basis's own options (Basis::ReadOptions)
  const glm::dvec3& axis;         ///< the light turns about it (said on the run summary)
  const CpcaOptions& cpca;        ///< --cpca: a glossy orbit's matrices compressed (0 clusters: off)
  const Environment& env;         ///< the light, for a basis that measures its truncation under it
  const Camera* camera;           ///< the fixed view of a glossy material (nullptr: none)
  const CachePlan& cache;
  bool matrices;                  ///< a glossy orbit: transfer matrices wanted
  /// A farm job's transport assembled from its shards (prt merge), taken in place of computing
  /// it; none: computed (or read from the cache).
  ShardedTransport sharded = {};
};

/// A basis made ready for the frames: it owns its transport (no lifetime by convention), and
/// makes any number of frame lights of it, each reading the transport while both live.
class PreparedBasis {
 public:
  virtual ~PreparedBasis() = default;
  /// A frame light under environment `env` (whose SH projection, windowed as the frames need,
  /// is `light`) turning about `axis`. `light_terms` of the light's coefficients are kept each
  /// frame (0: all; a basis that always keeps all ignores it). `env` and this object must
  /// outlive the result. `quality` kInteractive allows a coarser light (basis/frame_light.h).
  virtual std::unique_ptr<FrameLight> Light(const Environment& env, const ShRgb& light, const glm::dvec3& axis,
                                            int light_terms, LightQuality quality) const = 0;
};

class Basis {
 public:
  virtual ~Basis() = default;
  /// The --basis value.
  virtual std::string Name() const = 0;
  /// What `prt help` says of it after its name ("" for the default).
  virtual std::string Help() const = 0;
  /// Its name in a sentence with its article, "an SH", "a wavelet" (the cache messages).
  virtual std::string Noun() const = 0;
  virtual BasisTraits Traits() const = 0;

  /// Its own options (applying to this basis alone), documented with their defaults.
  virtual std::vector<OptionSpec> OwnOptions() const { return {}; }
  /// Reads its own options from `args` (those the command's table lists), each checked with the
  /// same message on every road; the defaults for the others.
  virtual std::shared_ptr<const BasisSettings> ReadOptions(Args& args) const = 0;
  /// Its own options' defaults.
  virtual std::shared_ptr<const BasisSettings> DefaultSettings() const = 0;
  /// Its own options written back as command-line options that repeat `settings`, with the
  /// light keeping `light_terms` (prt view's command line): "" when there are none.
  virtual std::string CommandLine(const BasisSettings& settings, int light_terms) const = 0;
  /// The most light coefficients a frame can keep (prt view's slider; 0: it always keeps all),
  /// and how many its options keep.
  virtual int MaxLightTerms(const BasisSettings&) const { return 0; }
  virtual int LightTerms(const BasisSettings&) const { return 0; }

  /// The --lmax it takes when none is given (-1: the scene options' own default), and why.
  virtual int Lmax() const { return -1; }
  virtual std::string LmaxWhy() const { return ""; }

  /// Its transport cache's name in the output folder: each basis its own, so that neither
  /// replaces the other's.
  virtual std::string CacheName() const = 0;
  /// True when the file at `path` starts as this basis's cache does (however damaged after).
  virtual bool IsOwnCache(const std::string& path) const = 0;

  /// Refuses (Error) what would fail for want of memory once the light is loaded, said on the
  /// run summary: called before the environment is loaded.
  virtual void CheckMemory(const Mesh&, const TransportOptions&, bool /*matrices*/) const {}
  /// Computes the transport (from the cache when it can, said on the run summary).
  virtual std::unique_ptr<PreparedBasis> Prepare(const BasisInputs& inputs) const = 0;
  /// `--shard`: the rows of vertex block `block` of the transport Prepare computes for `inputs`
  /// (the others 0, none read from or written to a cache), said on the run summary, and in
  /// `key` the whole run's cache key, which leaves the block out. Only where Traits().shards.
  virtual Transport ComputeBlock(const BasisInputs& /*inputs*/, const VertexBlock& /*block*/,
                                 std::uint64_t& /*key*/) const {
    throw std::logic_error("ComputeBlock of a basis whose transport does not split into blocks");
  }
  /// The light alone, for the light view, which draws the light as the basis keeps it and no
  /// transport (FrameLight::Kept; nothing else of its frame lights may be called).
  virtual std::unique_ptr<PreparedBasis> PrepareLight(const BasisInputs& inputs) const = 0;

  /// Its own study for `prt report --basis NAME` and its cases of the stability suite
  /// (basis/study.h; one instance that lives as long as the program), or nullptr: none.
  virtual const BasisStudy* Study() const { return nullptr; }
};

/// `settings` as the basis's own type: a basis handed another's settings is a programming
/// error (std::logic_error).
template <class Settings>
const Settings& SettingsAs(const BasisSettings& settings) {
  const auto* own = dynamic_cast<const Settings*>(&settings);
  if (!own) throw std::logic_error("a basis was handed another basis's settings");
  return *own;
}

}  // namespace prt
