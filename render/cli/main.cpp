// rigidreel: the command line, a thin layer that wires scenes, the simulator and the renderer.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>

#include "render/cli/commands.h"
#include "sim/yaml/scene_yaml.h"

int main(int argc, char** argv) {
  CLI::App app{"rigidreel: simulate and render 2D rigid-body scenes written in YAML"};
  app.require_subcommand(1);
  int exitCode = render::jobs::kExitOk;
  render::cli::addSimulateCommand(app, exitCode);
  render::cli::addCheckCommand(app, exitCode);
  render::cli::addSweepCommand(app, exitCode);
  render::cli::addStabilityCommand(app, exitCode);
  render::cli::addRenderCommand(app, exitCode);
  render::cli::addSnapshotCommand(app, exitCode);
  render::cli::addLectureCommand(app, exitCode);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : render::jobs::kExitBadInput;
  } catch (const sim::yaml::SceneError& e) {
    std::cerr << e.what() << '\n';
    return render::jobs::kExitBadInput;
  } catch (const render::jobs::UsageError& e) {
    std::cerr << "rigidreel: " << e.what() << '\n';
    return render::jobs::kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "rigidreel: " << e.what() << '\n';
    return render::jobs::kExitFailure;
  }
  // what was printed reaches its file only now, for the most part: a full disk (/dev/full), a
  // closed standard output fail here, and a run whose results were not written is not a success
  std::cout.flush();
  if (!std::cout || std::fflush(stdout) != 0 || std::ferror(stdout)) {
    std::cerr << "rigidreel: cannot write standard output (" << std::strerror(errno) << "); the results are not complete\n";
    return exitCode == render::jobs::kExitOk ? render::jobs::kExitFailure : exitCode;
  }
  return exitCode;
}
