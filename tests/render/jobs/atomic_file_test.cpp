// Outputs written under a temporary name and put in place whole: a file, and a folder that several
// processes publish at once (two renders of one scene into one -o).
#include "render/jobs/atomic_file.h"

#include <doctest/doctest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using render::jobs::AtomicFile;
using render::jobs::StagedDirectory;

namespace {

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("rigidreel_atomic_file_test_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// what a writer of frames leaves: kFiles files, each naming the writer, so a folder mixed from two
// writers shows
constexpr int kFiles = 40;

// in a child: stage a folder of kFiles files and publish it as `final`; exit 0 when commit succeeds
pid_t publishInChild(const std::string& final) {
  const pid_t pid = ::fork();
  if (pid != 0) return pid;
  int status = 0;
  try {
    StagedDirectory dir(final);
    for (int k = 0; k < kFiles; ++k) std::ofstream(dir.path() + "/frame" + std::to_string(k)) << ::getpid();
    dir.commit();
  } catch (...) {
    status = 1;
  }
  ::_exit(status);
}

// the folder holds kFiles files, all of one writer, and nothing else
bool whole(const fs::path& dir) {
  std::string writer;
  int files = 0;
  for (const fs::directory_entry& e : fs::directory_iterator(dir)) {
    std::string text;
    std::ifstream(e.path()) >> text;
    if (writer.empty()) writer = text;
    if (text.empty() || text != writer) return false;
    ++files;
  }
  return files == kFiles;
}

}  // namespace

TEST_CASE("an atomic file appears only on commit, and a file not committed leaves nothing") {
  const fs::path dir = scratch("file");
  const std::string path = (dir / "a.json").string();
  {
    AtomicFile f(path);
    f.stream() << "first";
    CHECK_FALSE(fs::exists(path));
    f.commit();
  }
  {
    AtomicFile f(path);
    f.stream() << "second, abandoned";
  }
  std::string text;
  std::ifstream(path) >> text;
  CHECK(text == "first");
  CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator()) == 1);
  fs::remove_all(dir);
}

TEST_CASE("a staged folder replaces the old one whole, and an uncommitted one leaves nothing") {
  const fs::path dir = scratch("folder");
  const std::string final = (dir / "frames").string();
  fs::create_directories(final);
  std::ofstream(final + "/old") << "old";
  {
    StagedDirectory staged(final);
    std::ofstream(staged.path() + "/frame0") << "new";
    staged.commit();
  }
  CHECK(fs::exists(final + "/frame0"));
  CHECK_FALSE(fs::exists(final + "/old"));
  { StagedDirectory abandoned(final); }
  CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator()) == 1);
  fs::remove_all(dir);
}

// Before the swap, the old folder was removed and the new one renamed over it: with 4 writers at
// once, some writer failed ("cannot remove all", or ENOTEMPTY on the rename) in most rounds.
TEST_CASE("writers publishing one folder at once all succeed, and the folder is one writer's, whole") {
  const fs::path dir = scratch("race");
  const std::string final = (dir / "frames").string();
  constexpr int kRounds = 30, kWriters = 4;
  int failedWriters = 0, brokenFolders = 0;
  for (int round = 0; round < kRounds; ++round) {
    std::vector<pid_t> writers;
    for (int w = 0; w < kWriters; ++w) writers.push_back(publishInChild(final));
    for (pid_t pid : writers) {
      int status = 0;
      ::waitpid(pid, &status, 0);
      failedWriters += !(WIFEXITED(status) && WEXITSTATUS(status) == 0);
    }
    brokenFolders += !whole(final);
  }
  CHECK(failedWriters == 0);
  CHECK(brokenFolders == 0);
  // nothing left beside the folder: every swapped-out old one removed
  CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator()) == 1);
  fs::remove_all(dir);
}

TEST_CASE("a path that is not a regular file is written through; a symlink keeps being one, its target replaced") {
  const fs::path dir = scratch("through");
  const fs::path fifo = dir / "fifo";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  // a reader at the FIFO's other end, in a child: what it reads comes back as its exit status
  const pid_t reader = ::fork();
  if (reader == 0) {
    std::ifstream in(fifo);
    std::string line;
    std::getline(in, line);
    ::_exit(line == "through" ? 0 : 1);
  }
  {
    AtomicFile out(fifo.string());
    CHECK(out.temporaryPath() == fifo.string());
    out.stream() << "through\n";
    out.commit();
  }
  int status = 0;
  ::waitpid(reader, &status, 0);
  CHECK(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
  CHECK(fs::is_fifo(fifo));

  std::ofstream(dir / "target") << "old";
  fs::create_symlink("target", dir / "link");
  {
    AtomicFile out((dir / "link").string());
    out.stream() << "new";
    out.commit();
  }
  CHECK(fs::is_symlink(dir / "link"));
  std::ifstream in(dir / "target");
  std::string text;
  in >> text;
  CHECK(text == "new");
  fs::remove_all(dir);
}

TEST_CASE("a write that fails at the end is an error, and nothing is left under the final name") {
  AtomicFile full("/dev/full");
  full.stream() << std::string(1 << 16, 'x');
  CHECK_THROWS_WITH_AS(full.commit(), doctest::Contains("/dev/full: could not finish writing"), std::runtime_error);
}
