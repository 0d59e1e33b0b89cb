#include "render/scene/render_yaml.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>

#include "render/scene/output_name_rules.h"

namespace render::scene {
using sim::yaml::describe;
using sim::yaml::Reader;

namespace {

std::string formatted(double x) {
  std::ostringstream o;
  o << x;
  return o.str();
}

// reads the render: block's values, each checked where it is written
class RenderReader {
 public:
  explicit RenderReader(const Reader& r) : r_(r) {}

  std::string color(const YAML::Node& n, const std::string& key) const {
    const std::string c = r_.text(n, key);
    const bool hex = c.size() == 7 && c[0] == '#' &&
                     std::all_of(c.begin() + 1, c.end(), [](char ch) { return std::isxdigit(static_cast<unsigned char>(ch)); });
    if (!hex) r_.fail(n, "'" + key + "' must be a color written \"#rrggbb\", got '" + c + "'");
    return c;
  }

  void size(const YAML::Node& n, RenderDef& out) const {
    if (!n.IsSequence() || n.size() != 2) r_.fail(n, "expected [width, height] in pixels for 'size', got " + describe(n));
    out.width = r_.wholeNumber(n[0], "size", kMinFrameSide, kMaxFrameSide);
    out.height = r_.wholeNumber(n[1], "size", kMinFrameSide, kMaxFrameSide);
    if (out.width % 2 || out.height % 2)
      r_.fail(n, "'size' must have even sides (H.264 video halves the color planes); try [" +
                     std::to_string(out.width + out.width % 2) + ", " + std::to_string(out.height + out.height % 2) + "]");
  }

  void camera(const YAML::Node& n, CameraDef& out) const {
    out.loc = {n.Mark().line + 1, n.Mark().column + 1};
    if (n.IsScalar()) {
      if (n.Scalar() != "auto") r_.fail(n, "'camera' is 'auto' or {center: [x, y], height: h}, got '" + n.Scalar() + "'");
      out.automatic = true;
      return;
    }
    r_.checkKeys(n, {"center", "height", "margin"}, "camera");
    if (n["center"] || n["height"]) {
      if (!n["center"] || !n["height"]) r_.fail(n, "a fixed camera needs both 'center' and 'height'");
      if (n["margin"]) r_.fail(n["margin"], "'margin' is for the automatic camera; a fixed camera shows exactly 'height'");
      out.automatic = false;
      out.center = r_.vec2(n["center"], "center");
      out.height = r_.positive(n["height"], "height");
      if (!(out.height <= kMaxViewExtent) || !(out.center.cwiseAbs().maxCoeff() <= kMaxViewExtent))
        r_.fail(n,
                "a fixed camera's center and height are at most 1e150 m (the frame's pixels would not be "
                "finite numbers); give a view of what the scene holds");
    }
    if (n["margin"]) {
      out.margin = r_.nonNegative(n["margin"], "margin");
      if (out.margin >= 0.5) r_.fail(n["margin"], "'margin' is a fraction of the view on each side, below 0.5");
    }
  }

  // the palette, and each role's color by its key in the role table
  void colors(const YAML::Node& n, ColorsDef& out) const {
    sim::yaml::Keys keys = {"palette"};
    for (const draw::RoleInfo& role : draw::kRoles)
      if (!role.colorKey.empty() && std::find(keys.begin(), keys.end(), role.colorKey) == keys.end())
        keys.emplace_back(role.colorKey);
    r_.checkKeys(n, keys, "colors");
    if (const YAML::Node p = n["palette"]) {
      if (!p.IsSequence() || p.size() == 0) r_.fail(p, "'palette' must be a list of at least one \"#rrggbb\" color");
      out.palette.clear();
      for (const YAML::Node& c : p) out.palette.push_back(color(c, "palette"));
    }
    for (const draw::RoleInfo& role : draw::kRoles) {
      const std::string key(role.colorKey);
      if (!key.empty() && n[key]) out.roles[static_cast<size_t>(role.role)] = color(n[key], key);
    }
  }

