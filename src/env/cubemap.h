#pragma once
/// \file
/// A cube-map environment: six square faces of linear radiance (see cube_faces.h for the face
/// frames and exact texel solid angles).

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/image.h"
#include "env/cube_faces.h"
#include "env/environment.h"

namespace prt {

/// Largest face side accepted (a 16K face would need 3 GiB of floats per cube).
constexpr int kMaxFaceSize = 8192;

class CubemapEnvironment : public Environment {
 public:
  /// Faces in kFaceNames order (posx negx posy negy posz negz), all square and of one size.
  CubemapEnvironment(std::array<ImageF, 6> faces, CubeLayout layout, std::string description);

  glm::dvec3 Radiance(const glm::dvec3& dir) const override;
  std::size_t RowCount() const override { return 6 * static_cast<std::size_t>(size_); }
  void Row(std::size_t i, std::vector<Texel>& out) const override;
  std::string Describe() const override { return description_; }

  int face_size() const { return size_; }

 private:
  std::array<ImageF, 6> faces_;
  std::array<FaceFrame, 6> frames_;
  int size_;
  std::vector<double> solid_angles_;  ///< size^2, shared by all faces
  std::string description_;
};

/// The six size^2 faces (in kFaceNames order, as `layout` maps them) whose texel centres hold
/// `radiance(direction)`.
std::array<ImageF, 6> CubemapFaceImages(const std::function<glm::dvec3(const glm::dvec3&)>& radiance, int size,
                                        CubeLayout layout = CubeLayout::kStandard);

/// The six size^2 faces whose texels each hold the average of `radiance` over the texel's solid
/// angle, as a filtered cubemap stores it: the mean of supersample x supersample sub-texel
/// centre samples, each weighted by its exact solid angle (cube_faces.h). Unlike a texel-centre
/// sample, a feature smaller than a texel (a sun disk) keeps its power whichever texels it
/// falls on. supersample = 1 is CubemapFaceImages.
std::array<ImageF, 6> CubemapFaceAverages(const std::function<glm::dvec3(const glm::dvec3&)>& radiance, int size,
                                          int supersample, CubeLayout layout = CubeLayout::kStandard);

/// A size^2 cubemap whose texels hold `radiance(direction)` at their centres (supersample 1) or
/// averaged over them (CubemapFaceAverages): for tests, benchmarks and resolution studies.
std::unique_ptr<CubemapEnvironment> CubemapFromFunction(const std::function<glm::dvec3(const glm::dvec3&)>& radiance,
                                                       int size, CubeLayout layout = CubeLayout::kStandard,
                                                       int supersample = 1);

/// The six face files of a cubemap folder, in kFaceNames order, checked as far as their headers
/// go: each face present once, square, of one size (stored in `face_size`), not oversized.
/// Throws Error as LoadCubemap does; decodes no pixel.
std::array<std::string, 6> CheckCubemapFolder(const std::string& folder, int* face_size = nullptr);

/// Refuses one face of a cubemap given where an image environment is expected: `path` is a
/// square image whose file stem is a face name (kFaceNames, any case) and whose folder holds the
/// five other faces as LoadCubemap finds them. Read as an equirectangular panorama it would be a
/// stretched, wrong light, so this throws Error `<path>: is the posx face of the cubemap in
/// <folder> (expected the folder: --env <folder>)`. Any other file (a lone square posx.png, a
/// non-square one) passes; only the header of a face-named file with siblings is read.
void RefuseCubemapFace(const std::string& path);

/// Loads `folder/{posx,negx,posy,negy,posz,negz}.{jpg,png,hdr,exr}`. Throws Error naming the
/// folder or face for a missing or ambiguous face, faces of different sizes, non-square or
/// oversized faces (checked before decoding), or an unreadable image. LDR faces are decoded
/// with the exact sRGB curve, or pow(x, 2.2) under the course layout; non-finite, negative and
/// enormous texels are sanitised with a warning.
std::unique_ptr<Environment> LoadCubemap(const std::string& folder, CubeLayout layout);

}  // namespace prt
