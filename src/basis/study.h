#pragma once
/// \file
/// A basis's own study for `prt report --basis NAME`: what the report knows of it. A basis that
/// has one (Basis::Study(), nullptr for one without) measures itself in its own folder (the
/// wavelets: wavelet/study.h, SH against Haar wavelets at several budgets), and the report runs
/// it, writes its rows, its section and its plot, and adds its cases to the stability suite,
/// all through this interface, so that report/ and app/ never name a basis's types.
///
/// The report writes what a study gives it as it is: the study's rows go in report.csv after
/// the report's own, its section in report.md after the glossy one, its plot to
/// basis_error.png (report/report_write.h).

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "basis/stability_case.h"
#include "core/image.h"
#include "env/environment.h"
#include "geometry/mesh.h"

namespace prt {

/// What the report hands a study to run it on.
struct StudyInputs {
  const Mesh& mesh;            ///< the scene: --mesh's, else the study's OwnScene (with the scene edits)
  std::string scene;           ///< its name in report.md
  const Environment& env;      ///< the report's light
  std::string environment;     ///< the --env value, in report.md
  bool quick = false;          ///< --quick: the study kept short
  int bounces = 1;             ///< --bounces, for the interreflection rows
  std::uint64_t seed = 1;      ///< --seed
};

/// The size of the scene a study's stability cases run on: a knot of `segments` x `sides`
/// standing on a ground of `ground` x `ground` quads (geometry/procedural.h, KnotOverGround).
/// All 0: each study's own measured scene, the one its limits were set from.
struct StudySceneSize {
  int segments = 0;
  int sides = 0;
  int ground = 0;
};

/// A study's measurements, as the report writes them.
class StudyResults {
 public:
  virtual ~StudyResults() = default;
  /// report.csv rows, each ending in a newline, in the report's columns up to and including
  /// bytes_per_vertex (report/report_write.cpp: mode .. matrix_bytes, basis, budget,
  /// bytes_per_vertex); the report adds its empty timing columns.
  virtual std::string CsvRows() const = 0;
  /// How many rows CsvRows writes (report.md's count of all measurements).
  virtual std::size_t RowCount() const = 0;
  /// Their `path` column's values in words, as report.md names them ("basis-sh or basis-wavelet").
  virtual std::string CsvPaths() const = 0;
  /// The report.md section, from its "## " heading on. `times_trusted`: the report's timing
  /// found its times trustworthy (report/report_sweep.h, TimesTrusted); if not, the section
  /// quotes the work done instead of seconds.
  virtual std::string Markdown(bool times_trusted) const = 0;
  /// basis_error.png (`times_trusted` as for Markdown).
  virtual Image8 Plot(bool times_trusted) const = 0;
};

/// A basis's study: its scene, the run, and its cases of the stability suite.
class BasisStudy {
 public:
  virtual ~BasisStudy() = default;
  /// What `prt help report` says of it: after the basis names in --basis's help ("wavelet adds
  /// a section ..."), and a sentence or more of the command's description ("With --basis
  /// wavelet ...").
  virtual std::string ReportOptionHelp() const = 0;
  virtual std::string ReportHelp() const = 0;
  /// The scene the study runs on when the report is given no --mesh (`quick`: a smaller one),
  /// and its name in report.md.
  virtual Mesh OwnScene(bool quick) const = 0;
  virtual std::string OwnSceneName(bool quick) const = 0;
  /// Runs the study (progress on the run summary).
  virtual std::unique_ptr<const StudyResults> Run(const StudyInputs& inputs) const = 0;
  /// Appends its cases of `prt report --stability` (none by default), run on a scene of
  /// `scene`'s size.
  virtual void StabilityCases(std::vector<StabilityCase>& /*out*/, const StudySceneSize& /*scene*/) const {}
};

}  // namespace prt
