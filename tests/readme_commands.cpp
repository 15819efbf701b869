#include "tests/readme_commands.h"

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>

#include "tests/test_process.h"

namespace prt::test {
namespace {
namespace fs = std::filesystem;

/// The course's framework layout (assets/mary, assets/cubemap/<Name>/faces, with the framework's
/// own light.txt and transport.txt) over the shared data: real folders holding links to the
/// files, so outputs written there stay in `root`.
void LayOutCourseFramework(const std::string& data, const std::string& root) {
  fs::create_directories(root + "/assets");
  fs::create_directory_symlink(data + "/games202/mary", root + "/assets/mary");
  for (const auto& cubemap : fs::directory_iterator(data + "/games202/cubemap")) {
    const std::string folder = root + "/assets/cubemap/" + cubemap.path().filename().string();
    fs::create_directories(folder);
    for (const auto& face : fs::directory_iterator(cubemap.path()))
      fs::create_symlink(face.path(), folder + "/" + face.path().filename().string());
    for (const char* name : {"light.txt", "transport.txt"}) std::ofstream(folder + "/" + name) << ShippedFile(name);
  }
}

}  // namespace

std::vector<std::string> ReadmeCommands() {
  std::ifstream in(SourceDir() + "/README.md");
  std::vector<std::string> commands;
  bool in_block = false;
  std::string pending;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("```", 0) == 0) {
      in_block = !in_block && line == "```sh";
      continue;
    }
    if (!in_block) continue;
    const auto first = line.find_first_not_of(' ');
    if (first == std::string::npos || line[first] == '#') continue;
    if (!line.empty() && line.back() == '\\') {
      pending += line.substr(0, line.size() - 1);
      continue;
    }
    commands.push_back(pending + line);
    pending.clear();
  }
  return commands;
}

std::string ReadmeCommandWith(const std::string& text) {
  std::vector<std::string> found;
  for (const std::string& command : ReadmeCommands())
    if (command.find(text) != std::string::npos) found.push_back(command);
  INFO("README commands with '" << text << "': " << found.size());
  CHECK(found.size() == 1);
  return found.size() == 1 ? found[0] : "";
}

std::string MakeReadmeClone(const std::string& name) {
  const std::string clone = ScratchDir(name);
  fs::create_directories(clone + "/build");
  fs::create_symlink(PrtBinary(), clone + "/build/prt");
  fs::create_directory_symlink(SourceDir() + "/scripts", clone + "/scripts");
  if (const auto data = SharedData()) LayOutCourseFramework(*data, clone + "/games202");
  return clone;
}

std::string ShippedFile(const std::string& name) { return "the framework's own " + name + "\n"; }

int RunInClone(const std::string& clone, const std::string& command) {
  const auto r = RunCommand("cd " + Q(clone) + " && GAMES202=" + Q(clone + "/games202") + " bash -c " + Q(command));
  CAPTURE(command);
  CAPTURE(r.err);
  CHECK(r.exit_code == 0);
  return r.exit_code;
}

}  // namespace prt::test
