#pragma once
/// \file
/// The README's shell commands, for the tests that run them verbatim (tests/app/test_readme.cpp,
/// and the stability test, which runs the README's `prt report --stability` itself), and a
/// scratch folder laid out like a fresh clone after the quick start to run them in.

#include <string>
#include <vector>

namespace prt::test {

/// The commands of the README's ```sh blocks, in order: comment lines dropped, continuations
/// joined.
std::vector<std::string> ReadmeCommands();

/// The one README command that contains `text`; a test failure (and "") when there is not
/// exactly one.
std::string ReadmeCommandWith(const std::string& text);

/// A scratch folder of `name` laid out like a fresh clone after the quick start: build/prt and
/// scripts/, with the course's framework under games202/ when the course data is there (assets/mary
/// and assets/cubemap/<Name>/ with the framework's own light.txt and transport.txt, ShippedFile).
std::string MakeReadmeClone(const std::string& name);

/// What the course's framework layout of MakeReadmeClone holds as each cubemap's `name`
/// (light.txt, transport.txt): stand-ins, which the README's course command must keep as *.orig.
std::string ShippedFile(const std::string& name);

/// Runs `command` with bash in `clone`, as a user of the README would (GAMES202 set to its
/// course framework). Returns the exit code; a failure shows the command and its stderr.
int RunInClone(const std::string& clone, const std::string& command);

}  // namespace prt::test
