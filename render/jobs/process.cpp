#include "render/jobs/process.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <thread>

#include "render/jobs/interrupt.h"

extern char** environ;

namespace render::jobs {

namespace {

// closes whichever of the fds are open
void closeAll(std::initializer_list<int> fds) {
  for (int fd : fds)
    if (fd >= 0) ::close(fd);
}

}  // namespace

bool SpawnError::missing() const { return error == ENOENT || error == EACCES || error == ENOEXEC || error == ENOTDIR; }

Child spawnChild(const std::vector<std::string>& argv, Stream input, Stream output, Stream errors) {
  // pipes[i] for the child's fd i: [0] the read end, [1] the write end
  int pipes[3][2] = {{-1, -1}, {-1, -1}, {-1, -1}};
  const Stream modes[3] = {input, output, errors};
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  for (int fd = 0; fd < 3; ++fd) {
    if (modes[fd] == Stream::Null) {
      posix_spawn_file_actions_addopen(&actions, fd, "/dev/null", fd == 0 ? O_RDONLY : O_WRONLY, 0);
    } else if (modes[fd] == Stream::Pipe) {
      if (::pipe2(pipes[fd], O_CLOEXEC) != 0) {
        const int error = errno;
        posix_spawn_file_actions_destroy(&actions);
        for (auto& p : pipes) closeAll({p[0], p[1]});
        throw SpawnError(std::string("cannot make a pipe: ") + std::strerror(error), error);
      }
      // the child's end: the read end of its input, the write end of its outputs
      posix_spawn_file_actions_adddup2(&actions, pipes[fd][fd == 0 ? 0 : 1], fd);
    }
  }
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  Child child;
  const int spawned = ::posix_spawnp(&child.pid, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  closeAll({pipes[0][0], pipes[1][1], pipes[2][1]});
  if (spawned != 0) {
    closeAll({pipes[0][1], pipes[1][0], pipes[2][0]});
    throw SpawnError("cannot run '" + argv[0] + "' (" + std::strerror(spawned) + ")", spawned);
  }
  child.input = pipes[0][1];
  child.output = pipes[1][0];
  child.errors = pipes[2][0];
  return child;
}

void widenPipe(int fd, size_t bytes) {
  if (::fcntl(fd, F_SETPIPE_SZ, static_cast<int>(std::min<size_t>(bytes, 1u << 30))) >= 0) return;
  // more than the system allows: its maximum, then
  size_t most = 0;
  if (std::FILE* f = std::fopen("/proc/sys/fs/pipe-max-size", "r")) {
    if (std::fscanf(f, "%zu", &most) != 1) most = 0;
    std::fclose(f);
  }
  if (most > 0 && most < bytes) ::fcntl(fd, F_SETPIPE_SZ, static_cast<int>(most));
}

int waitChild(pid_t pid) {
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
  return status;
}

void readTail(int fd, std::string& into, size_t keep) {
  char buffer[4096];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    into.append(buffer, static_cast<size_t>(n));
    if (into.size() > 2 * keep) into.erase(0, into.size() - keep);
  }
}

ProcessResult runProgram(const std::vector<std::string>& argv, const std::string& input) {
  Child child;
  try {
    child = spawnChild(argv, Stream::Pipe, Stream::Null, Stream::Pipe);
  } catch (const SpawnError& e) {
    throw std::runtime_error(std::string(e.what()) + (e.missing() ? "; is it installed?" : ""));
  }
  // read its standard error while we write, so that neither side blocks on a full pipe
  ProcessResult result;
  std::thread reader([&] {
    readTail(child.errors, result.errorTail, 4096);
    ::close(child.errors);
  });
  // a program that stops reading early must not kill us with SIGPIPE
  struct sigaction ignore {
  }, previous{};
  ignore.sa_handler = SIG_IGN;
  ::sigaction(SIGPIPE, &ignore, &previous);
  for (size_t done = 0; done < input.size();) {
    const ssize_t n = ::write(child.input, input.data() + done, input.size() - done);
    if (n <= 0) break;
    done += static_cast<size_t>(n);
  }
  ::close(child.input);
  ::sigaction(SIGPIPE, &previous, nullptr);
  const int status = waitChild(child.pid);
  reader.join();
  checkChildInterrupted(status);
  result.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

}  // namespace render::jobs
