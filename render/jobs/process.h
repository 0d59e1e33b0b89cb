// Child processes: started from an argument vector (no shell, so no file name can inject a
// command), with pipes to the streams asked for. The one place that spawns: ffmpeg (video.cpp),
// gnuplot (chart.cpp) and `rigidreel lecture`'s jobs (job_runner.cpp) all start here.
#pragma once

#include <sys/types.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace render::jobs {

// what a child's standard stream is connected to
enum class Stream { Inherit, Null, Pipe };

// a started child: its id and our ends of its piped streams (-1 for those not piped); our ends are
// close-on-exec, so that other children never hold them open
struct Child {
  pid_t pid = -1;
  int input = -1;   // we write its standard input
  int output = -1;  // we read its standard output
  int errors = -1;  // we read its standard error
};

// "cannot run 'ffmpeg' (No such file or directory)": the caller adds what to do about it
struct SpawnError : std::runtime_error {
  SpawnError(const std::string& message, int error) : std::runtime_error(message), error(error) {}
  int error;  // errno: ENOENT or EACCES say the program is missing; EMFILE, ENOMEM, EAGAIN that the
              // machine is out of descriptors, memory or processes, where installing it would not help
  bool missing() const;
};

// starts argv[0] (looked up on PATH when it has no '/'); throws SpawnError
Child spawnChild(const std::vector<std::string>& argv, Stream input, Stream output, Stream errors);
// asks the kernel to let the pipe `fd` hold `bytes` (a whole video frame) rather than its default
// 64 KiB, or as much as an unprivileged process may (/proc/sys/fs/pipe-max-size, 1 MiB by default):
// fewer, larger writes, and fewer wake-ups of the reader. Best effort: a pipe left as it was still works
void widenPipe(int fd, size_t bytes);
// waits for the child to end (through EINTR); its raw wait status (WIFEXITED, …)
int waitChild(pid_t pid);
// appends what `fd` gives until its end, keeping about the last `keep` characters of `into`
void readTail(int fd, std::string& into, size_t keep);

struct ProcessResult {
  int status = -1;        // exit status, or -1 when it was killed by a signal
  std::string errorTail;  // the last lines it wrote to standard error
};

// runs argv[0] (looked up on PATH) with `input` on its standard input and waits for it; throws
// std::runtime_error naming the program when it cannot be started
ProcessResult runProgram(const std::vector<std::string>& argv, const std::string& input);

}  // namespace render::jobs