 private:
  const Reader& r_;
};

}  // namespace

void readFrame(const YAML::Node& node, const Reader& reader, RenderDef& out) {
  const RenderReader r(reader);
  if (node["size"]) r.size(node["size"], out);
  if (const YAML::Node n = node["fps"]) {
    out.fps = reader.positive(n, "fps");
    if (out.fps > kMaxFps) reader.fail(n, "'fps' must be at most " + formatted(kMaxFps) + ", got " + n.Scalar());
  }
  if (node["background"]) out.background = r.color(node["background"], "background");
  reader.optional(node, "line_width", out.lineWidth, &Reader::positive);
  if (node["font_size"]) out.fontSize = reader.between(node["font_size"], "font_size", kMinFontSize, kMaxFontSize);
  if (node["colors"]) r.colors(node["colors"], out.colors);
}

std::string readColor(const YAML::Node& n, const Reader& reader, const std::string& key) {
  return RenderReader(reader).color(n, key);
}

namespace {

// a switch that is `auto`, true or false: `auto` leaves `on` (and sets `automatic`), the others set it
void readAuto(const YAML::Node& node, const Reader& reader, const std::string& key, bool& on, bool& automatic) {
  if (!node[key]) return;
  const YAML::Node n = node[key];
  automatic = n.IsScalar() && n.Scalar() == "auto";
  if (automatic) {
    on = true;
    return;
  }
  std::string word = n.IsScalar() ? n.Scalar() : "";
  for (char& c : word) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const char* spelling : {"true", "yes", "on", "false", "no", "off"})
    if (word == spelling) {
      on = reader.boolean(n, key);
      return;
    }
  reader.fail(n, "expected auto, true or false for '" + key + "', got " + describe(n));
}

// the block's own keys, but for the overlays and panels read after it
void readBlock(const YAML::Node& node, const Reader& reader, RenderDef& out) {
  reader.checkKeys(node,
                   {"size", "fps", "background", "line_width", "font_size", "colors", "camera", "contacts", "contact_hold",
                    "impulses", "impulse_scale", "velocities", "velocity_scale", "trails", "centers", "sat", "strobe", "springs",
                    "labels", "time", "key", "panels",
                    // video timing and text
                    "title", "title_card", "caption", "slow_motion", "answer_card", "reveal",

                    // the lecture overlays, read by readOverlays
                    "arrows", "force_scale", "momentum_scale", "impact_values", "energy", "momentum", "sat_axes"},
                   "render");
  const RenderReader r(reader);
  readFrame(node, reader, out);
  if (node["camera"]) r.camera(node["camera"], out.camera);
  readAuto(node, reader, "contacts", out.contacts, out.contactsAuto);
  reader.optional(node, "contact_hold", out.contactHold, &Reader::nonNegative);
  reader.optional(node, "impulses", out.impulses, &Reader::boolean);
  reader.optional(node, "impulse_scale", out.impulseScale, &Reader::positive);
  reader.optional(node, "velocities", out.velocities, &Reader::boolean);
  reader.optional(node, "velocity_scale", out.velocityScale, &Reader::positive);
  reader.optional(node, "trails", out.trails, &Reader::boolean);
  reader.optional(node, "centers", out.centers, &Reader::boolean);
  reader.optional(node, "sat", out.sat, &Reader::boolean);
  if (node["strobe"]) out.strobe = reader.wholeNumber(node["strobe"], "strobe", 0, 100);
  reader.optional(node, "springs", out.springs, &Reader::boolean);
  readAuto(node, reader, "labels", out.labels, out.labelsAuto);
  reader.optional(node, "time", out.time, &Reader::boolean);
  reader.optional(node, "key", out.key, &Reader::boolean);
  readTiming(node, reader, out);
}

ArrowDef readArrow(const YAML::Node& n, const Reader& reader, const sim::scene::SceneDef& scene) {
  reader.checkKeys(n, {"body", "show", "at", "label", "value", "color"}, "an arrow");
  ArrowDef a;
  a.body = scene.bodyIndex(reader.bodyRef(n, "body", scene, "an arrow"));
  a.show = reader.named(
      reader.required(n, "show", "an arrow"), "show", [](const std::string& s) { return kShowNames.parse(s); },
      kShowNames.list());
  reader.optional(n, "at", a.at, &Reader::vec2);
  reader.optional(n, "label", a.label, &Reader::text);
  reader.optional(n, "value", a.value, &Reader::boolean);
  if (n["color"]) a.color = RenderReader(reader).color(n["color"], "color");
  return a;
}

}  // namespace

