// How a run of rigidreel ends: its exit statuses, and the error that means "the input is wrong".
#pragma once

#include <stdexcept>

namespace render::jobs {

inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;   // a check failed, the simulation diverged, a tool failed
inline constexpr int kExitBadInput = 2;  // the scene or the command line is wrong

// a command-line value that is wrong: reported like a scene error, exit 2
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace render::jobs
