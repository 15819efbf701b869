// Words of the command lines prt prints for a user to paste (core/shell_word.h): plain words as
// they are, anything else single-quoted so that the shell reads back the same bytes.
#include <doctest/doctest.h>

#include <string>

#include "core/shell_word.h"

namespace prt {
namespace {

/// The word a POSIX shell reads from `text`, made of plain characters, single-quoted runs and
/// backslashed characters (what ShellWord writes): quotes removed, everything between them kept
/// as it is, a backslash outside them standing for the character after it.
std::string ShellReads(const std::string& text) {
  std::string word;
  bool quoted = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\'') quoted = !quoted;
    else if (!quoted && text[i] == '\\' && i + 1 < text.size()) word += text[++i];
    else word += text[i];
  }
  return word;
}

}  // namespace

TEST_SUITE("core") {
  TEST_CASE("ShellWord leaves a plain word as it is and quotes anything else") {
    CHECK(ShellWord("--mesh") == "--mesh");
    CHECK(ShellWord("data/envs/sky.hdr") == "data/envs/sky.hdr");
    CHECK(ShellWord("--size=640x480") == "--size=640x480");
    CHECK(ShellWord("a,b:c@d%e+f_g.h") == "a,b:c@d%e+f_g.h");
    CHECK(ShellWord("") == "''");
    CHECK(ShellWord("my sky.hdr") == "'my sky.hdr'");
    CHECK(ShellWord("it's") == "'it'\\''s'");
    CHECK(ShellWord("$HOME/*.obj") == "'$HOME/*.obj'");
    CHECK(ShellWord("~/x") == "'~/x'");
    CHECK(ShellWord("a\nb") == "'a\nb'");
  }

  TEST_CASE("ShellWord's quoting reads back as the same bytes") {
    for (const std::string word :
         {"plain", "two words", "it's", "''", "a'b'c", "\\", "$(rm -rf /)", "tab\there", "é.hdr"}) {
      CAPTURE(word);
      CHECK(ShellReads(ShellWord(word)) == word);
    }
  }
}

}  // namespace prt
