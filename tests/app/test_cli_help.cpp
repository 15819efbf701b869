// The command line as users meet it: every option a command accepts is in its help and in
// docs/CLI.md (both come from, or are checked against, the one table the parser uses), help is
// reachable three ways, and mistakes name the nearest valid spelling.
#include <doctest/doctest.h>

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "options/args.h"
#include "app/commands.h"
#include "cli/command_table.h"
#include "core/error.h"
#include "core/atomic_file.h"
#include "tests/test_process.h"

namespace prt {
namespace {

/// The section `## prt <command>` of docs/CLI.md, up to the next `## ` heading.
std::string DocSection(const std::string& doc, const std::string& command) {
  const std::string heading = "\n## prt " + command + "\n";
  const auto begin = doc.find(heading);
  if (begin == std::string::npos) return "";
  const auto end = doc.find("\n## ", begin + heading.size());
  return doc.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
}

/// True if `text` mentions option `name` as a whole word (`--out` is not found in `--outline`).
bool Mentions(const std::string& text, const std::string& name) {
  for (auto at = text.find(name); at != std::string::npos; at = text.find(name, at + 1)) {
    const char next = at + name.size() < text.size() ? text[at + name.size()] : ' ';
    if (!(std::isalnum(static_cast<unsigned char>(next)) || next == '-')) return true;
  }
  return false;
}

}  // namespace

TEST_SUITE("app") {
  TEST_CASE("cli: every option the parser accepts is in the command's help and in docs/CLI.md") {
    const std::string doc = ReadFile(test::SourceDir() + "/docs/CLI.md");
    for (const Command& c : Commands()) {
      CAPTURE(c.name);
      const CommandSpec spec = c.spec();
      const std::string help = FormatHelp(spec);
      const std::string section = DocSection(doc, c.name);
      CHECK_FALSE(section.empty());  // every command has its section
      for (const std::string& name : spec.Names()) {
        CAPTURE(name);
        CHECK(Mentions(help, name));
        CHECK(Mentions(section, name));
        // The parser accepts the name: a flag alone, any other option with a value.
        const OptionSpec* option = spec.Find(name);
        std::vector<std::string> tokens = {name};
        if (!option->value.empty()) tokens.push_back("1");
        CHECK_NOTHROW(Args(c.name, tokens, spec));
      }
      // ... and nothing else: a name outside the table is a usage error.
      CHECK_THROWS_AS(Args(c.name, {"--no-such-option"}, spec), UsageError);
    }
  }

  TEST_CASE("cli: reading an option the table does not list is a programming error") {
    Args args("light", {}, LightSpec());
    CHECK_THROWS_AS(args.String("--mesh"), std::logic_error);  // light takes no mesh
    CHECK_NOTHROW(args.String("--env"));
  }

  TEST_CASE("cli: unknown options and commands name the nearest valid one") {
    CHECK(NearestName("--sample", {"--samples", "--sampler", "--seed"}) == "--samples");
    CHECK(NearestName("--smaples", {"--samples", "--seed"}) == "--samples");
    CHECK(NearestName("rendr", {"render", "demo", "diff"}) == "render");
    CHECK(NearestName("--zzzzzz", {"--samples", "--seed"}).empty());  // nothing close: no guess
    CHECK(NearestName("lihgt", {"light", "bvh"}) == "light");          // a transposition is one typo
    CHECK(NearestName("ACES", {"srgb", "reinhard", "aces"}) == "aces");  // case does not count
    // A value of a short list: the nearest even a few letters off, if no other is as near and it
    // is at most half its own length away (rounded up).
    CHECK(NearestName("lite", {"light", "glossy"}).empty());
    CHECK(NearestChoice("lite", {"radiance", "light", "glossy"}) == "light");        // 3 of 5
    CHECK(NearestChoice("Lite", {"radiance", "light", "glossy"}) == "light");
    CHECK(NearestChoice("cose", {"default", "course"}) == "course");                 // 2 of 6
    CHECK(NearestChoice("abcd", {"abxy", "abzw"}).empty());                          // a tie: no guess
    CHECK(NearestChoice("abcd", {"zzzz", "abzw", "abxy", "abcx"}) == "abcx");        // nearer than the tie
    CHECK(NearestChoice("qqqqqq", {"light", "glossy"}).empty());                     // too far
    CHECK(NearestChoice("ligh", {"light", "glossy"}) == "light");                    // NearestName's first
    CHECK_THROWS_WITH_AS(Args("render", {"--sampels", "64"}, RenderSpec()),
                         "--sampels: unknown option (did you mean --samples?)", UsageError);

    const auto typo = test::RunPrt("render --sample 64");
    CHECK(typo.exit_code == 2);
    CHECK(typo.err == "prt: error: --sample: unknown option (did you mean --samples?) (see prt help render)\n");
    const auto command = test::RunPrt("rendr");
    CHECK(command.exit_code == 2);
    CHECK(command.err == "prt: error: 'rendr': unknown command (did you mean render?) (see prt help)\n");
    const auto help_typo = test::RunPrt("help rendr");
    CHECK(help_typo.exit_code == 2);
    CHECK(help_typo.err == "prt: error: 'rendr': unknown command (did you mean render?) (see prt help)\n");
    CHECK(test::RunPrt("--versoin").err.find("did you mean --version?") != std::string::npos);
    const auto version_extra = test::RunPrt("--version extra");
    CHECK(version_extra.exit_code == 2);
    CHECK(version_extra.out.empty());
    CHECK(test::RunPrt("bench lihgt").err.find("did you mean light?") != std::string::npos);
    const auto dash = test::RunPrt("diff a.png b.png -q");
    CHECK(dash.exit_code == 2);
    CHECK(dash.err.find("'-q': unknown option (options start with --)") != std::string::npos);
    const auto value = test::RunPrt("render --transport shadowd");
    CHECK(value.exit_code == 2);
    CHECK(value.err.find("did you mean shadowed?") != std::string::npos);
  }

  TEST_CASE("cli: prt help COMMAND, prt COMMAND --help and -h print the same full help") {
    const auto help = test::RunPrt("help render");
    CHECK(help.exit_code == 0);
    CHECK(help.out == FormatHelp(RenderSpec()));
    for (const char* scene_option : {"--mesh", "--env", "--lmax", "--transport", "--samples", "--view", "--size",
                                     "--tonemap", "--exposure", "--ssaa", "--eye", "--target", "--up", "--fov"})
      CHECK(Mentions(help.out, scene_option));
    CHECK(help.out.find("e.g. fibonacci 8192 at lmax 2") != std::string::npos);  // --samples follows --lmax
    for (const char* ask : {"render --help", "render -h", "render --out x --help"}) {
      CAPTURE(ask);
      const auto r = test::RunPrt(ask);
      CHECK(r.exit_code == 0);
      CHECK(r.out == help.out);
      CHECK(r.err.empty());
    }
    // The demo documents its own defaults.
    const auto demo = test::RunPrt("demo --help");
    CHECK(demo.out.find("--transport MODE") != std::string::npos);
    CHECK(demo.out.find("(default: interreflection)") != std::string::npos);
    CHECK(demo.out.find("(default: out/demo)") != std::string::npos);
    const auto list = test::RunPrt("help");
    for (const Command& c : Commands()) CHECK(list.out.find(std::string("  ") + c.name + " ") != std::string::npos);
  }

  TEST_CASE("cli: a value that is not a number says so, one out of range gives the range") {
    const auto check = [](const std::string& value, const std::string& problem) {
      CAPTURE(value);
      Args args("render", {"--samples", value}, RenderSpec());
      const std::string message = "--samples: '" + value + "' " + problem + " (expected an integer from 1 to 100)";
      CHECK_THROWS_WITH_AS(args.Int("--samples", 1, 1, 100), message.c_str(), UsageError);
    };
    check("abc", "is not a number");
    check("2.5", "is not an integer");
    check("101", "is out of range");
    check("nan", "is not a number");
  }
}

}  // namespace prt
