#include "material/lobe_transfer.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "core/constants.h"
#include "core/frame.h"
#include "core/parallel.h"
#include "sh/basis.h"
#include "sh/coeffs.h"
#include "sh/quadrature.h"
#include "sh/rotation.h"

namespace prt {
namespace {

/// Gauss–Legendre nodes per theta piece and per arc beyond the arc's polynomial degree.
constexpr int kThetaNodes = 24;
constexpr int kArcExtraNodes = 16;
/// Pieces next to a kink are graded geometrically by this ratio, this many times.
constexpr double kGradeRatio = 0.25;
constexpr int kGradeLevels = 4;
/// LobeTransferTable's grid: nodes per lobe width and the fewest nodes.
constexpr double kNodesPerWidth = 32.0;
constexpr int kMinTableNodes = 1024;

struct Rule {
  std::vector<double> x, w;  // on [-1, 1]
};

/// The n-node rule, made once per thread. A map: its elements stay where they are when others
/// are added, so a reference to one rule survives asking for another.
const Rule& GaussRule(int n) {
  thread_local std::map<int, Rule> rules;
  Rule& r = rules[n];
  if (r.x.empty()) GaussLegendre(n, r.x, r.w);
  return r;
}

/// The lobe's frame: (e1, e2, r) right-handed with n in the (e1, r) half-plane, n.r = cg and
/// |n x r| = sg (e1 any perpendicular of r when n is along r).
struct LobeFrame {
  double cg, sg;
  glm::dvec3 e1, e2;
};

LobeFrame LobeFrameOf(const glm::dvec3& n, const glm::dvec3& r) {
  LobeFrame f;
  f.cg = std::clamp(glm::dot(n, r), -1.0, 1.0);
  const glm::dvec3 across = n - f.cg * r;
  f.sg = glm::length(across);
  if (f.sg > 1e-12) {
    f.e1 = across / f.sg;
  } else {
    glm::dvec3 unused;
    TangentFrame(r, f.e1, unused);
  }
  f.e2 = glm::cross(r, f.e1);
  return f;
}

/// The theta pieces: [0, end] split at the kinks (graded toward them) and every `width`.
std::vector<double> ThetaBreaks(double end, double width, const std::vector<double>& kinks) {
  std::vector<double> marks = {0.0, end};
  for (double k : kinks) {
    if (!(k > 0.0 && k < end)) continue;
    marks.push_back(k);
    double step = std::min(width, std::min(k, end - k));
    for (int i = 0; i < kGradeLevels; ++i) {
      step *= kGradeRatio;
      if (k - step > 0.0) marks.push_back(k - step);
      if (k + step < end) marks.push_back(k + step);
    }
  }
  std::sort(marks.begin(), marks.end());
  std::vector<double> breaks;
  for (std::size_t i = 0; i + 1 < marks.size(); ++i) {
    const double a = marks[i], b = marks[i + 1];
    if (b <= a) continue;
    const int pieces = std::max(1, int(std::ceil((b - a) / width)));
    for (int j = 0; j < pieces; ++j) breaks.push_back(a + (b - a) * j / pieces);
  }
  breaks.push_back(end);
  return breaks;
}

}  // namespace

glm::dvec3 MirrorView(const glm::dvec3& n, const glm::dvec3& v) { return 2.0 * glm::dot(n, v) * n - v; }

glm::dvec3 LobeAxis(const glm::dvec3& normal, const glm::dvec3& position, const glm::dvec3& eye) {
  const glm::dvec3 to_eye = eye - position;
  const double distance = glm::length(to_eye);
  return glm::normalize(MirrorView(normal, distance > 0.0 ? to_eye / distance : normal));
}

void LobeTransfer(const Lobe& lobe, const glm::dvec3& n, const glm::dvec3& r, int lmax, double* out) {
  const int count = CoeffCount(lmax);
  std::fill(out, out + count, 0.0);
  const LobeFrame frame = LobeFrameOf(n, r);
  const double cg = frame.cg, sg = frame.sg;
  const glm::dvec3 &e1 = frame.e1, &e2 = frame.e2;
  const double g = std::acos(cg);
  const double end = std::min(lobe.SupportAngle(), std::acos(lobe.MinMu()));
  const std::vector<double> breaks = ThetaBreaks(end, lobe.Width(), {std::abs(kPi / 2 - g), kPi / 2 + g});

  const Rule& theta_rule = GaussRule(kThetaNodes);
  const Rule& arc_rule = GaussRule(lmax + kArcExtraNodes);
  const int ring_points = lmax + 3;
  std::vector<double> y(count);
  for (std::size_t piece = 0; piece + 1 < breaks.size(); ++piece) {
    const double t0 = breaks[piece], half = 0.5 * (breaks[piece + 1] - t0);
    for (std::size_t i = 0; i < theta_rule.x.size(); ++i) {
      const double theta = t0 + half * (theta_rule.x[i] + 1.0);
      const double ct = std::cos(theta), st = std::sin(theta);
      const double a = cg * ct, b = sg * st;
      if (a + b <= 0.0) continue;  // the whole ring is below the horizon
      const double ring_weight = half * theta_rule.w[i] * st * lobe.Value(ct);
      if (ring_weight == 0.0) continue;
      const bool whole = a - b >= 0.0;
      const double alpha = whole ? kPi : std::acos(std::clamp(-a / b, -1.0, 1.0));
      const int points = whole ? ring_points : int(arc_rule.x.size());
      for (int j = 0; j < points; ++j) {
        const double phi = whole ? 2.0 * kPi * j / points : alpha * arc_rule.x[j];
        const double wphi = whole ? 2.0 * kPi / points : alpha * arc_rule.w[j];
        const double c = a + b * std::cos(phi);
        if (c <= 0.0) continue;
        const glm::dvec3 s = ct * r + st * (std::cos(phi) * e1 + std::sin(phi) * e2);
        EvalBasis(lmax, s, y.data());
        const double f = ring_weight * wphi * c;
        for (int k = 0; k < count; ++k) out[k] += f * y[k];
      }
    }
  }
}

LobeTransferTable::LobeTransferTable(const Lobe& lobe, int lmax)
    : lmax_(lmax), count_(CoeffCount(lmax)),
      nodes_(std::max(kMinTableNodes, int(std::ceil(kPi * kNodesPerWidth / lobe.Width()))) + 1) {
  table_.resize(std::size_t(nodes_) * count_);
  ParallelFor(std::size_t(nodes_), 8, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      const double g = kPi * double(i) / double(nodes_ - 1);
      LobeTransfer(lobe, glm::dvec3(std::sin(g), 0.0, std::cos(g)), glm::dvec3(0, 0, 1), lmax_,
                   table_.data() + i * count_);
    }
  });
}

