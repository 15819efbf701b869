#pragma once
/// \file
/// Turns the `--env` argument into an Environment: a cubemap folder, an equirectangular image
/// file, or a built-in name (`furnace[:C]`, `sky[:key=value,...]`, see procedural.h).

#include <memory>
#include <string>

#include "env/cube_faces.h"
#include "env/environment.h"

namespace prt {

/// The environment of `prt demo` and of every command run without `--env`.
constexpr const char* kDefaultEnvironment = "sky";

/// Loads `spec`. `layout` applies to cubemap folders. Throws Error naming `spec` if it is
/// neither an existing folder or file nor a built-in name, or if its parameters are invalid.
std::unique_ptr<Environment> LoadEnvironment(const std::string& spec, CubeLayout layout);

}  // namespace prt
