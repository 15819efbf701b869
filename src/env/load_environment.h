#pragma once
/// \file
/// Turns the `--env` argument into an Environment: a cubemap folder, an equirectangular image
/// file, or a built-in name (`furnace[:C]`, `sky[:key=value,...]`, see procedural.h).

#include <memory>
#include <string>
#include <vector>

#include "env/cube_faces.h"
#include "env/environment.h"
#include "env/procedural.h"  // SkyParams

namespace prt {

/// The environment of `prt demo` and of every command run without `--env`.
constexpr const char* kDefaultEnvironment = "sky";

/// The names of the built-in environments: furnace, sky.
const std::vector<std::string>& BuiltinEnvironmentNames();

/// A built-in environment and its parameters.
struct BuiltinEnvironment {
  std::string name;      ///< one of BuiltinEnvironmentNames()
  double furnace = 1.0;  ///< furnace: its constant radiance
  SkyParams sky;         ///< sky: its parameters
};

/// Parses `spec` as a built-in, `furnace[:C]` or `sky[:key=value,...]`, without making it.
/// Throws Error naming `spec` and the problem: not a built-in name, a parameter that is unknown,
/// given twice, without a value, not a number (hexadecimal included) or out of range.
BuiltinEnvironment ParseBuiltinEnvironment(const std::string& spec);

/// Loads `spec`. `layout` applies to cubemap folders. Throws Error naming `spec` if it is
/// neither an existing folder or file nor a built-in name, or if its parameters are invalid.
std::unique_ptr<Environment> LoadEnvironment(const std::string& spec, CubeLayout layout);

}  // namespace prt
