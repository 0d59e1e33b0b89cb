// The subcommands of `rigidreel`; each registers itself on the CLI11 app.
#pragma once

#include <CLI/CLI.hpp>

#include "render/jobs/exit_status.h"

namespace render::cli {

void addSimulateCommand(CLI::App& app, int& exitCode);
void addCheckCommand(CLI::App& app, int& exitCode);
void addSweepCommand(CLI::App& app, int& exitCode);
void addStabilityCommand(CLI::App& app, int& exitCode);
void addRenderCommand(CLI::App& app, int& exitCode);
void addSnapshotCommand(CLI::App& app, int& exitCode);
void addLectureCommand(CLI::App& app, int& exitCode);
void addGoldenCommand(CLI::App& app, int& exitCode);
void addCompareCommand(CLI::App& app, int& exitCode);
void addExpectCommand(CLI::App& app, int& exitCode);

}  // namespace render::cli