void readOverlays(const YAML::Node& node, const Reader& reader, const sim::scene::SceneDef& scene, OverlaysDef& out) {
  if (const YAML::Node arrows = node["arrows"]) {
    if (!arrows.IsSequence()) reader.fail(arrows, "'arrows' must be a list of {body, show}, got " + describe(arrows));
    out.arrows.clear();
    for (const YAML::Node& a : arrows) out.arrows.push_back(readArrow(a, reader, scene));
  }
  reader.optional(node, "force_scale", out.forceScale, &Reader::positive);
  reader.optional(node, "momentum_scale", out.momentumScale, &Reader::positive);
  reader.optional(node, "impact_values", out.impactValues, &Reader::boolean);
  reader.optional(node, "energy", out.energy, &Reader::boolean);
  reader.optional(node, "momentum", out.momentum, &Reader::boolean);
  reader.optional(node, "sat_axes", out.satAxes, &Reader::boolean);
}

void readPanels(const YAML::Node& node, const Reader& reader, double duration, size_t variants, PanelsDef& out) {
  out = {};
  if (!node) {
    if (variants >= 2) out.times = {duration};
    return;
  }
  out.line = node.Mark().line + 1;
  out.column = node.Mark().column + 1;
  if (variants == 0)
    reader.fail(node, "'panels' puts the variants side by side, and this scene has none; add 'variants:' or remove 'panels'");
  if (node.IsScalar() && node.Scalar() == "impacts") {
    out.impacts = true;
    return;
  }
  if (!node.IsSequence())
    reader.fail(node, "'panels' is a list of times in seconds, e.g. [0, 1.5], or 'impacts'; got " + describe(node));
  for (const YAML::Node& t : node) {
    const double time = reader.nonNegative(t, "panels");
    if (time > duration)
      reader.fail(t, "a panel at " + formatted(time) + " s is after the scene's duration (" + formatted(duration) +
                         " s); give times from 0 to the duration");
    out.times.push_back(time);
  }
}

std::vector<BodyLook> readLooks(const YAML::Node& bodies, const Reader& reader) {
  std::vector<BodyLook> looks;
  for (const YAML::Node& n : bodies) {
    BodyLook look;
    if (n["color"]) look.color = readColor(n["color"], reader, "color");
    look.label = n["label"] ? reader.text(n["label"], "label") : n["name"].Scalar();
    look.named = static_cast<bool>(n["label"]);
    looks.push_back(std::move(look));
  }
  return looks;
}

RenderDef readRender(const sim::yaml::SceneSource& source, const sim::scene::SceneDef& model) {
  return sim::yaml::readGuarded(source.file, [&] {
    Reader reader(source.file);
    reader.placeUnmarked(source.variantMark);
    checkOutputNames(source, model.name, reader);
    RenderDef out;
    out.bodies = readLooks(source.root["bodies"], reader);
    const YAML::Node block = source.root[kRenderKey];
    if (block) {
      readBlock(block, reader, out);
      readOverlays(block, reader, model, out.overlays);
    }
    readPanels(block ? block["panels"] : block, reader, model.duration, model.variantNames.size(), out.panels);
    readPoll(source.root, block, reader, source.file, model.duration, out.poll);
    return out;
  });
}

}  // namespace render::scene
