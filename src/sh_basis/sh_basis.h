#pragma once
/// \file
/// Spherical harmonics behind the basis interface (basis/basis.h): the default basis. Its
/// transport is precompute/'s Transport (sh_basis/scene_transport.h computes or reads it), its
/// frame light sh_basis/frame_light.h; it alone writes the course's files, takes glossy
/// materials and shows its coefficients per vertex (--view transport, --look course). It has no
/// options of its own; --cpca compresses a glossy orbit's matrices (sh_basis/scene_cpca.cpp).

#include "basis/basis.h"

namespace prt {

/// The SH basis (one instance).
const Basis& ShBasis();

}  // namespace prt
