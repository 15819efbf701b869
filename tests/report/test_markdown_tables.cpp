// The Markdown tables prt writes (report.md, stability/report.md), rendered by GitHub's own
// renderer, Debian's cmark-gfm (gfm_html.h): every row keeps its columns and a `|` in a cell's
// text shows as `|` (core/markdown_table.h).
#include <doctest/doctest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "core/atomic_file.h"
#include "core/markdown_table.h"
#include "core/output_folder.h"
#include "core/text.h"
#include "precompute/sample_rule.h"
#include "report/report_write.h"
#include "report/stability.h"
#include "tests/report/gfm_html.h"
#include "tests/test_process.h"
#include "wavelet/study.h"

namespace {

using prt::test::Cell;
using prt::test::Elements;
using prt::test::HtmlTable;
using prt::test::TableWith;
using prt::test::Tables;

// Strings with pipes in every place a table cell holds text (the mode, the noise method).
const std::string kMode = "shadowed | a|b";
const std::string kMethod = "stratified | `64|128` dirs";

/// A small ReportData of made-up numbers with every optional study, so that report.md holds
/// every table WriteReport can write. Sweep: one sampler, 16 and 64 directions, lmax 1 and 2.
prt::ReportData SyntheticReport() {
  prt::ReportData d;
  d.scene = "scene | one";
  d.environment = "sky";
  d.vertices = 100;
  d.max_lmax = 2;
  d.bvh_seconds = 0.001;
  for (int samples : {16, 64})
    for (int lmax : {1, 2}) {
      prt::SweepRow r;
      r.mode = kMode, r.sampler = "fibonacci";
      r.samples = r.directions = samples;
      r.lmax = lmax;
      r.time.median = r.time.min = r.time.max = 0.001 * samples;
      r.time.samples = 5;
      r.sampling = {0.1, 0.2, 1.6 / samples};  // above 1%: "not reached"
      r.total = {0.1, 0.2, 0.2};
      r.psnr = 30;
      d.rows.push_back(r);
    }
  prt::ModeBaseline b;
  b.mode = kMode;
  b.reference_seconds = 2, b.reference_rms_error = 0.01, b.reference_rms_radiance = 1, b.reference_samples = 1024;
  b.converged_seconds = 1, b.converged_samples = 4096, b.converged_self_error = 0.015;
  b.truncation = {0.5, 0.2, 0.1};
  d.baselines.push_back(b);
  prt::LightRow light;
  light.face_size = 8, light.supersample = 2, light.coeff_error = 0.05;
  light.time.median = light.time.min = light.time.max = 0.01;
  d.light.push_back(light);

  prt::GlossyStudy g;
  g.ks = 0.5, g.samples = 256, g.lobe_samples = 128, g.reference_samples = 1024;
  prt::GlossyExponent e;
  e.exponent = 10, e.share_lmax = 2;
  e.unshadowed = {1.25, 0.01, 0.3, 2, 2, 0.05};
  e.shadowed = {2.5, 0.02, 0.4, -1, 2, 0.2};
  g.exponents.push_back(e);
  for (prt::TransportMode mode : {prt::TransportMode::kUnshadowed, prt::TransportMode::kShadowed})
    for (int lmax : {1, 2}) g.vector_rows.push_back({mode, 10, lmax, 0.1, {0.1, 0.2, 0.3}, {0.1, 0.2, 0.4 / lmax}, 0.8});
  for (int lmax : {1, 2})
    g.matrix_rows.push_back({10, lmax, 0.2, 4096, {0.1, 0.2, 0.35}, {0.1, 0.2, 0.45}, {0.1, 0.2, 0.1}, {0.1, 0.2, 0.2}});
  d.glossy = g;

  prt::WaveletStudy w;
  w.scene = "scene | one", w.environment = "sky", w.vertices = 100;
  w.config.modes = {prt::TransportMode::kShadowed};
  w.references.push_back({prt::TransportMode::kShadowed, 1024, 3.0, 0.01});
  prt::BasisRow sh;
  sh.lmax = 2, sh.directions = 512, sh.bytes_per_vertex = 36, sh.seconds = 0.1, sh.total = {0.1, 0.2, 0.3};
  prt::BasisRow wav = sh;
  wav.wavelet = true, wav.lmax = 0, wav.budget = 64, wav.kept = 60, wav.kept_energy = 0.9, wav.bytes_per_vertex = 264;
  wav.total = {0.1, 0.2, 0.25};
  w.rows = {sh, wav};
  d.basis_study = prt::WaveletStudyResults(w);

  prt::NoiseStudy n;
  n.vertices = 100, n.seen_vertices = 50, n.pixels = 1000;
  prt::NoiseRow nr;
  nr.method.name = kMethod;
  nr.seconds = 0.123, nr.rays = 6400, nr.rms_error = 0.02;
  nr.frame.max_abs = 7, nr.frame.pixels_over_one = 10;
  n.rows.push_back(nr);
  d.noise = n;
  return d;
}

prt::StabilityCase Case(std::string name, std::string checks, double figure, double limit, bool pass,
                        std::string note = "", bool at_least = false) {
  return {std::move(name), std::move(checks), figure, limit, at_least, pass, std::move(note)};
}

/// Stability cases with the names, checks and notes of the real ones whose text holds a `|`
/// (src/report/stability.cpp; running them takes most of a minute), plus one that fails.
std::vector<prt::StabilityCase> StabilityCasesWithPipes() {
  std::vector<prt::StabilityCase> cases;
  for (int lmax : {32, 64})
    cases.push_back(Case("orthonormality_lmax" + std::to_string(lmax),
                         "max |<Y_i,Y_j> - delta_ij| on the exact Gauss rule, bands 0.." + std::to_string(lmax), 1.7e-14,
                         1e-12, true));
  for (int lmax : {32, 64, 100, 200}) {
    const std::string at = "_lmax" + std::to_string(lmax);
    cases.push_back(Case("rotation_equivariance" + at, "max |Y(R d) - D(R) Y(d)| over 16 random d, random R", 1e-14,
                         1e-11, true));
    cases.push_back(Case("rotation_orthogonality" + at,
                         lmax <= 64 ? std::string("max |D_l D_l^T - I| over bands")
                                    : "max |D_l D_l^T - I| over bands 0, 7, 14, ... and the last (a band costs (2l+1)^3)",
                         8.9e-16, 1e-12, true));
  }
  for (const char* scale : {"0.0001", "10000"})
    cases.push_back(Case(std::string("convex_scale_") + scale,
                         std::string("a lone convex sphere of radius ") + scale +
                             " far from the origin: shadowed transport equals unshadowed (max |difference|)",
                         0, 0, true, "642 of 642 vertices unoccluded"));
  cases.push_back(Case("basis_finite_lmax200",
                       "every Y_k to lmax 200 finite at both poles and at z = +-(1 - 1e-15) (1 = yes)", 1, 1, true,
                       "largest |Y| 12.34", true));
  cases.push_back(Case("made_up_failure", "a case that fails, `|x|` in code", 2, 1, false, "|a| > 1"));
  return cases;
}

}  // namespace

