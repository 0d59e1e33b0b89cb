// Jobs as child processes, at most N at a time, each one's standard output and standard error
// captured whole, so that jobs running side by side never interleave their messages.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace render::jobs {

struct JobResult {
  size_t job = 0;      // its index in the list of commands
  int status = 0;      // raw wait status; a job that could not start has exit status 127
  std::string output;  // what it printed on standard output
  std::string errors;  // on standard error (or why it could not start)
  double seconds = 0;  // wall time from start to end
};

// true when the job exited with status 0
bool succeeded(const JobResult& result);
// "exit status 1", "killed by signal 9"
std::string describeStatus(int status);

// the order to start jobs in, given what each costs (any unit): the costliest first, ties in their
// order (longest processing time first: the jobs that start last are short, so that a batch does
// not end with one long job running alone while the other workers idle; Graham 1969)
std::vector<size_t> largestFirst(const std::vector<double>& cost);

// runs every command (an argument vector each, argv[0] looked up on PATH) with at most `parallel`
// running at once, started in order; tells `done` about each job as it ends, in the order they
// end. On Ctrl-C (see interrupt.h) it passes SIGINT on to the running jobs, waits for them and
// throws Interrupted.
void runJobs(const std::vector<std::vector<std::string>>& commands, size_t parallel,
             const std::function<void(const JobResult&)>& done);

}  // namespace render::jobs
