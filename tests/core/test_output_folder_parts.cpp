// Parts of one output folder at once (core/output_folder.h, OutputPlan::part): parts share the
// folder while a whole run excludes them and they it; each stages apart, adds its outputs to the
// list beside the others' and removes nothing; a failed part leaves no trace of itself; the last
// part to end removes the lock files; a whole run sweeps what killed parts left.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>

#include "core/atomic_file.h"
#include "core/output_folder.h"
#include "tests/test_support.h"

namespace prt {
namespace {

namespace fs = std::filesystem;

/// Every name in `dir`, hidden files and folders too.
std::set<std::string> Names(const std::string& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
  return names;
}

/// The list's entries, name -> command.
std::map<std::string, std::string> List(const std::string& dir) {
  std::map<std::string, std::string> entries;
  std::istringstream in(ReadFile(dir + "/" + OutputFolder::kListName));
  for (std::string line; std::getline(in, line);)
    if (!line.empty() && line[0] != '#') entries[line.substr(line.find('\t') + 1)] = line.substr(0, line.find('\t'));
  return entries;
}

OutputPlan Part(std::vector<std::string> names) { return {"render", std::move(names), false, true}; }
OutputPlan Whole(std::vector<std::string> names) { return {"render", std::move(names), false, false}; }

/// Writes `text` as the output `name` of `folder`.
void Put(OutputFolder& folder, const std::string& name, const std::string& text) {
  WriteFileAtomic(folder.Output(name), text);
}

}  // namespace

TEST_SUITE("core") {
TEST_CASE("output folder parts: two at once each add their outputs, and remove nothing an earlier run wrote") {
  const std::string dir = test::ScratchDir("parts_two");
  {
    // An earlier whole run of the same command: three frames.
    OutputFolder whole(dir, Whole({"a", "b", "c"}));
    for (const char* n : {"a", "b", "c"}) Put(whole, n, "old");
    whole.Finish();
  }
  {
    OutputFolder one(dir, Part({"a"}));
    OutputFolder two(dir, Part({"b"}));  // while the first holds the folder
    Put(one, "a", "new a");
    Put(two, "b", "new b");
    // Each stages apart: neither output is in the folder before its part finishes.
    CHECK(ReadFile(dir + "/a") == "old");
    two.Finish();
    CHECK(ReadFile(dir + "/b") == "new b");
    CHECK(ReadFile(dir + "/a") == "old");
    one.Finish();
  }
  CHECK(ReadFile(dir + "/a") == "new a");
  CHECK(ReadFile(dir + "/c") == "old");  // not a part's output, and not removed by one
  CHECK(List(dir) == std::map<std::string, std::string>{{"a", "render"}, {"b", "render"}, {"c", "render"}});
  // The last part removed the lock files and its staging folder: only the outputs and the list.
  CHECK(Names(dir) == std::set<std::string>{"a", "b", "c", OutputFolder::kListName});
}

TEST_CASE("output folder parts: a whole run is refused while a part holds the folder, and a part while a whole run does") {
  const std::string dir = test::ScratchDir("parts_exclusive");
  {
    OutputFolder part(dir, Part({"x"}));
    CHECK_THROWS_AS(OutputFolder(dir, Whole({"y"})), FolderBusy);
    // The part goes on, unharmed by the refused run.
    Put(part, "x", "x");
    part.Finish();
  }
  {
    OutputFolder whole(dir, Whole({"x"}));
    CHECK_THROWS_AS(OutputFolder(dir, Part({"y"})), FolderBusy);
    Put(whole, "x", "x2");
    whole.Finish();
  }
  CHECK(ReadFile(dir + "/x") == "x2");
  CHECK(Names(dir) == std::set<std::string>{"x", OutputFolder::kListName});
}

TEST_CASE("output folder parts: the lock files stay while another part holds the folder, the last removes them") {
  const std::string dir = test::ScratchDir("parts_last");
  std::optional<OutputFolder> first(std::in_place, dir, Part({"p"}));
  {
    OutputFolder second(dir, Part({"q"}));
    Put(second, "q", "q");
    second.Finish();
  }
  CHECK(fs::exists(dir + "/" + OutputFolder::kLockName));  // the first still holds the folder
  CHECK_THROWS_AS(OutputFolder(dir, Whole({"r"})), FolderBusy);
  Put(*first, "p", "p");
  first->Finish();
  first.reset();
  CHECK_FALSE(fs::exists(dir + "/" + OutputFolder::kLockName));
  CHECK_FALSE(fs::exists(dir + "/" + OutputFolder::kListLockName));
  CHECK(List(dir) == std::map<std::string, std::string>{{"p", "render"}, {"q", "render"}});
}

TEST_CASE("output folder parts: a failed part leaves nothing of itself; a whole run sweeps a killed part's staging") {
  const std::string dir = test::ScratchDir("parts_failed");
  {
    OutputFolder kept(dir, Part({"k"}));
    Put(kept, "k", "k");
    kept.Finish();
  }
  {
    OutputFolder failed(dir, Part({"f"}));
    Put(failed, "f", "half");
    // Destroyed without Finish: the run failed.
  }
  CHECK(Names(dir) == std::set<std::string>{"k", OutputFolder::kListName});
  // A part killed by SIGKILL leaves its staging folder (nothing runs at its end): the next
  // whole run removes it, the part's own folder name and all.
  const std::string orphan = dir + "/" + OutputFolder::kStagingName + ".Ab12Cd";
  fs::create_directories(orphan);
  std::ofstream(orphan + "/frame_0003.png") << "partial";
  {
    OutputFolder part(dir, Part({"m"}));  // a part leaves other parts' staging alone
    part.Finish();
  }
  CHECK(fs::exists(orphan));
  {
    OutputFolder whole(dir, Whole({"k"}));
    Put(whole, "k", "k2");
    whole.Finish();
  }
  CHECK_FALSE(fs::exists(orphan));
  CHECK(Names(dir) == std::set<std::string>{"k", OutputFolder::kListName});
}

TEST_CASE("output folder parts: a file prt did not write is refused to a part as to a whole run") {
  const std::string dir = test::ScratchDir("parts_foreign");
  std::ofstream(dir + "/frame_0001.png") << "the user's";
  CHECK_THROWS_WITH_AS(OutputFolder(dir, Part({"frame_0001.png"})),
                       doctest::Contains("exists and prt did not write it"), Error);
  CHECK(ReadFile(dir + "/frame_0001.png") == "the user's");
  CHECK(Names(dir) == std::set<std::string>{"frame_0001.png"});
}
}  // TEST_SUITE

}  // namespace prt
