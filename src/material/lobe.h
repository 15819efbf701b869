#pragma once
/// \file
/// Lobes symmetric about an axis r: h(mu), mu = r.s the cosine between r and the direction s.
///
///   phong:N          h(mu) = (N+2)/(2 pi) max(0, mu)^N         (support mu > 0)
///   raised-cosine:P  h(mu) = (P+1)/(4 pi) ((1 + mu)/2)^P        (a polynomial of degree P: its SH
///                                                                 bands stop at P; used to test
///                                                                 what is exact for band-limited lobes)
///
/// Zonal coefficients (Funk–Hecke [1]): integral h(r.s) Y_lm(s) ds = h_l Y_lm(r) with
///   h_l = 2 pi integral_{-1}^{1} h(mu) P_l(mu) dmu.
/// For Phong, h_l = (N+2) I_l with I_l = integral_0^1 mu^N P_l(mu) dmu, which obeys
///   I_0 = 1/(N+1),  I_1 = 1/(N+2),  (N+l+1) I_l = (N-l+2) I_{l-2}   [2, 7.126]
/// (ratios below 1 for l > 1: no cancellation). For the raised cosine the integrand is a
/// polynomial of degree P + l, integrated exactly by Gauss–Legendre.
///
/// The Phong lobe's h_l / h_0 fall off roughly as exp(-l^2 / (2N)) (so a lobe of exponent N needs
/// about sqrt(N) bands; `prt report` measures it).
///
/// Sampling: mu is drawn from the lobe's own density, h(mu) / integral h ds, by inverting its
/// cumulative distribution (Phong: mu = u^(1/(N+1)), density (N+1)/(2 pi) mu^N; raised cosine:
/// mu = 2 u^(1/(P+1)) - 1, density h itself), the azimuth uniformly.
///
/// References
/// [1] Atkinson, Han, "Spherical Harmonics and Approximations on the Unit Sphere", Springer 2012,
///     sec. 2.5 (Funk–Hecke formula).
/// [2] Gradshteyn, Ryzhik, "Table of Integrals, Series, and Products", 7th ed., 7.126.

#include <string>
#include <vector>

namespace prt {

enum class LobeKind { kPhong, kRaisedCosine };

struct Lobe {
  LobeKind kind = LobeKind::kPhong;
  int exponent = 1;

  /// h(mu).
  double Value(double mu) const;
  /// The cosine below which h is 0 (phong: 0; raised cosine: -1).
  double MinMu() const { return kind == LobeKind::kPhong ? 0.0 : -1.0; }
  /// The angle from the axis beyond which h / h(1) < 1e-18 (the lobe is negligible in double).
  double SupportAngle() const;
  /// An angular scale of the lobe's variation, for quadrature: about 1 / sqrt(exponent).
  double Width() const;
  /// Draws mu for u in [0, 1) from the lobe's density; `weight` gets h(mu) / density(mu) (a
  /// constant: phong (N+2)/(N+1), raised cosine 1).
  double SampleMu(double u, double& weight) const;
  /// h_0 .. h_lmax (see above).
  std::vector<double> ZonalCoefficients(int lmax) const;
  /// "phong:N" or "raised-cosine:P".
  std::string Name() const;
};

/// The share of the lobe's energy (its squared norm on the sphere, sum_l (2l+1)/(4 pi) h_l^2 by
/// Parseval) in bands 0..lmax: how much of its sharpness lmax bands can show. The tail is summed
/// to l = 3 sqrt(N) + 20; what lies beyond is below 3e-5 of the energy (measured, N = 1..1000).
double LobeBandShare(const Lobe& lobe, int lmax);

/// The lowest lmax (up to `max_lmax`) whose bands keep `share` of the lobe's energy; max_lmax
/// when none does.
int LmaxForShare(const Lobe& lobe, double share, int max_lmax);

/// The band share below which prt warns that lmax blurs a glossy lobe (its highlight is then as
/// broad as the bands, not as the lobe).
constexpr double kLobeShareWarning = 0.9;

}  // namespace prt
