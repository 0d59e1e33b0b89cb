#include "render/jobs/job_runner.h"

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <numeric>
#include <cerrno>
#include <chrono>
#include <list>
#include <stdexcept>
#include <string>

#include "render/jobs/interrupt.h"
#include "render/jobs/process.h"

namespace render::jobs {

namespace {

using Clock = std::chrono::steady_clock;

struct Running {
  JobResult result;
  Child child;
  Clock::time_point start;
};

// reads what is there on `fd` into `into`; closes it and sets it to -1 at its end
void drain(int& fd, std::string& into) {
  char buffer[4096];
  const ssize_t n = ::read(fd, buffer, sizeof buffer);
  if (n < 0 && errno == EINTR) return;
  if (n > 0) {
    into.append(buffer, static_cast<size_t>(n));
    return;
  }
  ::close(fd);
  fd = -1;
}

}  // namespace

std::vector<size_t> largestFirst(const std::vector<double>& cost) {
  std::vector<size_t> order(cost.size());
  std::iota(order.begin(), order.end(), size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return cost[a] > cost[b]; });
  return order;
}

bool succeeded(const JobResult& result) { return WIFEXITED(result.status) && WEXITSTATUS(result.status) == 0; }

std::string describeStatus(int status) {
  if (WIFEXITED(status)) return "exit status " + std::to_string(WEXITSTATUS(status));
  if (WIFSIGNALED(status)) return "killed by signal " + std::to_string(WTERMSIG(status));
  return "status " + std::to_string(status);
}

void runJobs(const std::vector<std::vector<std::string>>& commands, size_t parallel,
             const std::function<void(const JobResult&)>& done) {
  std::list<Running> running;
  size_t next = 0;
  const auto finish = [&](std::list<Running>::iterator r) {
    r->result.status = waitChild(r->child.pid);
    r->result.seconds = std::chrono::duration<double>(Clock::now() - r->start).count();
    const JobResult result = std::move(r->result);
    running.erase(r);
    done(result);
  };
  while (next < commands.size() || !running.empty()) {
    while (running.size() < std::max<size_t>(parallel, 1) && next < commands.size()) {
      Running r{{next, 0, {}, {}, 0.0}, {}, Clock::now()};
      try {
        r.child = spawnChild(commands[next], Stream::Null, Stream::Pipe, Stream::Pipe);
        running.push_back(std::move(r));
      } catch (const SpawnError& e) {
        r.result.status = 127 << 8;  // as a shell reports a command it cannot run
        r.result.errors = e.what();
        done(r.result);
      }
      ++next;
    }
    // wait for output from any job; a job whose streams have both ended is finished
    std::vector<pollfd> fds;
    for (const Running& r : running)
      for (int fd : {r.child.output, r.child.errors})
        if (fd >= 0) fds.push_back({fd, POLLIN, 0});
    // a short timeout too, so that a Ctrl-C arriving just before poll() is seen soon
    if (!fds.empty() && ::poll(fds.data(), fds.size(), 250) < 0 && errno != EINTR)
      throw std::runtime_error("cannot wait for the jobs: poll failed");
    try {
      checkInterrupted();
    } catch (const Interrupted&) {
      for (Running& r : running) ::kill(r.child.pid, SIGINT);
      for (Running& r : running) {
        if (r.child.output >= 0) ::close(r.child.output);
        if (r.child.errors >= 0) ::close(r.child.errors);
        waitChild(r.child.pid);
      }
      throw;
    }
    for (const pollfd& p : fds) {
      if (!(p.revents & (POLLIN | POLLHUP | POLLERR))) continue;
      for (Running& r : running) {
        if (p.fd == r.child.output) drain(r.child.output, r.result.output);
        if (p.fd == r.child.errors) drain(r.child.errors, r.result.errors);
      }
    }
    for (auto r = running.begin(); r != running.end();) {
      const auto here = r++;
      if (here->child.output < 0 && here->child.errors < 0) finish(here);
    }
  }
}

}  // namespace render::jobs
