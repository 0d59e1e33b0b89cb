#include "render/jobs/interrupt.h"

#include <sys/wait.h>

#include <csignal>
#include <iostream>

namespace render::jobs {

namespace {

volatile std::sig_atomic_t interruptedFlag = 0;

extern "C" void raiseFlag(int) { interruptedFlag = 1; }

}  // namespace

void catchInterrupts() {
  struct sigaction action {};
  action.sa_handler = raiseFlag;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

void checkInterrupted() {
  if (interruptedFlag) throw Interrupted();
}

void checkChildInterrupted(int waitStatus) {
  checkInterrupted();
  if (WIFSIGNALED(waitStatus) && (WTERMSIG(waitStatus) == SIGINT || WTERMSIG(waitStatus) == SIGTERM)) throw Interrupted();
}

int runInterruptible(const std::string& what, const std::function<int()>& command) {
  catchInterrupts();
  try {
    return command();
  } catch (const Interrupted& e) {
    std::cerr << "rigidreel: " << what << ' ' << e.what() << '\n';
    return kExitInterrupted;
  }
}

}  // namespace render::jobs
