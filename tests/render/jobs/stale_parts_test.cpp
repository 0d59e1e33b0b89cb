// Temporary files of a run killed outright: the next run of the same output removes those whose
// process has ended, and only those (not a running writer's, not another output's).
#include "render/jobs/stale_parts.h"

#include <doctest/doctest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace fs = std::filesystem;

namespace {

// the id of a process that has ended: a child that exited and was reaped
pid_t endedPid() {
  const pid_t pid = ::fork();
  if (pid == 0) ::_exit(0);
  ::waitpid(pid, nullptr, 0);
  return pid;
}

}  // namespace

TEST_CASE("stale temporaries of an output are removed; a running writer's and other outputs' are kept") {
  const fs::path dir = fs::temp_directory_path() / ("rigidreel_stale_parts_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string dead = std::to_string(endedPid()), live = std::to_string(::getppid());
  for (const std::string& name : {".a.part-" + dead + ".mp4", "a.mp4.part-" + dead, ".a.part-" + live + ".mp4",
                                  ".b.part-" + dead + ".mp4", std::string("a.mp4")})
    std::ofstream(dir / name) << "x";
  fs::create_directories(dir / (".a.mp4.part-" + dead) / "frames");
  render::jobs::removeStaleParts((dir / "a.mp4").string());
  CHECK_FALSE(fs::exists(dir / (".a.part-" + dead + ".mp4")));
  CHECK_FALSE(fs::exists(dir / ("a.mp4.part-" + dead)));
  CHECK_FALSE(fs::exists(dir / (".a.mp4.part-" + dead)));
  CHECK(fs::exists(dir / (".a.part-" + live + ".mp4")));
  CHECK(fs::exists(dir / (".b.part-" + dead + ".mp4")));
  CHECK(fs::exists(dir / "a.mp4"));
  fs::remove_all(dir);
}

TEST_CASE("a temporary name is the output's, with this process's id") {
  CHECK(render::jobs::partName("out/a.json") == "out/a.json.part-" + std::to_string(::getpid()));
}
