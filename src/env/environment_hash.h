#pragma once
/// \file
/// A fingerprint of an environment light for the keys of work computed under it (a farm job's
/// reference shards, app/reference_shard.h): FNV-1a over every texel's direction, solid angle
/// and radiance in row order (Environment::Row) and its analytic disks (Disks), not its
/// description (which names the file as the command line spelled it). Two environments with one
/// hash read the same numbers in the same order; a texel changed by one bit changes it.

#include <cstdint>

#include "env/environment.h"

namespace prt {

std::uint64_t EnvironmentHash(const Environment& env);

}  // namespace prt