TEST_SUITE("report") {
  TEST_CASE("markdown table: a cell escapes each pipe and turns line breaks into spaces") {
    CHECK(prt::MarkdownCell("plain text, `code` and **bold**") == "plain text, `code` and **bold**");
    CHECK(prt::MarkdownCell("max |<Y_i,Y_j> - delta_ij|") == "max \\|<Y_i,Y_j> - delta_ij\\|");
    CHECK(prt::MarkdownCell("`a|b`") == "`a\\|b`");           // inside a code span too
    CHECK(prt::MarkdownCell("a\\|b") == "a\\\\|b");          // the table removes only the added backslash
    CHECK(prt::MarkdownCell("||") == "\\|\\|");
    CHECK(prt::MarkdownCell("one\ntwo\r\nthree\rfour") == "one two three four");
    CHECK(prt::MarkdownCell("") == "");
    CHECK(prt::MarkdownRow({"a", "b|c", ""}) == "| a | b\\|c |  |\n");
    CHECK(prt::MarkdownHeader({"m", "n|o"}) == "| m | n\\|o |\n|---|---|\n");
    CHECK(prt::MarkdownHeader({"m", "n"}, {prt::MarkdownAlign::kDefault, prt::MarkdownAlign::kRight}) ==
          "| m | n |\n|---|---:|\n");
    CHECK_THROWS_AS(prt::MarkdownHeader({"m", "n"}, {prt::MarkdownAlign::kRight}), std::logic_error);
  }

  TEST_CASE("markdown table: cmark-gfm shows a cell as its text alone shows as a paragraph" *
            prt::test::NeedsCmarkGfm()) {
    // Pipes bare, in code spans, after a backslash (escaped or not), at the ends, doubled.
    const std::vector<std::string> texts = {
        "max |<Y_i,Y_j> - delta_ij|", "`a|b`", "a\\|b", "`a\\|b`", "a\\\\|b", "`a\\\\|b`", "|", "||x||",
        "**FAIL** |x| and `|`", "a | b\nc", "<= 1e-12", "50% & more"};
    std::string md;
    for (const std::string& text : texts) {
      std::string paragraph = text;
      for (char& c : paragraph) c = c == '\n' ? ' ' : c;
      md += paragraph + "\n\n" + prt::MarkdownHeader({"text", "after"}) + prt::MarkdownRow({text, "end"}) + "\n";
    }
    const std::string html = prt::test::RenderGfm(md);
    const std::vector<HtmlTable> tables = Tables(html);
    const std::vector<std::string> paragraphs = Elements(html, "p", 0, html.size());
    REQUIRE(tables.size() == texts.size());
    REQUIRE(paragraphs.size() == texts.size());
    // The cells' inner HTML, not just their text: a code span stays a code span.
    std::size_t at = 0;
    for (std::size_t i = 0; i < texts.size(); ++i) {
      CAPTURE(texts[i]);
      const std::size_t table = html.find("<table>", at), end = html.find("</table>", table);
      const std::vector<std::string> cells = Elements(html, "td", table, end);
      REQUIRE(cells.size() == 2);
      CHECK(cells[0] == paragraphs[i]);
      CHECK(cells[1] == "end");
      CHECK(tables[i].header == std::vector<std::string>{"text", "after"});
      at = end;
    }
  }

  TEST_CASE("markdown table: report.md from WriteReport renders every table whole" * prt::test::NeedsCmarkGfm()) {
    const std::string dir = prt::test::ScratchDir("markdown_report");
    const prt::ReportData d = SyntheticReport();
    {
      prt::OutputFolder folder(dir, {"report",
                                     {"report.md", "report.csv", "error_vs_time.png", "glossy_error_vs_lmax.png",
                                      "basis_error.png"},
                                     false});
      prt::WriteReport(folder, d);
      folder.Finish();
    }
    // Each table is found by a column of its own and read by column name, so columns added
    // beside these (the timing's) leave the test as it is.
    const std::vector<HtmlTable> tables = Tables(prt::test::RenderGfmFile(dir + "/report.md"));
    CHECK(tables.size() >= 11);
    for (const HtmlTable& t : tables) {
      CAPTURE(t.header.front());
      for (const auto& row : t.rows) CHECK(row.size() == t.header.size());
      for (const auto& name : t.header) CHECK(!name.empty());
    }
    const HtmlTable& baselines = TableWith(tables, "reference own RMS error");
    REQUIRE(baselines.rows.size() == 1);
    CHECK(Cell(baselines, 0, "mode") == kMode);
    CHECK(Cell(baselines, 0, "reference directions") == "1024");
    CHECK(Cell(baselines, 0, "converged vs half-size run") == "1.5%");
    const HtmlTable& convergence = TableWith(tables, "slope vs directions");
    REQUIRE(convergence.rows.size() == 1);
    CHECK(Cell(convergence, 0, "mode") == kMode);
    CHECK(Cell(convergence, 0, "sampler") == "fibonacci");
    CHECK(Cell(convergence, 0, "time to 1% total error (any lmax)") == "not reached (lowest 20%)");
    const HtmlTable& truncation = TableWith(tables, "PSNR dB");  // the highest count's rows
    REQUIRE(truncation.rows.size() == 2);
    CHECK(Cell(truncation, 1, "mode") == kMode);
    CHECK(Cell(truncation, 1, "sampler") == "fibonacci");
    CHECK(Cell(truncation, 1, "lmax") == "2");
    CHECK(Cell(truncation, 1, "total relative") == "20%");
    CHECK(Cell(truncation, 1, "PSNR dB") == "30.0");
    const HtmlTable& rule = TableWith(tables, "rule default");
    REQUIRE(rule.rows.size() == 2);
    CHECK(rule.header.size() == 7);  // lmax, truncation, 16, 64, need, min, default
    CHECK(Cell(rule, 0, "lmax") == "1");
    CHECK(Cell(rule, 0, "rule default") == std::to_string(prt::DefaultSamples(1, prt::Sampler::kFibonacci)));
    const HtmlTable& light = TableWith(tables, "coefficient error");
    REQUIRE(light.rows.size() == 1);
    CHECK(Cell(light, 0, "sub-texels") == "2^2");
    CHECK(Cell(light, 0, "coefficient error") == "0.05");
    // Glossy: each reference's seconds and own error in a column of its own.
    const HtmlTable& glossy = TableWith(tables, "reference own error (shadowed)");
    REQUIRE(glossy.rows.size() == 1);
    CHECK(Cell(glossy, 0, "N") == "10");
    CHECK(Cell(glossy, 0, "shadowed: needed") == "> 2");
    CHECK(Cell(glossy, 0, "lobe / radiance") == "40%");
    CHECK(Cell(glossy, 0, "reference seconds (unshadowed)") == "1.25");
    CHECK(Cell(glossy, 0, "reference seconds (shadowed)") == "2.50");
    CHECK(Cell(glossy, 0, "reference own error (unshadowed)") == "1%");
    CHECK(Cell(glossy, 0, "reference own error (shadowed)") == "2%");
    const HtmlTable& vector = TableWith(tables, "lobe energy in bands");
    REQUIRE(vector.rows.size() == 4);
    CHECK(vector.rows[3] == std::vector<std::string>{"shadowed", "10", "2", "0.1", "30%", "20%", "80%"});
    const HtmlTable& matrices = TableWith(tables, "matrix MiB");
    REQUIRE(matrices.rows.size() == 2);
    CHECK(Cell(matrices, 0, "matrix MiB") == "0.00391");
    // Basis.
    const HtmlTable& references = TableWith(tables, "reference own error");
    CHECK(references.rows == std::vector<std::vector<std::string>>{{"shadowed", "1024", "3.00", "1%"}});
    const HtmlTable& basis = TableWith(tables, "transport energy kept");
    REQUIRE(basis.rows.size() == 2);
    // The directions a vertex in a column of their own, beside the seconds.
    CHECK(basis.rows[1] == std::vector<std::string>{"shadowed", "wavelet", "64 terms", "60", "264", "512", "0.1", "25%",
                                                    "0.2", "90%"});
    // Visible noise: the method's name with its pipes, one in a code span.
    const HtmlTable& noise = TableWith(tables, "pixels > 1 level");
    REQUIRE(noise.rows.size() == 1);
    CHECK(noise.rows[0] == std::vector<std::string>{"stratified | 64|128 dirs", "7", "1.000%", "2.000%", "6400", "0.123"});
  }

  TEST_CASE("markdown table: the stability table keeps six columns and reads pass or FAIL" *
            prt::test::NeedsCmarkGfm()) {
    const std::vector<prt::StabilityCase> cases = StabilityCasesWithPipes();
    const std::string path = prt::test::ScratchDir("markdown_stability") + "/report.md";
    prt::WriteFileAtomic(path, prt::StabilityMarkdown(cases));
    const std::vector<HtmlTable> t = Tables(prt::test::RenderGfmFile(path));
    REQUIRE(t.size() == 1);
    CHECK(t[0].header == std::vector<std::string>{"case", "what is checked", "measured", "limit", "result", "note"});
    CHECK(t[0].rows.size() == cases.size());
    for (std::size_t i = 0; i < cases.size() && i < t[0].rows.size(); ++i) {
      const prt::StabilityCase& c = cases[i];
      const std::vector<std::string>& row = t[0].rows[i];
      CAPTURE(c.name);
      REQUIRE(row.size() == 6);
      CHECK(row[0] == c.name);
      // Code spans lose their backticks in the rendered text.
      std::string checks = c.checks;
      for (std::size_t at; (at = checks.find('`')) != std::string::npos;) checks.erase(at, 1);
      CHECK(row[1] == checks);
      CHECK(row[2] == prt::Formatted("%.4g", c.figure));
      CHECK(row[3] == (c.at_least ? ">= " : "<= ") + prt::Formatted("%.3g", c.limit));
      CHECK(row[4] == (c.pass ? "pass" : "FAIL"));
      CHECK(row[5] == c.note);
    }
  }
}
