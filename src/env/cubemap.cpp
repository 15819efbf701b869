#include "env/cubemap.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "core/error.h"
#include "core/log.h"
#include "core/parallel.h"
#include "core/simd.h"
#include "io/image_load.h"

namespace prt {
namespace fs = std::filesystem;

CubemapEnvironment::CubemapEnvironment(std::array<ImageF, 6> faces, CubeLayout layout,
                                       std::string description)
    : faces_(std::move(faces)), frames_(FaceFrames(layout)), size_(faces_[0].width),
      description_(std::move(description)) {
  // Solid angles depend only on (col, row), the same for every face: compute them once.
  solid_angles_.resize(static_cast<std::size_t>(size_) * size_);
  for (int row = 0; row < size_; ++row)
    for (int col = 0; col < size_; ++col)
      solid_angles_[static_cast<std::size_t>(row) * size_ + col] = TexelSolidAngle(col, row, size_);
}

namespace {

// Rows on core/simd.h's vectors (V2 on the baseline, V4 with AVX2): per texel one square root
// and three divisions, which took most of the time of the scalar loop (measured for the rows of
// a 6 x 512^2 cube, one thread, AMD EPYC of lscpu family 26: 6.5 ms scalar, 3.3 ms with V4).
// Everything on vectors is forced inline, so -Wpsabi's warning (vectors passed by value depend
// on the instruction set) does not apply.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

/// What one face row's texels are made of.
struct FaceRow {
  const FaceFrame* frame;
  double t, step;  ///< the row's face coordinate t, the texel size 2 / size
  int size;
  const double* solid_angles;  ///< size values
  const glm::vec3* radiance;   ///< size values
};

/// Fills out[0..size) for the face row r: solid angle and radiance copied, and the centre
/// direction d = (n + s u) + t v, s = -1 + (col + 1/2) step, component by component, divided by
/// sqrt((d.x^2 + d.y^2) + d.z^2). That is how the glm expression d / sqrt(dot(d, d)) rounds, so
/// the result does not depend on the vector width V.
template <class V>
PRT_SIMD_INLINE void RowTexelsBody(const FaceRow& r, Texel* out) {
  constexpr int kLanes = sizeof(V) / sizeof(double);
  const FaceFrame& f = *r.frame;
  V lane;
  for (int j = 0; j < kLanes; ++j) lane[j] = j;
  const double tx = r.t * f.v.x, ty = r.t * f.v.y, tz = r.t * f.v.z;
  for (int col = 0; col < r.size; col += kLanes) {
    const V s = -1.0 + ((lane + col) + 0.5) * r.step;
    const V dx = (f.n.x + s * f.u.x) + tx, dy = (f.n.y + s * f.u.y) + ty, dz = (f.n.z + s * f.u.z) + tz;
    const V len = simd::Sqrt((dx * dx + dy * dy) + dz * dz);
    const V x = dx / len, y = dy / len, z = dz / len;
    for (int j = 0; j < kLanes && col + j < r.size; ++j)
      out[col + j] = Texel{glm::dvec3(x[j], y[j], z[j]), r.solid_angles[col + j], glm::dvec3(r.radiance[col + j])};
  }
}

using RowKernel = void (*)(const FaceRow& r, Texel* out);

void RowTexels2(const FaceRow& r, Texel* out) { RowTexelsBody<simd::V2>(r, out); }
#ifdef PRT_TARGET_AVX2
PRT_TARGET_AVX2 void RowTexels4(const FaceRow& r, Texel* out) { RowTexelsBody<simd::V4>(r, out); }
#endif

RowKernel ChooseRowKernel() {
#ifdef PRT_TARGET_AVX2
  if (CpuVectorLevel() != VectorLevel::kBaseline) return RowTexels4;
#endif
  return RowTexels2;
}

}  // namespace

void CubemapEnvironment::Row(std::size_t i, std::vector<Texel>& out) const {
  static const RowKernel row_texels = ChooseRowKernel();
  const int face = static_cast<int>(i / size_), row = static_cast<int>(i % size_);
  const double step = 2.0 / size_;
  out.resize(size_);
  row_texels({&frames_[face], -1.0 + (row + 0.5) * step, step, size_,
              solid_angles_.data() + static_cast<std::size_t>(row) * size_, &faces_[face].at(0, row)},
             out.data());
}

glm::dvec3 CubemapEnvironment::Radiance(const glm::dvec3& dir) const {
  // The face whose axis is closest to dir, then bilinear filtering inside that face.
  int face = 0;
  double best = -1.0;
  for (int k = 0; k < 6; ++k) {
    const double c = glm::dot(dir, frames_[k].n);
    if (c > best) best = c, face = k;
  }
  const FaceFrame& f = frames_[face];
  const double s = glm::dot(dir, f.u) / best, t = glm::dot(dir, f.v) / best;
  const double x = std::clamp((s + 1.0) * 0.5 * size_ - 0.5, 0.0, size_ - 1.0);
  const double y = std::clamp((t + 1.0) * 0.5 * size_ - 0.5, 0.0, size_ - 1.0);
  const int x0 = static_cast<int>(x), y0 = static_cast<int>(y);
  const int x1 = std::min(x0 + 1, size_ - 1), y1 = std::min(y0 + 1, size_ - 1);
  const double fx = x - x0, fy = y - y0;
  const ImageF& img = faces_[face];
  const glm::dvec3 top = glm::mix(glm::dvec3(img.at(x0, y0)), glm::dvec3(img.at(x1, y0)), fx);
  const glm::dvec3 bottom = glm::mix(glm::dvec3(img.at(x0, y1)), glm::dvec3(img.at(x1, y1)), fx);
  return glm::mix(top, bottom, fy);
}

std::array<ImageF, 6> CubemapFaceImages(const std::function<glm::dvec3(const glm::dvec3&)>& radiance, int size,
                                        CubeLayout layout) {
  std::array<ImageF, 6> faces;
  const auto& frames = FaceFrames(layout);
  for (int k = 0; k < 6; ++k) {
    faces[k] = ImageF(size, size);
    for (int row = 0; row < size; ++row)
      for (int col = 0; col < size; ++col) {
        const double s = -1.0 + (col + 0.5) * 2.0 / size, t = -1.0 + (row + 0.5) * 2.0 / size;
        faces[k].at(col, row) = glm::vec3(radiance(glm::normalize(frames[k].n + s * frames[k].u + t * frames[k].v)));
      }
  }
  return faces;
}

std::array<ImageF, 6> CubemapFaceAverages(const std::function<glm::dvec3(const glm::dvec3&)>& radiance, int size,
                                          int supersample, CubeLayout layout) {
  const int k = std::max(1, supersample), fine = size * k;
  std::array<ImageF, 6> faces;
  for (auto& f : faces) f = ImageF(size, size);
  const auto& frames = FaceFrames(layout);
  // One row of texels of one face per item; each texel's sum is its own, so any thread count
  // gives the same bytes.
  ParallelFor(6 * static_cast<std::size_t>(size), 1, [&](std::size_t begin, std::size_t end) {
    for (std::size_t item = begin; item < end; ++item) {
      const int face = static_cast<int>(item / size), row = static_cast<int>(item % size);
      const FaceFrame& f = frames[face];
      for (int col = 0; col < size; ++col) {
        glm::dvec3 sum(0.0);
        double weight = 0.0;
        for (int j = 0; j < k; ++j)
          for (int i = 0; i < k; ++i) {
            const int fc = col * k + i, fr = row * k + j;
            const double s = -1.0 + (fc + 0.5) * 2.0 / fine, t = -1.0 + (fr + 0.5) * 2.0 / fine;
            const double w = TexelSolidAngle(fc, fr, fine);
            sum += w * radiance(glm::normalize(f.n + s * f.u + t * f.v));
            weight += w;
          }
        faces[face].at(col, row) = glm::vec3(sum / weight);
      }
    }
  });
  return faces;
}

std::unique_ptr<CubemapEnvironment> CubemapFromFunction(const std::function<glm::dvec3(const glm::dvec3&)>& radiance,
                                                       int size, CubeLayout layout, int supersample) {
  if (supersample <= 1)
    return std::make_unique<CubemapEnvironment>(CubemapFaceImages(radiance, size, layout), layout,
                                                "cubemap from a function 6x" + std::to_string(size) + "^2");
  return std::make_unique<CubemapEnvironment>(CubemapFaceAverages(radiance, size, supersample, layout), layout,
                                              "cubemap from a function 6x" + std::to_string(size) + "^2, texels "
                                              "averaged over " + std::to_string(supersample) + "^2 sub-texels");
}

namespace {

/// Every file folder/<name>.<ext> with an extension a face may have.
std::vector<std::string> FaceFiles(const std::string& folder, const char* name) {
  std::vector<std::string> found;
  for (const char* ext : {".jpg", ".jpeg", ".png", ".hdr", ".exr", ".JPG", ".PNG", ".HDR", ".EXR"}) {
    const fs::path p = fs::path(folder) / (std::string(name) + ext);
    std::error_code ec;
    if (fs::exists(p, ec)) found.push_back(p.string());
  }
  return found;
}

/// The one file folder/<name>.<ext> for a face; Error if none or several.
std::string FindFace(const std::string& folder, const char* name) {
  const std::vector<std::string> found = FaceFiles(folder, name);
  if (found.empty())
    throw Error(folder + ": missing face '" + name +
                "' (expected posx negx posy negy posz negz as .jpg, .png, .hdr or .exr)");
  if (found.size() > 1)
    throw Error(folder + ": face '" + name + "' exists in several formats (" + found[0] + ", " +
                found[1] + "; expected exactly one)");
  return found[0];
}

/// The index in kFaceNames of the face named `stem` in any case, or -1.
int FaceIndex(std::string stem) {
  for (char& c : stem) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (int k = 0; k < 6; ++k)
    if (stem == kFaceNames[k]) return k;
  return -1;
}

}  // namespace

void RefuseCubemapFace(const std::string& path) {
  const int face = FaceIndex(fs::path(path).stem().string());
  if (face < 0) return;
  std::string folder = fs::path(path).parent_path().string();
  if (folder.empty()) folder = ".";
  for (int k = 0; k < 6; ++k)
    if (k != face && FaceFiles(folder, kFaceNames[k]).empty()) return;  // not beside its five siblings
  int w = 0, h = 0;
  ImageSize(path, w, h);
  if (w != h) return;  // a panorama that happens to be named like a face
  throw Error(path + ": is the " + kFaceNames[face] + " face of the cubemap in " + folder +
              " (expected the folder: --env " + folder + ")");
}

std::array<std::string, 6> CheckCubemapFolder(const std::string& folder, int* face_size) {
  std::array<std::string, 6> paths;
  for (int k = 0; k < 6; ++k) paths[k] = FindFace(folder, kFaceNames[k]);
  // Every size from the headers, before any pixel is decoded.
  int size = 0;
  for (int k = 0; k < 6; ++k) {
    int w = 0, h = 0;
    ImageSize(paths[k], w, h);
    if (w != h)
      throw Error(paths[k] + ": face is " + std::to_string(w) + "x" + std::to_string(h) +
                  " (expected a square face)");
    if (w > kMaxFaceSize)
      throw Error(paths[k] + ": face of " + std::to_string(w) + "x" + std::to_string(h) +
                  " is too large (at most " + std::to_string(kMaxFaceSize) + " per side)");
    if (k == 0) size = w;
    if (w != size)
      throw Error(paths[k] + ": face is " + std::to_string(w) + "x" + std::to_string(h) +
                  " but " + paths[0] + " is " + std::to_string(size) + "x" + std::to_string(size) +
                  " (expected six faces of one size)");
  }
  if (face_size) *face_size = size;
  return paths;
}

std::unique_ptr<Environment> LoadCubemap(const std::string& folder, CubeLayout layout) {
  int size = 0;
  const std::array<std::string, 6> paths = CheckCubemapFolder(folder, &size);
  const LdrDecode decode = layout == CubeLayout::kGames202 ? LdrDecode::kGamma22 : LdrDecode::kSrgb;
  std::array<ImageF, 6> faces;
  SanitizeCounts fixed;
  for (int k = 0; k < 6; ++k) {
    faces[k] = LoadImageLinear(paths[k], decode);
    const SanitizeCounts c = SanitizeRadiance(faces[k]);
    fixed.non_finite += c.non_finite, fixed.negative += c.negative, fixed.enormous += c.enormous;
  }
  if (fixed.total() > 0) Warn(folder + ": " + DescribeSanitized(fixed));
  const std::string ext = fs::path(paths[0]).extension().string();
  const std::string description =
      "cubemap " + folder + " 6x" + std::to_string(size) + "^2 (" + ext.substr(1) +
      (layout == CubeLayout::kGames202 ? ", course face mapping, pow 2.2" : "") + ")";
  return std::make_unique<CubemapEnvironment>(std::move(faces), layout, description);
}

}  // namespace prt
