#pragma once
/// \file
/// Cube-map face geometry: which direction each texel of each face looks along, and how much
/// of the sphere it covers.
///
/// A face is a frame (N, U, V): the texel at face coordinates (s, t) in [-1, 1]^2 looks along
/// normalize(N + s U + t V); image column 0 is at s = -1 and image row 0 at t = -1.
/// The standard table (OpenGL cube-map layout, CONVENTIONS.md) is checked by seam continuity.
/// The course's precompute code assigned the frames differently (posy/negy and posz/negz
/// swapped, posx mirrored), so every course `light.txt` has up and down swapped; that table is
/// kept to reproduce those files and must be asked for (`--games202-faces`).
///
/// Texel solid angle, exactly [1]: the area on the unit sphere of the face rectangle
/// [x0, x1] x [y0, y1] at distance 1 is A(x0,y0) - A(x0,y1) - A(x1,y0) + A(x1,y1) with
/// A(x, y) = atan2(x y, sqrt(x^2 + y^2 + 1)). All texels of a cube sum to 4 pi.
///
/// References
/// [1] Driscoll, "Cubemap Texel Solid Angle", 2012 (derivation of A(x, y)).

#include <array>
#include <string>

#include <glm/vec3.hpp>

namespace prt {

struct FaceFrame {
  glm::dvec3 n, u, v;
};

enum class CubeLayout { kStandard, kGames202 };

/// Face file names in storage order: posx negx posy negy posz negz.
extern const std::array<const char*, 6> kFaceNames;

/// The frame of each face file (in kFaceNames order) under `layout`.
const std::array<FaceFrame, 6>& FaceFrames(CubeLayout layout);

/// Exact solid angle of the face rectangle [x0, x1] x [y0, y1] (face coordinates in [-1, 1]).
double FaceRectSolidAngle(double x0, double y0, double x1, double y1);

/// Solid angle of texel (col, row) of a size x size face.
double TexelSolidAngle(int col, int row, int size);

}  // namespace prt
