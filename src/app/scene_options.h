#pragma once
/// \file
/// The scene options shared by render, precompute, reference and report (CLI.md), read once and
/// validated here, so every command means the same by them.

#include <cstdint>
#include <optional>
#include <set>
#include <string>

#include <glm/vec3.hpp>

#include "app/args.h"
#include "env/cube_faces.h"

namespace prt {

struct SceneOptions {
  std::string mesh;                  ///< OBJ path; empty = the embedded demo scene
  std::string env = "sky";           ///< cubemap folder, image file, or built-in name
  int lmax = 2;                      ///< highest SH band
  std::string transport = "shadowed";  ///< unshadowed | shadowed | interreflection
  int samples = 1024;                ///< directions per vertex
  std::string sampler = "fibonacci"; ///< fibonacci | stratified | uniform
  int bounces = 1;                   ///< interreflection bounces
  int direction_sets = 64;           ///< pool of direction sets (1: every vertex shares one)
  std::optional<glm::dvec3> albedo;  ///< overrides the material colour
  std::uint64_t seed = 1;
  int threads = 0;                   ///< 0 = all cores
  CubeLayout layout = CubeLayout::kStandard;  ///< --games202-faces selects the course's
  std::string window = "none";       ///< none | hann | lanczos | auto
  bool lmax_auto = false;            ///< --lmax auto: lmax chosen by --tolerance (report_auto_lmax.h)
  double tolerance = 0.01;           ///< --tolerance: relative irradiance error for --lmax auto
};

/// The value-less flags of the scene options, plus `extra` (for the Args constructor).
std::set<std::string> SceneFlags(std::set<std::string> extra = {});

/// Reads the scene options from `args`, with `defaults` for what is not given.
SceneOptions ReadSceneOptions(Args& args, const SceneOptions& defaults = {});

/// The help text of the scene options, with their defaults.
extern const char* const kSceneOptionsHelp;

}  // namespace prt
