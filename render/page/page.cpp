#include "render/page/page.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <sstream>

#include "render/jobs/atomic_file.h"
#include "render/jobs/bounded_read.h"
#include "render/jobs/exit_status.h"
#include "render/jobs/read_limits.h"
#include "render/jobs/regular_file.h"
#include "render/jobs/xml_text.h"

namespace render::page {
using namespace render::jobs;

namespace fs = std::filesystem;

namespace {

// a number as people read it: up to `digits` significant digits, no trailing zeros
std::string shown(double x, int digits = 4) {
  if (!std::isfinite(x)) return "—";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*g", digits, x);
  return buf;
}

// a value as the page shows it: 6 digits, and 0 below `zeroBelow` (round-off, not data)
std::string shownValues(const std::vector<double>& v, double zeroBelow = 0.0) {
  const auto one = [zeroBelow](double x) { return shown(std::abs(x) < zeroBelow ? 0.0 : x, 6); };
  if (v.size() == 1) return one(v[0]);
  std::string s = "(";
  for (size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + one(v[i]);
  return s + ")";
}

// a check's noise floor: 10⁻¹² of its largest value, at least of 1 (SI values of a lecture's scenes),
// so that a simulated (8.9e-16, 2.2e-16) of a closed form (0, 0) reads (0, 0); its error says the rest
double noiseFloorOf(const CheckRecord& c) {
  double most = 1.0;
  for (double x : c.expected) most = std::max(most, std::abs(x));
  for (double x : c.actual) most = std::max(most, std::abs(x));
  return 1e-12 * most;
}

// the scene file's own number, "10a" of 10a_energy_gain.yaml: its leading digits and the letters
// after them, up to a '_' or '-'; "" when it has none
std::string fileNumber(const std::string& file) {
  const std::string stem = fs::path(file).stem().string();
  size_t digits = 0;
  while (digits < stem.size() && std::isdigit(static_cast<unsigned char>(stem[digits]))) ++digits;
  size_t end = digits;
  while (end < stem.size() && std::islower(static_cast<unsigned char>(stem[end]))) ++end;
  if (digits == 0 || (end < stem.size() && stem[end] != '_' && stem[end] != '-')) return "";
  return stem.substr(0, end);
}

// an id for a scene's section, one per name: ASCII letters, digits, '-' and '_' as they are, every
// other byte as ".XX" (HTML ids have no spaces; "Stoß" and "Stoä" differ)
std::string sectionId(const std::string& scene) {
  std::string id = "scene-";
  for (unsigned char c : scene) {
    if (std::isalnum(c) || c == '-' || c == '_') {
      id += static_cast<char>(c);
      continue;
    }
    char hex[4];
    std::snprintf(hex, sizeof hex, ".%02X", c);
    id += hex;
  }
  return id;
}

// an exclusive lock on a directory, held while the object lives (flock(2) on the directory itself:
// no lock file left behind). Where locks are not supported it goes without: `--page` rebuilds
class DirectoryLock {
 public:
  explicit DirectoryLock(const std::string& dir) : fd_(::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC)) {
    if (fd_ >= 0) ::flock(fd_, LOCK_EX);
  }
  ~DirectoryLock() {
    if (fd_ >= 0) ::close(fd_);  // closing releases the lock
  }
  DirectoryLock(const DirectoryLock&) = delete;
  DirectoryLock& operator=(const DirectoryLock&) = delete;

 private:
  int fd_;
};

const char* const kStyle = R"(
:root { color-scheme: light; --ink: #1f1f1f; --muted: #5f6368; --line: #dadce0; --panel: #f6f7f9; --accent: #3b6ea5; }
* { box-sizing: border-box; }
body { margin: 0; font: 16px/1.5 "DejaVu Sans", system-ui, sans-serif; color: var(--ink); background: #fff; }
header, main, footer { max-width: 1200px; margin: 0 auto; padding: 0 24px; }
/* long names and paths wrap rather than widen the page */
h1, h2, code, .description, figcaption { overflow-wrap: anywhere; }
header { padding-top: 24px; border-bottom: 1px solid var(--line); }
h1 { font-size: 28px; margin: 0 0 4px; }
h2 { font-size: 22px; margin: 0 0 8px; }
h3 { font-size: 16px; margin: 16px 0 8px; }
a { color: var(--accent); }
.muted { color: var(--muted); font-size: 14px; }
/* the contents, numbered by the scene files' own numbers (10a, 10b, ...) */
nav ul { columns: 2; column-gap: 32px; list-style: none; padding-left: 0; margin: 8px 0 16px; }
li .number { display: inline-block; min-width: 3.2em; color: var(--muted); font-variant-numeric: tabular-nums; }
section { padding: 24px 0; border-bottom: 1px solid var(--line); }
.description { max-width: 80ch; white-space: pre-line; }
/* a lone video or panel takes the width; two or three share it; on a narrow screen, one a row at
   the screen's width */
.media { display: grid; grid-template-columns: repeat(auto-fit, minmax(min(360px, 100%), 1fr)); gap: 16px; }
figure { margin: 0; padding: 8px; background: var(--panel); border-radius: 6px; min-width: 0; container-type: inline-size; }
video, img { display: block; width: 100%; height: auto; background: #fff; border: 1px solid var(--line); }
/* the browser draws a video's controls over the bottom of its box, where the frame's caption is:
   the box is the picture and a strip below it (--controls) for the controls, the picture at its top
   (Chromium's controls are 72 px high, a row of buttons over the timeline; its shade over the
   picture is dropped) */
video { --controls: 80px; height: calc(100cqw * var(--ratio, 0.5625) + var(--controls)); object-fit: contain;
        object-position: top; background: #222; }
video::-webkit-media-controls-panel { background: none; }
figcaption { font-size: 14px; margin-top: 6px; }
.question { color: #8a4b08; font-weight: bold; }
.answer { color: #1e6b34; font-weight: bold; }
.poll-question { max-width: 80ch; font-size: 18px; }
details.poll-answer { margin-top: 16px; max-width: 80ch; }
details.poll-answer summary { cursor: pointer; font-weight: bold; color: #1e6b34; }
/* a wide table scrolls inside its own box, never the page */
.table { max-width: 100%; overflow-x: auto; }
table { border-collapse: collapse; font-size: 14px; margin-top: 4px; }
th, td { border-bottom: 1px solid var(--line); padding: 4px 10px; text-align: left; vertical-align: top; }
td.number { text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }
.ok { color: #1e6b34; }
.failed { color: #b3261e; font-weight: bold; }
footer { padding-top: 16px; padding-bottom: 32px; }
@media (max-width: 600px) {
  header, main, footer { padding-left: 12px; padding-right: 12px; }
  nav ul { columns: 1; }
  h1 { font-size: 24px; }
  /* on a phone a table's columns would lie off the screen: each row is a card of its cells, each
     cell after its column's heading (data-label); the headings stay for screen readers */
  .table thead { position: absolute; width: 1px; height: 1px; overflow: hidden; clip-path: inset(50%); white-space: nowrap; }
  .table table, .table tbody, .table tr { display: block; }
  .table tr { padding: 6px 0; border-bottom: 1px solid var(--line); }
  .table td, .table td.number { display: flex; justify-content: space-between; gap: 16px; border: 0; padding: 1px 0;
                                text-align: right; white-space: normal; overflow-wrap: anywhere; }
  .table td::before { content: attr(data-label); color: var(--muted); text-align: left; white-space: nowrap; }
}
)";

// a table in a box of its own: its columns under their headings, the box scrolling sideways when
// they are wider still; on a phone each row a card, each cell labelled with its column's heading
const char* const kTableOpen = "<div class=\"table\">\n<table>\n";
const char* const kTableClose = "</table>\n</div>\n";

// a table's cell: its class ("" for none) and its HTML
struct Cell {
  std::string cls, html;
};

// the table's box opened and its headings (text) written
void writeTableHead(std::ostream& h, const std::vector<std::string>& headings) {
  h << kTableOpen << "<thead><tr>";
  for (const std::string& heading : headings) h << "<th>" << escapeHtml(heading) << "</th>";
  h << "</tr></thead>\n<tbody>\n";
}

// one row, each cell labelled with its column's heading (the card's labels on a phone)
void writeTableRow(std::ostream& h, const std::vector<std::string>& headings, const std::vector<Cell>& cells) {
  h << "<tr>";
  for (size_t i = 0; i < cells.size(); ++i) {
    h << "<td";
    if (!cells[i].cls.empty()) h << " class=\"" << cells[i].cls << "\"";
    h << " data-label=\"" << escapeHtml(i < headings.size() ? headings[i] : std::string()) << "\">" << cells[i].html << "</td>";
  }
  h << "</tr>\n";
}

// the checks of one kind: closed forms, or values an earlier run gave
void writeChecks(std::ostream& h, const std::vector<CheckRecord>& checks, bool earlierRun) {
  std::vector<const CheckRecord*> these;
  for (const CheckRecord& c : checks)
    if (c.earlierRun == earlierRun) these.push_back(&c);
  if (these.empty()) return;
  h << "<h3>" << (earlierRun ? "Checked against an earlier run" : "Closed forms, checked") << "</h3>\n";
  const std::vector<std::string> headings = {"variant",   "t (s)", "quantity",  earlierRun ? "earlier run" : "closed form",
                                             "simulated", "error", "tolerance", ""};
  writeTableHead(h, headings);
  for (const CheckRecord* c : these)
    writeTableRow(h, headings,
                  {{"", escapeHtml(c->variant.empty() ? "—" : c->variant)},
                   {"number", shown(c->time, 6)},
                   {"", escapeHtml(c->quantity)},
                   {"number", shownValues(c->expected)},
                   {"number", shownValues(c->actual, noiseFloorOf(*c))},
                   {"number", shown(c->error, 2)},
                   {"number", shown(c->tolerance, 2)},
                   c->passed() ? Cell{"ok", "ok"} : Cell{"failed", "FAILED"}});
  h << "</tbody>\n" << kTableClose;
}

// a file of the scene's folder, relative to the page
std::string href(const SceneRecord& r, const std::string& file) { return urlOf(r.scene + "/" + file); }

// the panels `which` of a scene, side by side
void writePanels(std::ostream& h, const PageScene& s, const std::vector<size_t>& which) {
  const SceneRecord& r = s.record;
  h << "<div class=\"media\">\n";
  for (size_t i : which) {
    const PanelRecord& p = r.panels[i];
    const MediaInfo& m = s.panels[i];
    const std::string role = p.question ? "question" : p.answer ? "answer" : "";
    h << "<figure>\n<a href=\"" << href(r, p.image) << "\"><img src=\"" << href(r, p.image) << "\" width=\"" << m.width
      << "\" height=\"" << m.height << "\" alt=\"" << escapeHtml(r.title) << ", every variant side by side"
      << (role.empty() ? "" : ", " + role) << " (" << escapeHtml(p.when) << ")\"></a>\n<figcaption>"
      << (role.empty() ? "" : "<span class=\"" + role + "\">" + role + "</span> · ") << escapeHtml(p.when) << " · <a href=\""
      << href(r, p.image) << "\">" << escapeHtml(p.image) << "</a></figcaption>\n</figure>\n";
  }
  h << "</div>\n";
}

void writeSection(std::ostream& h, const PageScene& s) {
  const SceneRecord& r = s.record;
  const std::string number = fileNumber(r.file);
  h << "<section id=\"" << sectionId(r.scene) << "\">\n<h2>"
    << (number.empty() ? "" : "<span class=\"muted\">" + escapeHtml(number) + "</span> ") << escapeHtml(r.title) << "</h2>\n";
  h << "<p class=\"muted\"><code>" << escapeHtml(r.file) << "</code></p>\n";
  if (!r.description.empty()) h << "<p class=\"description\">" << escapeHtml(r.description) << "</p>\n";
  if (!r.question.empty()) h << "<p class=\"poll-question\"><strong>Question.</strong> " << escapeHtml(r.question) << "</p>\n";

  h << "<h3>" << (r.videos.size() == 1 ? "Video" : "Videos") << "</h3>\n<div class=\"media\">\n";
  for (size_t i = 0; i < r.videos.size(); ++i) {
    const VideoRecord& v = r.videos[i];
    const MediaInfo& m = s.videos[i];
    h << "<figure>\n<video controls preload=\"metadata\" width=\"" << m.width << "\" height=\"" << m.height << "\" poster=\""
      << href(r, v.poster) << "\" data-duration=\"" << shown(m.duration, 9)
      << "\" style=\"--ratio: " << shown(static_cast<double>(m.height) / std::max(1, m.width), 6) << "\">"
      << "<source src=\"" << href(r, v.video) << "\" type=\"video/mp4\">"
      << "<a href=\"" << href(r, v.video) << "\">" << escapeHtml(v.video) << "</a></video>\n";
    h << "<figcaption>" << (v.variant.empty() ? "" : "<strong>" + escapeHtml(v.variant) + "</strong> · ") << m.width << "×"
      << m.height << ", " << shown(v.fps) << " fps, " << shown(m.duration) << " s · <a href=\"" << href(r, v.video)
      << "\">video</a> · <a href=\"" << href(r, v.poster) << "\">poster</a></figcaption>\n</figure>\n";
  }
  h << "</div>\n";

  // the panels that ask (or simply show) in the open; those labelled "answer" (from the scene's
  // `reveal` time on) folded away with the answer's text until clicked, so the page can be shown in class
  std::vector<size_t> open, answers;
  for (size_t i = 0; i < r.panels.size(); ++i) (r.panels[i].answer ? answers : open).push_back(i);
  if (!open.empty()) {
    h << "<h3>Poll panels</h3>\n";
    writePanels(h, s, open);
  }
  // a poll's checks tell its outcome too (speeds, energies), so they fold away with the answer
  const bool poll = !r.question.empty();
  if (!r.answer.empty() || !answers.empty() || (poll && !r.checks.empty())) {
    h << "<details class=\"poll-answer\"><summary>Answer</summary>\n";
    if (!r.answer.empty()) h << "<p class=\"description\">" << escapeHtml(r.answer) << "</p>\n";
    if (!answers.empty()) writePanels(h, s, answers);
    if (poll) writeChecks(h, r.checks, false), writeChecks(h, r.checks, true);
    h << "</details>\n";
  }
  if (!poll) writeChecks(h, r.checks, false), writeChecks(h, r.checks, true);
  h << "</section>\n";
}

}  // namespace

std::string escapeHtml(const std::string& text) { return render::jobs::escapeXml(text); }

std::string urlOf(const std::string& path) {
  std::string out;
  for (unsigned char c : path) {
    if (std::isalnum(c) || c == '-' || c == '.' || c == '_' || c == '~' || c == '/') {
      out += static_cast<char>(c);
    } else {
      char buf[4];
      std::snprintf(buf, sizeof buf, "%%%02X", c);
      out += buf;
    }
  }
  return out;
}

std::vector<PageScene> readPack(const std::string& dir) {
  std::error_code error;
  if (!fs::is_directory(dir, error))
    throw UsageError(dir + ": no such directory; give the folder that `rigidreel lecture -o DIR` writes");
  std::vector<fs::path> folders;
  for (const fs::directory_entry& e : fs::directory_iterator(dir, error)) {
    const std::string name = e.path().filename().string();
    if (!name.empty() && name[0] != '.' && e.is_directory() && fs::exists(e.path() / kRecordName)) folders.push_back(e.path());
  }
  std::sort(folders.begin(), folders.end());
  std::vector<PageScene> scenes;
  for (const fs::path& folder : folders) {
    const std::string recordPath = (folder / kRecordName).string();
    PageScene s{readSceneRecord(recordPath), {}, {}, {}};
    const SceneRecord& r = s.record;
    if (r.scene != folder.filename().string())
      throw UsageError(recordPath + ": it names scene '" + r.scene + "' but lies in folder '" + folder.filename().string() +
                       "'; render the scene again to rewrite it");
    // every file it names, read: what the page says of it is what the file holds
    const auto media = [&](const std::string& file, bool video) {
      const std::string path = (folder / file).string();
      if (const std::string kind = notRegularFile(path); !kind.empty())
        throw UsageError(path + ": " + kind + " (" + recordPath + " names it); remove it and render the scene again");
      const std::optional<MediaInfo> m = video ? mp4Info(path) : pngInfo(path);
      if (!m)
        throw UsageError(recordPath + ": '" + file + "' is " +
                         (fs::exists(path) ? std::string("not a readable ") + (video ? "MP4" : "PNG") : "missing") + " in " +
                         folder.string() + "/; render the scene again");
      return *m;
    };
    for (const VideoRecord& v : r.videos) {
      s.videos.push_back(media(v.video, true));
      s.posters.push_back(media(v.poster, false));
    }
    for (const PanelRecord& p : r.panels) s.panels.push_back(media(p.image, false));
    scenes.push_back(std::move(s));
  }
  // in their folders' order.txt where they have one (first), else by name
  std::stable_sort(scenes.begin(), scenes.end(), [](const PageScene& a, const PageScene& b) {
    const auto place = [](const PageScene& s) { return s.record.order > 0 ? s.record.order : std::numeric_limits<int>::max(); };
    return place(a) < place(b);
  });
  return scenes;
}

std::string pageHtml(const std::vector<PageScene>& scenes, const std::string& title) {
  size_t videos = 0, panels = 0;
  for (const PageScene& s : scenes) videos += s.record.videos.size(), panels += s.record.panels.size();
  std::ostringstream h;
  h << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
       "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
       "<title>"
    << escapeHtml(title) << ": " << scenes.size() << " scenes</title>\n<style>" << kStyle << "</style>\n</head>\n<body>\n";
  h << "<header>\n<h1>" << escapeHtml(title) << "</h1>\n<p class=\"muted\">" << scenes.size() << " scenes, " << videos
    << " videos, " << panels
    << " poll panels, rendered by <code>rigidreel lecture</code>. Every file is in this folder: copy it to any web server "
       "as it is.</p>\n<nav>\n<h2>Contents</h2>\n<ul>\n";
  for (const PageScene& s : scenes)
    h << "<li><span class=\"number\">" << escapeHtml(fileNumber(s.record.file)) << "</span><a href=\"#"
      << sectionId(s.record.scene) << "\">" << escapeHtml(s.record.title) << "</a></li>\n";
  h << "</ul>\n</nav>\n</header>\n<main>\n";
  for (const PageScene& s : scenes) writeSection(h, s);
  h << "</main>\n<footer>\n<h2>How it was made</h2>\n";
  const std::vector<std::string> headings = {"scene", "videos", "frame size", "fps", "job (s)"};
  writeTableHead(h, headings);
  double total = 0.0;
  for (const PageScene& s : scenes) {
    const SceneRecord& r = s.record;
    std::string sizes, rates;
    for (size_t i = 0; i < r.videos.size(); ++i) {
      const std::string size = std::to_string(s.videos[i].width) + "×" + std::to_string(s.videos[i].height);
      if (sizes.find(size) == std::string::npos) sizes += (sizes.empty() ? "" : ", ") + size;
      if (rates.find(shown(r.videos[i].fps)) == std::string::npos) rates += (rates.empty() ? "" : ", ") + shown(r.videos[i].fps);
    }
    total += r.seconds;
    writeTableRow(h, headings,
                  {{"", "<a href=\"#" + sectionId(r.scene) + "\">" + escapeHtml(r.scene) + "</a>"},
                   {"number", std::to_string(r.videos.size())},
                   {"", sizes},
                   {"", rates},
                   {"number seconds", shown(r.seconds, 3)}});
  }
  h << "</tbody>\n"
    << kTableClose << "<p class=\"muted seconds\">" << shown(total, 4)
    << " s of job time in all; jobs that ran at once overlap in wall time.</p>\n</footer>\n</body>\n</html>\n";
  return h.str();
}

std::string packTitle(const std::string& dir) {
  const fs::path path = fs::path(dir) / kTitleName;
  std::error_code error;
  if (!fs::exists(fs::symlink_status(path, error))) return kDefaultTitle;
  const std::string text(withoutBom(readBounded(path.string(), kMaxListFileBytes, "page title",
                                                "write it again with `rigidreel lecture --page DIR --title TEXT`")));
  const std::string title = text.substr(0, text.find_first_of("\r\n"));
  return title.empty() ? kDefaultTitle : title;
}

void writePackTitle(const std::string& dir, const std::string& title) {
  if (title.empty() || title.find_first_of("\n\r") != std::string::npos)
    throw UsageError("--title: give the page's title as one line of text, e.g. --title \"Rigid body motion\"");
  AtomicFile file((fs::path(dir) / kTitleName).string());
  file.stream() << title << '\n';
  file.commit();
}

size_t writePage(const std::string& dir) {
  // one writer at a time: the last job to take the lock reads every record written before it
  DirectoryLock lock(dir);
  const std::vector<PageScene> scenes = readPack(dir);
  if (scenes.empty())
    throw UsageError(dir + ": no scenes here (no <scene>/" + kRecordName + "); render some with `rigidreel lecture SCENE... -o " +
                     dir + "`");
  AtomicFile page((fs::path(dir) / kPageName).string());
  page.stream() << pageHtml(scenes, packTitle(dir));
  page.commit();
  return scenes.size();
}

}  // namespace render::page
