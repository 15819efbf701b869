#pragma once
/// \file
/// The wavelet basis's own study, which `prt report --basis wavelet` runs through the study
/// interface (basis/study.h, WaveletBasisStudy below): spherical harmonics against Haar wavelets
/// (all-frequency PRT [1], wavelet/transport.h) on one scene, each scored against
/// prt reference's ground truth (precompute/reference.h) by the per-vertex relative RMS error of
/// the outgoing radiance, beside what it costs: the transport's memory per vertex and its
/// precompute time. Per transport mode (shadowed; with the full report interreflection too):
///   SH        at each lmax of `sh_lmax`, `sh_samples` fibonacci directions per vertex; memory
///             (lmax+1)^2 floats per channel (1 channel shadowed, 3 with interreflection, whose
///             bounces are coloured);
///   wavelets  at each budget of `budgets`: a cube of 6 F^2 texels, split^2 jittered rays per
///             texel, each vertex keeping its `budget` most important coefficients; memory
///             WaveletTransport::Bytes() (the faces' means as floats, each detail a 16-bit index
///             and a 16-bit value, a step and an offset per vertex); with interreflection the
///             bounced light in SH at `bounce_lmax` from `sh_samples` directions, whose floats are
///             counted too.
/// Every run is timed whole (BVH build, rays, transform and selection, the bounce pass), the
/// fastest of repeats as TimedTransport times (basis/timed_transport.h). The light is the
/// unturned environment: SH projected once at the highest lmax and cut to each run's bands; the
/// cube resampled once (wavelet/light_cube.h) with every light coefficient kept.
/// study_write.cpp writes its report.md section, report.csv rows and basis_error.png.
///
/// The stability suite (report/stability.h) uses the same measurement for its wavelet cases
/// (WaveletAgreementCases below).
///
/// References
/// [1] Ng, Ramamoorthi, Hanrahan, "All-Frequency Shadows Using Non-linear Wavelet Lighting
///     Approximation", SIGGRAPH 2003.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "basis/stability_case.h"
#include "basis/study.h"
#include "core/image.h"
#include "env/environment.h"
#include "geometry/mesh.h"
#include "precompute/error_metrics.h"
#include "precompute/transport.h"
#include "wavelet/selection.h"
#include "wavelet/transport.h"

namespace prt {

struct WaveletStudyConfig {
  std::vector<TransportMode> modes = {TransportMode::kShadowed, TransportMode::kInterreflection};
  std::vector<int> sh_lmax = {2, 4, 8, 16};                 ///< ascending
  int sh_samples = 16384;                                   ///< fibonacci directions per vertex
  std::vector<int> budgets = {64, 128, 256, 512, 1024, 2048};  ///< ascending
  int face_size = WaveletOptions{}.face_size;               ///< F, as --cube-size's default
  int split = WaveletOptions{}.split;                       ///< rays per texel: split x split
  /// prt's selection (WaveletOptions' default).
  Selection selection = WaveletOptions{}.selection;
  int bounce_lmax = 4;                                      ///< the wavelets' bounces in SH
  int bounces = 1;
  int reference_samples = 16384;
  std::uint64_t seed = 1;
  bool progress = true;                                     ///< a run-summary line per reference and mode
};

/// The study `prt report --basis wavelet` runs (WaveletBasisStudy): `quick` keeps it short
/// (shadowed only, SH lmax 2, 4, 8 from 4096 directions, budgets 64, 256, 512 (the default)
/// and 1024, a 4096-direction reference).
WaveletStudyConfig MakeWaveletStudyConfig(bool quick, int bounces, std::uint64_t seed);

/// The scene the wavelet basis was measured on: a (2, 3) torus knot of `segments` x `sides`
/// standing 2 high on an 8 x 8 ground of `ground` x `ground` quads, fine enough for a small
/// sun's shadow to show between vertices. MakeSunScene() is the measured one (192 x 20 on
/// 40 x 40, 5,521 vertices).
Mesh MakeSunScene(int segments = 192, int sides = 20, int ground = 40);

/// One (mode, basis, lmax or budget).
struct BasisRow {
  TransportMode mode = TransportMode::kShadowed;
  bool wavelet = false;
  int lmax = 0;                 ///< SH: its lmax; wavelets: the bounces' (interreflection), else 0
  int budget = 0;               ///< wavelets: coefficients kept per vertex, at most
  double kept = 0;              ///< wavelets: mean coefficients kept (zeros are never kept)
  double kept_energy = 0;       ///< wavelets: mean share of the transport's energy kept
  int directions = 0;           ///< SH: directions per vertex; wavelets: rays per vertex
  double bytes_per_vertex = 0;  ///< transport memory over the vertex count
  double seconds = 0;           ///< the whole transport, fastest of repeats
  VertexError total;            ///< against the reference
};

/// The reference of one mode.
struct BasisReference {
  TransportMode mode = TransportMode::kShadowed;
  int samples = 0;
  double seconds = 0;
  double own_error = 0;  ///< its two halves' estimate, relative to its RMS radiance
};

struct WaveletStudy {
  std::string scene, environment;
  int vertices = 0;
  WaveletStudyConfig config;
  std::vector<BasisReference> references;
  std::vector<BasisRow> rows;  ///< per mode: SH rows by lmax, then wavelet rows by budget
};

/// Runs the study on `mesh` under `env` (progress on the run summary).
WaveletStudy RunWaveletStudy(const Mesh& mesh, const Environment& env, const WaveletStudyConfig& config);

/// The report.md section (heading, how to read it, the table, what equal memory buys).
/// `times_trusted`: the report's timing found its times trustworthy (TimesTrusted,
/// report/report_sweep.h); if not, the conclusion quotes rays traced per vertex instead of seconds, and
/// the table's seconds are marked untrusted, as error_vs_time.png turns to rays.
std::string WaveletMarkdown(const WaveletStudy& study, bool times_trusted);
/// report.csv rows in the report's columns (report/report_write.cpp) plus basis, budget,
/// bytes_per_vertex.
std::string WaveletCsvRows(const WaveletStudy& study);
/// basis_error.png: error against bytes per vertex (left) and against seconds (right; rays traced
/// per vertex when the times are not trusted), a line per basis and mode.
Image8 WaveletPlot(const WaveletStudy& study, bool times_trusted);

/// The stability suite's wavelet cases: MakeSunScene(segments, sides, ground) (by default the
/// measured scene) under the default sky, wavelets at the
/// default cube and budget (WaveletOptions' defaults), shadowed and with one bounce,
/// against a 4096-direction reference (16 s on 2 cores, 10 of them the references).
void WaveletAgreementCases(std::vector<StabilityCase>& out, int segments = 192, int sides = 20, int ground = 40);

/// `study` as the report writes it (basis/study.h): its rows, WaveletMarkdown, WaveletCsvRows and
/// WaveletPlot.
std::unique_ptr<const StudyResults> WaveletStudyResults(WaveletStudy study);

/// The study as the report sees it (basis/study.h), WaveletBasis's Study(): its own scene is
/// MakeSunScene() (MakeSunScene(96, 12, 20) with --quick), its configuration
/// MakeWaveletStudyConfig, its stability cases WaveletAgreementCases (on the measured scene
/// unless a size is given).
const BasisStudy& WaveletBasisStudy();

}  // namespace prt
