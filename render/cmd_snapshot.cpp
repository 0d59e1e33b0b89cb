// `rigidreel snapshot`: still frames of a scene at exact times or at its impacts, one PNG each, or
// with --panels every variant side by side in one labeled image (the poll slide).
#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>

#include "commands.h"
#include "output.h"
#include "panels.h"
#include "png_io.h"
#include "scene_options.h"
#include "scene_run.h"

namespace render {

namespace {

struct SnapshotOptions : SceneOptions {
  std::string at;
  bool impacts = false;
  bool panels = false;
  std::optional<int> strobe;
  std::string output = "out";
  std::string size;
};

// "0.5,1,2.25" → {0.5, 1, 2.25}; throws UsageError
std::vector<double> parseTimes(const std::string& text) {
  std::vector<double> times;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    size_t used = 0;
    double t = 0.0;
    try {
      t = std::stod(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    while (used < item.size() && std::isspace(static_cast<unsigned char>(item[used]))) ++used;
    if (item.empty() || used != item.size() || !std::isfinite(t))
      throw UsageError("--at: expected times in seconds separated by commas, e.g. 0.5,1.25; got '" + text + "'");
    times.push_back(t);
  }
  if (times.empty()) throw UsageError("--at: give at least one time");
  return times;
}

// one variant of the scene, with the command line's overrides
struct Variant {
  sim::SceneDef def;
  RunSurvey survey;
};

int snapshot(const SnapshotOptions& o) {
  if (o.at.empty() == !o.impacts) throw UsageError("give the times with --at T1,T2,... or ask for --impacts (one of them)");
  if (o.panels && !o.variant.empty())
    throw UsageError("--panels shows every variant side by side; leave out --variant");
  if (o.strobe && (*o.strobe < 0 || *o.strobe > 100)) throw UsageError("--strobe: give a number of ghosts from 0 to 100");
  std::optional<FrameSize> size;
  if (!o.size.empty()) size = parseSize(o.size);

  // the variants: every one side by side, or the one asked for (or the base scene)
  std::vector<std::string> names = {o.variant};
  if (o.panels) {
    names = o.load().variantNames;
    if (names.empty()) throw UsageError("--panels: " + o.scene + " has no variants to put side by side");
  }
  std::vector<Variant> variants;
  for (const std::string& name : names) {
    SceneOptions one = o;
    one.variant = name;
    Variant v{one.load(), {}};
    if (size) v.def.render.width = size->width, v.def.render.height = size->height;
    v.survey = surveyRun(v.def);
    variants.push_back(std::move(v));
  }
  const sim::SceneDef& first = variants.front().def;
  const int strobe = o.strobe.value_or(first.render.strobe);

  // the instants: per panel, per variant (the same --at times for all; each variant's own impacts)
  std::vector<std::vector<double>> instants;  // [shot][variant]
  if (!o.at.empty()) {
    for (double t : parseTimes(o.at)) {
      for (const Variant& v : variants)
        if (t < 0.0 || t > v.def.duration)
          throw UsageError("--at: " + timeForName(t) + " s is outside the scene's duration [0, " +
                           timeForName(v.def.duration) + "]");
      instants.push_back(std::vector<double>(variants.size(), t));
    }
  } else {
    size_t most = 0;
    for (const Variant& v : variants) {
      if (v.survey.impactTimes.empty())
        throw UsageError("--impacts: " + o.scene + (v.def.variant.empty() ? "" : " (variant " + v.def.variant + ")") +
                         " has no impacts in its " + timeForName(v.def.duration) +
                         " s; nothing collides there (use --at to choose times)");
      most = std::max(most, v.survey.impactTimes.size());
    }
    // shot i: each variant at its i-th impact, or at its last when it has fewer
    for (size_t i = 0; i < most; ++i) {
      std::vector<double> shot;
      for (const Variant& v : variants) shot.push_back(v.survey.impactTimes[std::min(i, v.survey.impactTimes.size() - 1)]);
      instants.push_back(shot);
    }
  }

  // one camera for all panels, so that the variants compare at the same scale
  Bounds bounds;
  for (const Variant& v : variants) bounds.add(v.survey.bounds);
  const std::string dir = outputDirectory(o.output, first.name);
  const std::string strobeSuffix = strobe > 0 ? "-strobe" + std::to_string(strobe) : "";
  GlContext gl(first.render.width, first.render.height);
  TextRenderer text;
  for (size_t shot = 0; shot < instants.size(); ++shot) {
    std::vector<Image> frames;
    std::vector<std::string> titles;
    for (size_t i = 0; i < variants.size(); ++i) {
      const Variant& v = variants[i];
      const double t = instants[shot][i];
      // a fresh run per picture: the strobe ghosts and the trails start from t = 0
      SceneRun run(v.def, cameraFor(v.def, bounds), v.survey, &gl, &text);
      frames.push_back(run.frameAt(t, strobe));
      // "A: center", or just "A" for a variant named A
      std::string title = panelLetter(i);
      if (v.def.variant != title) title += ": " + v.def.variant;
      if (o.impacts) title += "  (t = " + timeForName(t) + " s)";
      titles.push_back(title);
    }
    std::string path;
    if (o.panels) {
      const std::string when = o.impacts ? "-impact" + std::to_string(shot + 1) : "-t" + timeForName(instants[shot][0]);
      path = dir + "/" + first.name + "-panels" + when + strobeSuffix + ".png";
      const Style style = makeStyle(first, first.render.height);
      writePng(composePanels(frames, titles, style, text), path);
    } else {
      const std::string when = (o.impacts ? "-impact" + std::to_string(shot + 1) : "") + "-t" + timeForName(instants[shot][0]);
      path = dir + "/" + outputBase(first) + when + strobeSuffix + ".png";
      writePng(frames.front(), path);
    }
    std::cout << path << '\n';
  }
  return kExitOk;
}

}  // namespace

void addSnapshotCommand(CLI::App& app, int& exitCode) {
  auto o = std::make_shared<SnapshotOptions>();
  CLI::App* cmd = app.add_subcommand("snapshot", "still frames of a scene as PNG under out/<scene>/");
  cmd->add_option("scene", o->scene, "the scene file (YAML)")->required();
  o->addTo(*cmd);
  cmd->add_option("--at", o->at, "times in seconds, separated by commas: one PNG each");
  cmd->add_flag("--impacts", o->impacts, "one PNG at each impact the collision response resolves");
  cmd->add_flag("--panels", o->panels, "every variant side by side in one labeled image");
  cmd->add_option("--strobe", o->strobe, "draw this many earlier poses, fading, behind the present one");
  cmd->add_option("-o,--output", o->output, "the output directory (default: out)");
  cmd->add_option("--size", o->size, "frame size WIDTHxHEIGHT in pixels, even (default: the scene's, 1280x720)");
  cmd->callback([o, &exitCode] {
    try {
      exitCode = snapshot(*o);
    } catch (const sim::Diverged& d) {
      std::cerr << o->scene << ": the simulation diverged at t = " << timeForName(d.time)
                << "; try a smaller step (--dt) or another integrator (--integrator rk4)\n";
      exitCode = kExitFailure;
    }
  });
}

}  // namespace render
