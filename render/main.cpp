// rigidreel: the command line, a thin layer that wires scenes, the simulator and the renderer.
#include <iostream>

#include "commands.h"
#include "scene_yaml.h"

int main(int argc, char** argv) {
  CLI::App app{"rigidreel: simulate and render 2D rigid-body scenes written in YAML"};
  app.require_subcommand(1);
  int exitCode = render::kExitOk;
  render::addSimulateCommand(app, exitCode);
  render::addCheckCommand(app, exitCode);
  render::addSweepCommand(app, exitCode);
  render::addStabilityCommand(app, exitCode);
  render::addRenderCommand(app, exitCode);
  render::addSnapshotCommand(app, exitCode);
  render::addLectureCommand(app, exitCode);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : render::kExitBadInput;
  } catch (const sim::SceneError& e) {
    std::cerr << e.what() << '\n';
    return render::kExitBadInput;
  } catch (const render::UsageError& e) {
    std::cerr << "rigidreel: " << e.what() << '\n';
    return render::kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "rigidreel: " << e.what() << '\n';
    return render::kExitFailure;
  }
  return exitCode;
}
