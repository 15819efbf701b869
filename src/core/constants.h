#pragma once
/// \file
/// Mathematical constants, defined once.

namespace prt {

/// pi to double precision (the literal has more digits than a double keeps).
inline constexpr double kPi = 3.14159265358979323846;

}  // namespace prt
