#include "sim/yaml/scene_source.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <unordered_map>
#include <unordered_set>
#include <utility>

#include <yaml-cpp/depthguard.h>

#include "sim/yaml/first_document.h"
#include "sim/yaml/path_name.h"
#include "sim/yaml/yaml_reader.h"

namespace sim::yaml {

namespace {

// the merge nests as deep as yaml-cpp lets a file's own text nest (its parser's depth guard): deeper
// nesting can come only through aliases, and the merge's recursion would overflow the stack
constexpr int kMaxMergeDepth = 500;

// A variant merged over the scene: maps key by key, the bodies list by name (each body's keys
// replaced whole), other values whole. The merge builds new maps and lists out of the file's
// nodes and never changes one: yaml-cpp's nodes are shared by every alias of them, so a merge in
// place would change every place an alias appears, and merging a map into itself (`{a: &m {...},
// a: *m}`) would insert into the map it iterates. Each key-value pair of the file costs it at
// least one byte, so a merge that visits more pairs than the file has bytes is repeating them
// through aliases (an alias bomb, tenfold per level): it stops there instead of running for hours.
class VariantMerge {
 public:
  VariantMerge(const Reader& r, std::string variant, size_t fileBytes)
      : r_(r), variant_(std::move(variant)), budget_(fileBytes) {}

  YAML::Node map(const YAML::Node& base, const YAML::Node& over, bool deep) {
    const Nested nested(depth_);
    if (depth_ > kMaxMergeDepth)
      r_.fail(over, "variant '" + variant_ + "' nests its maps more than " + std::to_string(kMaxMergeDepth) +
                        " levels deep through aliases (*name); write the changes out instead of nesting aliases");
    // the changes by name, each given once
    std::unordered_map<std::string, std::pair<YAML::Node, YAML::Node>> changes;
    std::vector<std::string> order;
    for (const auto& kv : over) {
      const std::string name = keyName(kv.first);
      if (!changes.emplace(name, std::pair{kv.first, kv.second}).second)
        r_.fail(kv.first, "duplicate key '" + name + "' in variant '" + variant_ + "'; give each key once");
      order.push_back(name);
    }
    // the base's pairs in their order, changed where the variant says; then the variant's new keys
    YAML::Node out = fresh(YAML::NodeType::Map);
    std::unordered_set<std::string> merged;
    for (const auto& kv : base) {
      visit(kv.first);
      const auto change = kv.first.IsScalar() ? changes.find(kv.first.Scalar()) : changes.end();
      if (change == changes.end() || !merged.insert(change->first).second) {
        out.force_insert(kv.first, kv.second);
        continue;
      }
      const YAML::Node& value = change->second.second;
      if (deep && kv.second.IsMap() && value.IsMap()) out.force_insert(kv.first, map(kv.second, value, true));
      else if (deep && change->first == "bodies" && kv.second.IsSequence() && value.IsSequence())
        out.force_insert(kv.first, bodies(kv.second, value));
      else out.force_insert(kv.first, value);
    }
    for (const std::string& name : order)
      if (!merged.count(name)) out.force_insert(changes[name].first, changes[name].second);
    return out;
  }

 private:
  // one level of map() deeper for as long as it lives
  struct Nested {
    explicit Nested(int& depth) : depth_(depth) { ++depth_; }
    ~Nested() { --depth_; }
    int& depth_;
  };

  // the bodies by name: a body the variant names has its keys replaced, others are added
  YAML::Node bodies(const YAML::Node& base, const YAML::Node& over) {
    std::unordered_map<std::string, YAML::Node> changes;
    for (const YAML::Node& body : over) {
      visit(body);
      const YAML::Node name = nameOf(body);
      if (name && !changes.emplace(name.Scalar(), body).second)
        r_.fail(name, "body '" + name.Scalar() + "' is changed twice in variant '" + variant_ + "'; give its changes once");
    }
    YAML::Node out = fresh(YAML::NodeType::Sequence);
    std::unordered_set<std::string> merged;
    for (const YAML::Node& body : base) {
      visit(body);
      const YAML::Node name = nameOf(body);
      const auto change = name ? changes.find(name.Scalar()) : changes.end();
      if (change == changes.end()) {
        out.push_back(body);
      } else {
        out.push_back(map(body, change->second, false));
        merged.insert(change->first);
      }
    }
    for (const YAML::Node& body : over) {
      const YAML::Node name = nameOf(body);
      if (!name || !merged.count(name.Scalar())) out.push_back(body);
    }
    return out;
  }

  // a body's name, when it has one to merge by
  static YAML::Node nameOf(const YAML::Node& body) {
    if (!body.IsMap()) return YAML::Node();
    const YAML::Node name = body["name"];
    return name && name.IsScalar() ? name : YAML::Node();
  }

