#pragma once
/// \file
/// Importance sampling of a distant environment, for the ground truth (reference.h).
///
/// The sphere is cut into an equal-area grid: `rows` bands uniform in z = cos(theta) times `cols`
/// sectors uniform in phi (polar axis world +Y), so every cell has solid angle 4 pi/(rows cols)
/// (Archimedes' hat-box theorem). Each cell gets the weight
///     q_c = max luminance of Radiance() at its 3 x 3 sub-points + defensive * mean luminance,
/// and a direction is drawn by picking a cell with probability q_c / sum q (inverting a row
/// marginal, then a column conditional [1, sec. A.5]) and a uniform point inside it (uniform in
/// z and phi is uniform in solid angle). The density is p(w) = q_c / (sum q * cell solid angle).
///
/// Why this and not splitting the sun off analytically: the estimator
///     L(w) V(w) max(0, n.w) / p(w)
/// uses the exact Radiance() at the sampled direction, so it is unbiased for any environment
/// (cubemap, equirect, sky) whatever the table resolves, and it needs nothing from the
/// environment but Radiance(). Because p is nearly proportional to L, L/p is nearly constant and
/// the variance is that of V max(0, n.w) alone, even with a sun disk of 1e4 times the mean
/// radiance [2]. The max over sub-points (rather than the mean) keeps the cells the sun disk only
/// grazes from being under-sampled, and the defensive term [3] bounds L/p where the table
/// misses a feature altogether (at most 1 / defensive times the mean radiance ratio).
///
/// References
/// [1] Pharr, Jakob, Humphreys, "Physically Based Rendering", 4th ed., sec. A.5 (sampling
///     piecewise-constant 2D distributions) and 12.5 (image infinite lights).
/// [2] Veach, "Robust Monte Carlo Methods for Light Transport Simulation", PhD thesis, Stanford
///     1997, sec. 2.5 (importance sampling: zero variance when p is proportional to f).
/// [3] Hesterberg, "Weighted average importance sampling and defensive mixture distributions",
///     Technometrics 37(2), 1995.

#include <vector>

#include <glm/vec3.hpp>

#include "env/environment.h"

namespace prt {

/// A direction drawn from the table, its density (per steradian) and the radiance there.
struct EnvSample {
  glm::dvec3 dir;
  double pdf;
  glm::dvec3 radiance;
};

class EnvSampler {
 public:
  /// Tabulates `env` on rows x cols cells (see above); defensive > 0.
  EnvSampler(const Environment& env, int rows = 512, int cols = 1024, double defensive = 0.1);

  /// The direction for the point (u1, u2) of the unit square (u in [0, 1)).
  EnvSample Sample(double u1, double u2) const;

  /// The density (per steradian) with which Sample draws the unit direction `dir`: that of the
  /// cell holding it (what multiple importance sampling needs for a direction another
  /// technique drew, reference.h).
  double Pdf(const glm::dvec3& dir) const;

  /// Integral of the environment's luminance over the sphere as the table sees it (for tests).
  double TableIntegral() const { return total_ * cell_solid_angle_; }

 private:
  const Environment& env_;
  int rows_, cols_;
  double cell_solid_angle_;
  double total_ = 0.0;
  std::vector<double> row_cdf_;   ///< rows_ + 1 entries, normalised
  std::vector<double> cell_cdf_;  ///< rows_ * (cols_ + 1), normalised per row
  std::vector<double> weight_;    ///< q_c, rows_ * cols_
};

}  // namespace prt
