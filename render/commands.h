// The subcommands of `rigidreel`; each registers itself on the CLI11 app.
#pragma once

#include <CLI/CLI.hpp>
#include <stdexcept>
#include <string>

namespace render {

inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;   // a check failed, the simulation diverged, a tool failed
inline constexpr int kExitBadInput = 2;  // the scene or the command line is wrong

// a command-line value that is wrong: reported like a scene error, exit 2
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

void addSimulateCommand(CLI::App& app, int& exitCode);
void addCheckCommand(CLI::App& app, int& exitCode);
void addSweepCommand(CLI::App& app, int& exitCode);
void addStabilityCommand(CLI::App& app, int& exitCode);
void addRenderCommand(CLI::App& app, int& exitCode);
void addSnapshotCommand(CLI::App& app, int& exitCode);
void addLectureCommand(CLI::App& app, int& exitCode);

}  // namespace render