  std::string keyName(const YAML::Node& key) {
    visit(key);
    if (!key.IsScalar()) r_.fail(key, "a key in variant '" + variant_ + "' must be a name, got " + describe(key));
    return key.Scalar();
  }

  void visit(const YAML::Node& at) {
    if (budget_-- == 0)
      r_.fail(at, "variant '" + variant_ +
                      "' repeats its values through aliases (*name) beyond the file's own size; "
                      "write the changes out instead of nesting aliases");
  }

  // a new node in the memory of the nodes made before it. yaml-cpp's node memory is a set that a
  // node joining another's absorbs: a map made apart would copy the whole file's set on its
  // first insert; kept in one pool, the file's set is copied once.
  YAML::Node fresh(YAML::NodeType::value type) {
    pool_.push_back(YAML::Node(type));
    return pool_[pool_.size() - 1];
  }

  const Reader& r_;
  const std::string variant_;
  size_t budget_;
  int depth_ = 0;  // map() calls open now
  YAML::Node pool_{YAML::NodeType::Sequence};
};

// the variants' names, each checked
void listVariants(const Reader& r, SceneDocument& s) {
  const YAML::Node variants = std::as_const(s.root)["variants"];
  if (variants) {
    if (!variants.IsMap()) r.fail(variants, "'variants' must be a map from names to changes, got " + describe(variants));
    for (const auto& kv : variants) {
      if (!kv.second.IsMap() && !kv.second.IsNull())
        r.fail(kv.second, "variant '" + kv.first.Scalar() + "' must be a map of changes, got " + describe(kv.second));
      if (const std::string fault = pathNameFault(kv.first.Scalar()); !fault.empty())
        r.fail(kv.first, "variant name '" + shownName(kv.first.Scalar()) + "' names output files but " + fault +
                             "; use letters, digits, '-' or '_'");
      // a name given twice: the second would be dropped and the first run twice
      if (std::find(s.variantNames.begin(), s.variantNames.end(), kv.first.Scalar()) != s.variantNames.end())
        r.fail(kv.first, "variant '" + kv.first.Scalar() + "' is defined twice; give each variant once, or rename one");
      s.variantNames.push_back(kv.first.Scalar());
      if (kv.second.IsMap() && kv.second["dimensions"])
        r.fail(kv.second["dimensions"], "a variant cannot change 'dimensions': a scene is 2D or 3D throughout");
    }
  }
}

// the chosen variant merged over the base scene
void mergeVariant(const Reader& r, const SceneDocument& d, SceneSource& s) {
  if (s.variant.empty()) return;
  const YAML::Node variants = std::as_const(d.root)["variants"];
  if (std::find(s.variantNames.begin(), s.variantNames.end(), s.variant) == s.variantNames.end()) {
    std::string known;
    for (const auto& n : s.variantNames) known += (known.empty() ? "" : ", ") + n;
    r.fail(variants ? variants : d.root,
           "unknown variant '" + s.variant + "'; " + (known.empty() ? "this scene has no variants" : "this scene has: " + known));
  }
  for (const auto& kv : variants)
    if (kv.first.Scalar() == s.variant) s.variantMark = kv.first.Mark();
  const YAML::Node changes = variants[s.variant];
  if (changes.IsMap()) {
    if (changes["variants"]) r.fail(changes["variants"], "a variant cannot define variants");
    // (reset, not =: assigning to a node handle rewrites the node it holds, here the document's root)
    s.root.reset(VariantMerge(r, s.variant, d.bytes).map(d.root, changes, true));
  }
}

std::string stem(const std::string& path) {
  std::string base = path.substr(path.find_last_of('/') + 1);
  if (base.size() > 5 && base.ends_with(".yaml")) base.resize(base.size() - 5);
  else if (base.size() > 4 && base.ends_with(".yml")) base.resize(base.size() - 4);
  return base;
}

// the bytes a UTF-8 byte order mark takes at the start of the text: yaml-cpp's marks do not count it
size_t bomBytes(const std::string& text) { return text.starts_with("\xEF\xBB\xBF") ? 3 : 0; }

// the text at byte `pos` opens a document of its own: a '---' there, or a '...' line (the end of
// the one before) above it, comments and blank lines between
bool startsSecondDocument(const std::string& text, size_t pos) {
  if (pos >= text.size() || text.compare(pos, 3, "---") == 0) return true;
  const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
  size_t end = text.rfind('\n', pos);
  while (end != std::string::npos && end > bomBytes(text)) {
    const size_t begin = text.rfind('\n', end - 1);
    size_t from = begin == std::string::npos ? bomBytes(text) : begin + 1;
    while (from < end && blank(text[from])) ++from;
    if (from < end && text[from] != '#')
      return text.compare(from, 3, "...") == 0 && (from + 3 == end || blank(text[from + 3]) || text[from + 3] == '#');
    if (begin == std::string::npos) break;
    end = begin;
  }
  return false;
}

}  // namespace

SceneDocument sceneDocumentText(const std::string& text, const std::string& file) {
  SceneDocument d{file, stem(file), {}, {}, 2, text.size()};
  try {
    const FirstDocument parsed = loadFirstDocument(text);
    // a second document would otherwise be ignored without a word
    if (parsed.second) {
      const YAML::Mark at = *parsed.second;
      const int line = at.is_null() ? 1 : at.line + 1, column = at.is_null() ? 1 : at.column + 1;
      // the parser also starts a "document" at text it cannot read as one (a line opening with ','):
      // only a '---', or text after a '...', is a second document
      const size_t pos = bomBytes(text) + static_cast<size_t>(std::max(at.pos, 0));
      if (!at.is_null() && !startsSecondDocument(text, pos)) {
        // the character quoted when it is printable ASCII (not a byte of a longer UTF-8 one)
        const std::string what = text[pos] > ' ' && text[pos] < 0x7f ? std::string("'") + text[pos] + "'" : "this text";
        throw SceneError(
            file, line, column,
            "invalid YAML: a scene cannot start with " + what + " here; a scene file is one YAML map of `key: value` lines");
      }
      throw SceneError(file, line, column,
                       "a second YAML document (after '---'): a scene file holds one scene; put the other in a file of its own");
    }
    d.root.reset(parsed.root);
  } catch (const YAML::DeepRecursion& e) {
    // yaml-cpp's guard against a stack overflow says only "bad file"
    throw SceneError(file, e.mark.is_null() ? 0 : e.mark.line + 1, e.mark.column + 1,
                     "lists and maps nested " + std::to_string(e.depth()) +
                         " levels deep, past the parser's limit; a scene needs a handful of levels: flatten the nesting");
  } catch (const YAML::ParserException& e) {
    throw SceneError(file, e.mark.line + 1, e.mark.column + 1, "invalid YAML: " + e.msg);
  }
  if (!d.root || d.root.IsNull()) throw SceneError(file, 1, 1, "the scene is empty; it needs at least 'bodies:'");
  readGuarded(file, [&] {
    const Reader r(file);
    if (!d.root.IsMap()) r.fail(d.root, "a scene is a map with at least 'bodies:'; got " + describe(d.root));
    listVariants(r, d);
    if (const YAML::Node n = std::as_const(d.root)["dimensions"]) {
      const double value = r.number(n, "dimensions");
      if (value != 2.0 && value != 3.0) r.fail(n, "'dimensions' is 2 (the default: a plane) or 3 (space), got " + n.Scalar());
      d.dimensions = static_cast<int>(value);
    }
  });
  return d;
}

SceneSource sceneSource(const SceneDocument& d, const std::string& variant) {
  SceneSource s{d.file, d.stem, variant, d.variantNames, d.root, d.dimensions, YAML::Mark::null_mark()};
  readGuarded(d.file, [&] { mergeVariant(Reader(d.file), d, s); });
  return s;
}

SceneSource sceneSourceText(const std::string& text, const std::string& file, const std::string& variant) {
  return sceneSource(sceneDocumentText(text, file), variant);
}

SceneDocument readSceneDocument(const std::string& path) {
  // only a regular file: opening a FIFO blocks until a writer comes, a device never ends
  std::error_code error;
  const std::filesystem::file_type kind = std::filesystem::status(path, error).type();
  if (kind == std::filesystem::file_type::directory)
    throw SceneError(path, 0, 0, "is a directory, not a scene file; give the path of a .yaml file");
  if (kind != std::filesystem::file_type::regular && kind != std::filesystem::file_type::not_found)
    throw SceneError(path, 0, 0,
                     std::string("is ") +
                         (kind == std::filesystem::file_type::fifo     ? "a FIFO (named pipe)"
                          : kind == std::filesystem::file_type::socket ? "a socket"
                                                                       : "a device") +
                         ", not a regular file; give the path of a scene file (.yaml)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError(path, 0, 0, "cannot open the scene file (does it exist and is it readable?)");
  // read in pieces up to the limit, not to the end: /dev/zero and pipes have no end
  std::string text;
  char piece[65536];
  while (in.read(piece, sizeof piece) || in.gcount() > 0) {
    text.append(piece, static_cast<size_t>(in.gcount()));
    if (text.size() > kMaxSceneBytes)
      throw SceneError(path, 0, 0,
                       "is larger than the limit of " + std::to_string(kMaxSceneBytes >> 20) +
                           " MiB for a scene file; is it a scene? (100,000 bodies written one a line take 6 MB)");
  }
  if (in.bad()) throw SceneError(path, 0, 0, "cannot read the scene file");
  return sceneDocumentText(text, path);
}

SceneSource readSceneSource(const std::string& path, const std::string& variant) {
  return sceneSource(readSceneDocument(path), variant);
}

}  // namespace sim::yaml
