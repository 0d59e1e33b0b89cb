// Ctrl-C during a long render: the signal only raises a flag; the frame loop sees it between frames
// and throws, so that the destructors stop ffmpeg and remove every temporary file.
#pragma once

#include <functional>
#include <stdexcept>
#include <string>

namespace render::jobs {

struct Interrupted : std::runtime_error {
  Interrupted() : std::runtime_error("interrupted; what was being written is removed, finished files are kept") {}
};

// from now on SIGINT and SIGTERM raise the flag instead of ending the process
void catchInterrupts();
// throws Interrupted when the flag is up
void checkInterrupted();

// after a child ended (its raw wait status): throws Interrupted when the flag is up or the child was
// stopped by SIGINT or SIGTERM, as Ctrl-C at a terminal stops every process of the group, ffmpeg
// included, and its death is then this run's interruption, not a failure of the tool
void checkChildInterrupted(int waitStatus);

// the exit status of a process stopped by SIGINT, as shells report it
inline constexpr int kExitInterrupted = 130;

// a subcommand with Ctrl-C caught: its exit status, or kExitInterrupted after saying on one line
// what was interrupted ("rigidreel: simulate a.yaml interrupted; …")
int runInterruptible(const std::string& what, const std::function<int()>& command);

}  // namespace render::jobs
