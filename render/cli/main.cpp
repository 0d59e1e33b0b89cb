// rigidreel: the command line, a thin layer that wires scenes, the simulator and the renderer.
#include <algorithm>
#include <functional>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>

#include "render/cli/commands.h"
#include "sim/yaml/path_name.h"
#include "sim/yaml/scene_yaml.h"

namespace {

// every subcommand, in the order --help lists them (the const overload: all of them, not the parsed)
std::vector<const CLI::App*> subcommandsOf(const CLI::App& app) {
  return app.get_subcommands(std::function<bool(const CLI::App*)>{});
}

// "simulate, check, ..."
std::string subcommandList(const CLI::App& app) {
  std::string list;
  for (const CLI::App* sub : subcommandsOf(app)) list += (list.empty() ? "" : ", ") + sub->get_name();
  return list;
}

// an error as the terminal shows it: each control character of a name the user gave (an ESC in
// --variant) as \xNN, not sent raw; its line breaks kept
std::string shown(const std::string& message) {
  std::string out;
  size_t start = 0;
  for (size_t end; (end = message.find('\n', start)) != std::string::npos; start = end + 1)
    out += sim::yaml::shownName(std::string_view(message).substr(start, end - start)) + '\n';
  return out + sim::yaml::shownName(std::string_view(message).substr(start));
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"rigidreel: simulate and render 2D and 3D rigid-body scenes written in YAML (a 3D scene says dimensions: 3)"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "rigidreel " RIGIDREEL_VERSION);
  app.footer(
      "Exit status: 0 success; 1 a run failed (an expect entry missed, a simulation diverged, a tool failed); "
      "2 bad input (a scene file or a command-line value, named with what to do); 130 interrupted (Ctrl-C, SIGTERM).\n"
      "`rigidreel SUBCOMMAND --help` says what each takes.");
  int exitCode = render::jobs::kExitOk;
  render::cli::addSimulateCommand(app, exitCode);
  render::cli::addCheckCommand(app, exitCode);
  render::cli::addSweepCommand(app, exitCode);
  render::cli::addStabilityCommand(app, exitCode);
  render::cli::addRenderCommand(app, exitCode);
  render::cli::addSnapshotCommand(app, exitCode);
  render::cli::addLectureCommand(app, exitCode);
  render::cli::addGoldenCommand(app, exitCode);
  render::cli::addCompareCommand(app, exitCode);
  render::cli::addExpectCommand(app, exitCode);
  // no subcommand, or one that does not exist: say which there are (CLI11 says only that one is required)
  const std::string first = argc > 1 ? argv[1] : "";
  const std::vector<const CLI::App*> subs = subcommandsOf(app);
  const bool known = std::any_of(subs.begin(), subs.end(), [&](const CLI::App* s) { return s->check_name(first); });
  if (first.empty() || (first[0] != '-' && !known)) {
    std::cerr << "rigidreel: " << (first.empty() ? "give a subcommand" : "unknown subcommand '" + first + "'")
              << "; choose one of: " << subcommandList(app) << " (rigidreel --help says what each does)\n";
    return render::jobs::kExitBadInput;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : render::jobs::kExitBadInput;
  } catch (const sim::yaml::SceneError& e) {
    std::cerr << shown(e.what()) << '\n';
    return render::jobs::kExitBadInput;
  } catch (const render::jobs::UsageError& e) {
    std::cerr << "rigidreel: " << shown(e.what()) << '\n';
    return render::jobs::kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "rigidreel: " << shown(e.what()) << '\n';
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
