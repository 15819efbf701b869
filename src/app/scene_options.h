#pragma once
/// \file
/// The scene options shared by render, demo, precompute, reference, report and light (CLI.md):
/// their table entries (documented with the command's own defaults) and their reader, so every
/// command means the same by them. A command takes the subset its table lists; the reader reads
/// exactly that subset, and checks every value before any file is loaded.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "bases/list.h"
#include "env/cube_faces.h"
#include "env/environment.h"
#include "material/material.h"
#include "sh/coeffs.h"
#include "options/args.h"
#include "precompute/transport.h"

namespace prt {

/// The `--window` of render and demo when none is given: auto where the frames would show the
/// light's ringing, else none (app/seen_ringing.h), resolved by ComputeLight once the light is
/// projected. Not accepted on the command line; precompute and light keep "none".
inline const std::string kDefaultWindow = "default";

struct SceneOptions {
  std::string mesh;                  ///< OBJ path; empty = the embedded demo scene
  std::string texture;               ///< --texture: one albedo texture for every face; empty = map_Kd
  std::string env = "sky";           ///< cubemap folder, image file, or built-in name
  int lmax = 2;                      ///< highest SH band
  /// The highest --lmax the command accepts: kMaxLmax where per-vertex transport is stored,
  /// kMaxBasisLmax for `prt light`, which only prints coefficients.
  int max_lmax = kMaxLmax;
  std::string transport = "shadowed";  ///< unshadowed | shadowed | interreflection
  /// Directions per vertex; 0: the sample rule's default for lmax and sampler
  /// (precompute/sample_rule.h), which ReadSceneOptions puts here.
  int samples = 0;
  bool samples_from_rule = false;    ///< samples is the rule's default, not given by --samples
  /// Directions per vertex the camera does not see; 0: the sample rule's, at most `samples`.
  int hidden_samples = 0;
  std::string sampler = "fibonacci"; ///< fibonacci | stratified | uniform
  int bounces = 1;                   ///< interreflection bounces
  int direction_sets = 64;           ///< pool of direction sets (1: every vertex shares one)
  std::optional<glm::dvec3> albedo;  ///< overrides the material colour
  Material material;                 ///< --material: diffuse, or phong:N,KS
  std::uint64_t seed = 1;
  int threads = 0;                   ///< 0 = all cores
  CubeLayout layout = CubeLayout::kStandard;  ///< --games202-faces selects the course's
  std::string window = "none";       ///< none | hann | lanczos | auto, or kDefaultWindow (render, demo)
  bool lmax_auto = false;            ///< --lmax auto: lmax chosen by --tolerance (report_auto_lmax.h)
  std::string lmax_why;              ///< why lmax is not --lmax's default when the basis chose it ("": it did not)
  double tolerance = 0.01;           ///< --tolerance: relative irradiance error for --lmax auto
  /// --max-edge: split triangles until no edge is longer than this (0: keep the mesh as it is);
  /// a fraction of the bounding-box diagonal when max_edge_relative.
  double max_edge = 0.0;
  bool max_edge_relative = false;
  /// --basis: the basis of the list (basis/basis.h) whose folder stores the transport.
  const Basis* basis = DefaultBasis();
  /// The environment --lmax auto loaded to choose lmax, from `loaded_env_spec` and
  /// `loaded_env_layout`, which LoadSceneEnvironment hands out instead of loading it again while
  /// `env` and `layout` still name it; null otherwise.
  std::shared_ptr<const Environment> loaded_env;
  std::string loaded_env_spec;
  CubeLayout loaded_env_layout = CubeLayout::kStandard;
  /// Every basis's own options (each basis declares and reads them: basis/basis.h).
  BasisOptionSet basis_options;

  /// The chosen basis's own options.
  const BasisSettings& own() const { return basis_options.Of(*basis); }
};

/// Every scene option in help order: what `render` takes.
const std::vector<std::string>& AllSceneOptionNames();
/// The options of the light alone (`prt light`).
const std::vector<std::string>& LightOptionNames();

/// The table entries of the scene options in `names`, documented with `defaults`' values.
OptionGroup SceneOptionGroup(const SceneOptions& defaults, const std::vector<std::string>& names,
                             const std::string& title = "scene options");

/// Reads the scene options the command's table lists, with `defaults` for what is not given,
/// and applies --quiet and --threads. Checks that --mesh and --env name something that exists
/// (or a built-in environment) before anything is loaded. `--lmax auto` loads the environment
/// here to choose lmax. Without --samples (and a default of 0) the direction count follows the
/// sample rule; an explicit --samples below the rule's minimum for a transport that casts rays is
/// a warning naming both counts, said once here, before any work.
SceneOptions ReadSceneOptions(Args& args, const SceneOptions& defaults = {});

/// The transport options the scene options ask for (no eye, every vertex seen).
TransportOptions TransportOptionsOf(const SceneOptions& options);

/// The `--max-edge` length for a mesh whose bounding-box diagonal is `diagonal` (0: none).
double MaxEdgeLength(const SceneOptions& options, double diagonal);

}  // namespace prt