void LobeTransferTable::Transfer(const glm::dvec3& n, const glm::dvec3& r, double* out) const {
  const LobeFrame frame = LobeFrameOf(n, r);
  const double cg = frame.cg, sg = frame.sg;
  const glm::dvec3 &e1 = frame.e1, &e2 = frame.e2;
  // Cubic Lagrange interpolation in g on the four nodes around it (clamped at the ends).
  const double x = std::atan2(sg, cg) / kPi * double(nodes_ - 1);
  const int first = std::clamp(int(std::floor(x)) - 1, 0, nodes_ - 4);
  double w[4];
  for (int a = 0; a < 4; ++a) {
    w[a] = 1.0;
    for (int b = 0; b < 4; ++b)
      if (b != a) w[a] *= (x - double(first + b)) / double(a - b);
  }
  thread_local std::vector<double> local;  // per thread, not per vertex
  local.assign(count_, 0.0);
  for (int a = 0; a < 4; ++a) {
    const double* row = table_.data() + std::size_t(first + a) * count_;
    for (int k = 0; k < count_; ++k) local[k] += w[a] * row[k];
  }
  // Local frame (X = e1, Y = e2, Z = r) to world: the transfer turns with it, t = D(R) t_local.
  const glm::dmat3 rotation(e1, e2, r);
  ShRotation(rotation, lmax_).Apply(local.data(), out);
}

double LobeCosineIntegral(const Lobe& lobe, const glm::dvec3& n, const glm::dvec3& r) {
  double t0 = 0.0;
  LobeTransfer(lobe, n, r, 0, &t0);
  return t0 * std::sqrt(4.0 * kPi);
}

}  // namespace prt
