#pragma once
/// \file
/// How far per-vertex radiance is from a reference, and sums that keep their accuracy.
///
/// Vertex error: over all vertices v and channels c of the difference d = x - ref,
///   rms = sqrt(mean d^2),  max = max |d|,  relative rms = rms / sqrt(mean ref^2),
/// so "1% error" means an RMS difference of 1% of the RMS radiance (the normalised RMS error
/// of image and signal processing).
///
/// Neumaier summation [1] carries the rounding error of every addition in a second accumulator:
/// the error bound is 2u |sum| + O(n u^2) sum |x_i| instead of (n - 1) u sum |x_i| for the naive
/// loop [2], so a million terms lose nothing a double can show.
///
/// References
/// [1] Neumaier, "Rundungsfehleranalyse einiger Verfahren zur Summation endlicher Summen",
///     ZAMM 54, 1974 (the improved Kahan–Babuska algorithm).
/// [2] Higham, "The accuracy of floating point summation", SIAM J. Sci. Comput. 14(4), 1993.

#include <vector>

#include <glm/vec3.hpp>

namespace prt {

struct VertexError {
  double rms = 0;       ///< root mean square difference (radiance units)
  double max = 0;       ///< largest absolute difference
  double relative = 0;  ///< rms / RMS of the reference (0 if the reference is 0)
};

/// Error of `x` against `ref` (same length; throws Error otherwise).
VertexError CompareVertices(const std::vector<glm::vec3>& x, const std::vector<glm::dvec3>& ref);
VertexError CompareVertices(const std::vector<glm::dvec3>& x, const std::vector<glm::dvec3>& ref);
VertexError CompareVertices(const std::vector<glm::vec3>& x, const std::vector<glm::vec3>& ref);

/// Compensated (Neumaier) running sum.
class NeumaierSum {
 public:
  void Add(double x);
  double Value() const { return sum_ + compensation_; }

 private:
  double sum_ = 0.0;
  double compensation_ = 0.0;
};

/// Least-squares slope of log(y) against log(x) over the pairs with x, y > 0 (NaN if fewer
/// than two).
double LogLogSlope(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace prt
