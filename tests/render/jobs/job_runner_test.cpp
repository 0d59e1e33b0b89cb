// Jobs as child processes: each one's output captured apart from the others', its exit status,
// never more than N running at once, and a command that cannot start reported as a failed job.
#include "render/jobs/job_runner.h"

#include <doctest/doctest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace {

std::vector<std::string> shell(const std::string& script) { return {"sh", "-c", script}; }

std::vector<render::jobs::JobResult> runAll(const std::vector<std::vector<std::string>>& commands, size_t parallel) {
  std::vector<render::jobs::JobResult> results;
  render::jobs::runJobs(commands, parallel, [&](const render::jobs::JobResult& r) { results.push_back(r); });
  std::sort(results.begin(), results.end(), [](const auto& a, const auto& b) { return a.job < b.job; });
  return results;
}

}  // namespace

TEST_CASE("each job's standard output and error are captured apart, with its exit status") {
  const auto results = runAll({shell("echo one; echo bad >&2; exit 3"), shell("printf 'two\\nlines\\n'")}, 2);
  REQUIRE(results.size() == 2);
  CHECK(results[0].output == "one\n");
  CHECK(results[0].errors == "bad\n");
  CHECK(WEXITSTATUS(results[0].status) == 3);
  CHECK_FALSE(render::jobs::succeeded(results[0]));
  CHECK(render::jobs::describeStatus(results[0].status) == "exit status 3");
  CHECK(results[1].output == "two\nlines\n");
  CHECK(results[1].errors.empty());
  CHECK(render::jobs::succeeded(results[1]));
}

TEST_CASE("output larger than a pipe's buffer is read while the job runs") {
  const auto results = runAll({shell("head -c 200000 /dev/zero | tr '\\0' x")}, 1);
  CHECK(results.at(0).output == std::string(200000, 'x'));
}

TEST_CASE("never more than N jobs run at once, and one at a time runs them in order") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("job_runner_test." + std::to_string(::getpid()));
  fs::create_directories(dir / "slots");
  // each job holds a slot while it runs and prints how many slots are held
  const std::string job = "mkdir " + (dir / "slots").string() + "/$$; ls " + (dir / "slots").string() +
                          " | wc -l; sleep 0.05; rmdir " + (dir / "slots").string() + "/$$";
  std::vector<std::vector<std::string>> commands(6, shell(job));
  for (size_t parallel : {1, 2}) {
    for (const render::jobs::JobResult& r : runAll(commands, parallel)) {
      CHECK(render::jobs::succeeded(r));
      CHECK(std::stoul(r.output) <= parallel);
    }
  }
  // one at a time: job i sees what job i - 1 wrote
  const std::string log = (dir / "log").string();
  const auto ordered = runAll({shell("echo a >> " + log), shell("grep -q a " + log + " && echo b >> " + log)}, 1);
  CHECK(render::jobs::succeeded(ordered.at(1)));
  fs::remove_all(dir);
}

TEST_CASE("two at a time runs two at once") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("job_runner_pair." + std::to_string(::getpid()));
  const std::string slots = (dir / "slots").string();
  fs::create_directories(slots);
  // each job holds a slot and waits (up to 10 s) for the other to hold one: only jobs that run at
  // the same time both see 2; run one after the other, each would give up and see 1
  const std::string job = "mkdir " + slots + "/$$; for i in $(seq 200); do [ $(ls " + slots +
                          " | wc -l) -ge 2 ] && break; sleep 0.05; done; ls " + slots + " | wc -l; sleep 0.1; rmdir " + slots +
                          "/$$";
  for (const render::jobs::JobResult& r : runAll({shell(job), shell(job)}, 2)) CHECK(std::stoul(r.output) == 2);
  fs::remove_all(dir);
}

TEST_CASE("a command that cannot start is a failed job that says so") {
  const auto results = runAll({{"/nonexistent/rigidreel-nothing"}, shell("true")}, 1);
  REQUIRE(results.size() == 2);
  CHECK(WEXITSTATUS(results[0].status) == 127);
  CHECK(results[0].errors.find("cannot run '/nonexistent/rigidreel-nothing'") != std::string::npos);
  CHECK(render::jobs::succeeded(results[1]));
}

TEST_CASE("jobs start costliest first, equal costs in their order") {
  CHECK(render::jobs::largestFirst({1.0, 5.0, 3.0, 5.0, 0.0}) == std::vector<size_t>{1, 3, 2, 0, 4});
  CHECK(render::jobs::largestFirst({}).empty());
}
