#pragma once
/// \file
/// A stub third basis, a folder of its own as a basis of src/ is (docs/ARCHITECTURE.md,
/// "Adding a basis"): every vertex receives the light's mean radiance scaled by --stub-gain, and
/// its transport is nothing at all. It exists to check that a basis is a folder and a line of
/// the list (tests/basis/test_stub_basis.cpp).

#include "basis/basis.h"

namespace prt {

/// The stub basis (one instance): name "stub", one option of its own, --stub-gain G.
const Basis& StubBasis();

}  // namespace prt
