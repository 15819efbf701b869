#include "material/material.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/text.h"

namespace prt {

std::string Material::Name() const {
  if (!glossy) return "diffuse";
  return "phong:" + std::to_string(lobe.exponent) + "," + ShortestFloat(float(ks));
}

Material GlossyMaterial(const Lobe& lobe, double ks) {
  Material m;
  m.glossy = true;
  m.lobe = lobe;
  m.ks = ks;
  return m;
}

Material ParseMaterial(const std::string& text) {
  const std::string expected = " (expected diffuse or phong:N[,KS], N an integer from " +
                               std::to_string(kMinPhongExponent) + " to " + std::to_string(kMaxPhongExponent) +
                               ", KS from 0 to 1)";
  Material m;
  if (text == "diffuse") return m;
  if (text.rfind("phong:", 0) != 0) throw Error("'" + text + "' is not a material" + expected);
  const std::string rest = text.substr(6);
  const std::size_t comma = rest.find(',');
  const std::string n_text = rest.substr(0, comma);
  const auto n = ParseNumber(n_text);
  if (!n || *n != std::floor(*n) || *n < kMinPhongExponent || *n > kMaxPhongExponent)
    throw Error("'" + text + "': exponent '" + n_text + "' " + (n ? "is out of range" : "is not an integer") + expected);
  m = GlossyMaterial(Lobe{LobeKind::kPhong, static_cast<int>(*n)}, m.ks);
  if (comma != std::string::npos) {
    const std::string ks_text = rest.substr(comma + 1);
    const auto ks = ParseNumber(ks_text);
    if (!ks || !(*ks >= 0.0 && *ks <= 1.0))
      throw Error("'" + text + "': KS '" + ks_text + "' " + (ks ? "is out of range" : "is not a number") + expected);
    m.ks = *ks;
  }
  return m;
}

bool EnergyFits(double ks, double max_albedo) {
  // Slack for albedo stored as float (0.8f is 0.800000012): 1e-6.
  return max_albedo + ks <= 1.0 + 1e-6;
}

void CheckMaterialEnergy(const Material& material, double max_albedo, const std::string& where) {
  if (!material.glossy || EnergyFits(material.ks, max_albedo)) return;
  throw Error("--material " + material.Name() + ": albedo " + ShortestFloat(float(max_albedo)) + " (" + where + ") + KS " +
              ShortestFloat(float(material.ks)) + " = " + ShortestFloat(float(max_albedo + material.ks)) +
              " exceeds 1: the surface would reflect more light than it receives (expected albedo + KS <= 1; lower KS "
              "or --albedo)");
}

KsOffer FittingKs(double ks, double max_albedo) {
  const long nearest = std::lround(std::clamp(ks, 0.0, 1.0) * 100.0);
  if (EnergyFits(double(nearest) / 100.0, max_albedo)) return {double(nearest) / 100.0, false};
  // Down from the nearest: the first multiple of 0.01 that fits is the largest (EnergyFits only
  // tightens as KS grows), floored below the limit, never rounded up past it.
  for (long k = nearest - 1; k > 0; --k)
    if (EnergyFits(double(k) / 100.0, max_albedo)) return {double(k) / 100.0, true};
  return {0.0, true};
}

double GlossyValue(const Material& material, double r_dot_s) {
  return material.glossy ? material.ks * material.lobe.Value(r_dot_s) : 0.0;
}

}  // namespace prt
