#pragma once
/// \file
/// Direction sets on the unit sphere for Monte Carlo integration, each with equal weights 4 pi/N.
///
/// - `fibonacci`: the spherical Fibonacci point set [1], z_i = 1 - (2i + 1)/N,
///   phi_i = 2 pi frac(i / golden ratio), turned by a random rotation so that each set is an
///   unbiased estimator. Near-uniform: RMS error falls about as N^-1.4..-1.6 on smooth
///   integrands and N^-0.75 on binary visibility (CONVENTIONS.md).
/// - `stratified`: the course's jittered grid: side = floor(sqrt(N)) cells in
///   (alpha, beta), one jittered sample each, theta = acos(2 alpha - 1), phi = 2 pi beta. About N^-1
///   on smooth integrands; uses side^2 <= N directions.
/// - `uniform`: independent uniform directions [2]: N^-0.5.
///
/// References
/// [1] Keinert, Innmann, Sänger, Stamminger, "Spherical Fibonacci Mapping", SIGGRAPH Asia 2015.
/// [2] Pharr, Jakob, Humphreys, "Physically Based Rendering", 4th ed., sec. A.5.2 (uniform
///     sphere sampling) and 8.5 (stratification).

#include <string>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "core/rng.h"

namespace prt {

enum class Sampler { kFibonacci, kStratified, kUniform };

/// "fibonacci" -> kFibonacci, ... (the `--sampler` words); throws Error for any other name.
Sampler SamplerFromName(const std::string& name);
/// The `--sampler` word of `s`.
const char* SamplerName(Sampler s);
/// Every sampler's word, in the enum's order.
std::vector<std::string> SamplerNames();

/// A direction set of `n` unit vectors (stratified: floor(sqrt(n))^2 of them) drawn with `rng`.
std::vector<glm::dvec3> SampleSphere(Sampler sampler, int n, Pcg32& rng);

/// A uniformly distributed random rotation (Arvo's method via a random unit quaternion).
glm::dmat3 RandomRotation(Pcg32& rng);

}  // namespace prt
