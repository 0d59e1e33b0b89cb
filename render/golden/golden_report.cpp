#include "render/golden/golden_report.h"

#include <filesystem>
#include <vector>
#include <fstream>

#include "render/draw/png_io.h"
#include "render/jobs/atomic_file.h"
#include "render/jobs/json_writer.h"
#include "render/jobs/xml_text.h"
#include "render/page/page.h"

namespace render::golden {

namespace fs = std::filesystem;

using render::jobs::escapeXml;
namespace {
// a path in the report as an attribute takes it: URL-encoded ('#', '?', '%'), then escaped
std::string srcOf(const std::string& path) { return escapeXml(render::page::urlOf(path)); }
}  // namespace

void writeReport(const std::vector<CaseResult>& results, const std::string& dir) {
  render::jobs::StagedDirectory folder(dir, "golden report");
  const fs::path to = folder.path();
  std::ofstream html(to / "index.html");
  size_t failed = 0;
  for (const CaseResult& c : results) failed += c.failed();
  html << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
          "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>rigidreel golden check</title>\n"
          "<style>\nbody{font-family:sans-serif;margin:1em auto;max-width:80em;padding:0 1em}\n"
          "table{border-collapse:collapse;width:100%;table-layout:fixed}"
          "td,th{border:1px solid #ccc;padding:.3em .6em;text-align:left;vertical-align:top;overflow-wrap:anywhere}\n"
          "col.scene{width:28%}col.level{width:14%}\n"
          ".ok{color:#2a7d2a}.failed{color:#c0392b;font-weight:bold}.skipped{color:#a66f00}\n"
          ".frames{display:flex;flex-wrap:wrap;gap:.5em}.frames figure{margin:0;flex:1 1 18em;min-width:0}\n"
          ".frames img{width:100%;height:auto;border:1px solid #ccc}figcaption{font-size:.9em}\n"
          "</style>\n</head>\n<body>\n<h1>rigidreel golden check</h1>\n<p>"
       << results.size() << " scene variants, " << failed
       << " failed. A failure at one level and not the others says where to look: "
       << "<em>state</em> the physics, <em>draw_list</em> what is shown, <em>pixels</em> only the rasterizer.</p>\n";
  html << "<table>\n<col class=\"scene\"><col class=\"level\"><col>\n<tr><th>scene</th><th>level</th><th>result</th></tr>\n";
  // the failed scene variants first: in a course's pack they are the few to read
  std::vector<const CaseResult*> order;
  for (const CaseResult& c : results)
    if (c.failed()) order.push_back(&c);
  for (const CaseResult& c : results)
    if (!c.failed()) order.push_back(&c);
  for (const CaseResult* pc : order)
    for (const LevelResult& l : pc->levels) {
      const CaseResult& c = *pc;
      const char* cls = l.status == LevelResult::Status::Failed    ? "failed"
                        : l.status == LevelResult::Status::Skipped ? "skipped"
                                                                   : "ok";
      html << "<tr><td><a href=\"#" << srcOf(c.name) << "\">" << escapeXml(c.name) << "</a></td><td>" << levelName(l.level)
           << "</td><td class=\"" << cls << "\">" << escapeXml(l.message) << "</td></tr>\n";
    }
  html << "</table>\n";
  for (const CaseResult& c : results) {
    html << "<section id=\"" << escapeXml(c.name) << "\">\n<h2>" << escapeXml(c.name) << "</h2>\n<p>" << escapeXml(c.file)
         << "</p>\n";
    for (const std::string& w : c.warnings) html << "<p class=\"skipped\">warning: " << escapeXml(w) << "</p>\n";
    for (const LevelResult& l : c.levels)
      for (const FrameDiff& f : l.frames) {
        const fs::path sub = to / c.name;
        fs::create_directories(sub);
        fs::copy_file(f.expectedPng, sub / (f.name + "-expected.png"), fs::copy_options::overwrite_existing);
        render::draw::writePng(f.actual, (sub / (f.name + "-actual.png")).string());
        render::draw::writePng(f.diff, (sub / (f.name + "-diff.png")).string());
        html << "<h3>" << escapeXml(f.name) << " (t = " << render::jobs::formatNumber(f.t) << " s)</h3>\n<p>"
             << escapeXml(f.message) << "</p>\n<div class=\"frames\">\n";
        for (const char* kind : {"expected", "actual", "diff"})
          html << "<figure><img src=\"" << srcOf(c.name + "/" + f.name + "-" + kind + ".png") << "\" alt=\"" << kind
               << " frame of " << escapeXml(c.name) << " at t = " << render::jobs::formatNumber(f.t) << "\"><figcaption>" << kind
               << (std::string(kind) == "diff" ? ": pixels off by more than the tolerance in red" : "")
               << "</figcaption></figure>\n";
        html << "</div>\n";
      }
    html << "</section>\n";
  }
  html << "</body>\n</html>\n";
  html.close();
  if (!html) throw std::runtime_error("cannot write " + (to / "index.html").string());
  folder.commit();
}

void writeJunit(const std::vector<CaseResult>& results, const std::string& path) {
  std::vector<JunitCase> cases;
  for (const CaseResult& c : results)
    for (const LevelResult& l : c.levels) cases.push_back({c.name, levelName(l.level), c.file, l.status, l.message});
  writeJunit(cases, "rigidreel golden check", path);
}

void writeJunit(const std::vector<JunitCase>& cases, const std::string& suite, const std::string& path) {
  render::jobs::AtomicFile file(path);
  std::ostream& out = file.stream();
  size_t tests = 0, failures = 0, skipped = 0;
  for (const JunitCase& l : cases) {
    ++tests;
    failures += l.status == LevelResult::Status::Failed;
    skipped += l.status == LevelResult::Status::Skipped;
  }
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"rigidreel\" tests=\"" << tests << "\" failures=\""
      << failures << "\" skipped=\"" << skipped << "\">\n<testsuite name=\"" << escapeXml(suite) << "\" tests=\"" << tests
      << "\" failures=\"" << failures << "\" errors=\"0\" skipped=\"" << skipped << "\">\n";
  for (const JunitCase& l : cases) {
    out << "  <testcase classname=\"" << escapeXml(l.classname) << "\" name=\"" << escapeXml(l.name) << "\" file=\""
        << escapeXml(l.file) << "\"";
    if (l.status == LevelResult::Status::Ok) {
      out << "/>\n";
      continue;
    }
    out << ">\n";
    if (l.status == LevelResult::Status::Failed)
      out << "    <failure message=\"" << escapeXml(l.message) << "\">" << escapeXml(l.message) << "</failure>\n";
    else out << "    <skipped message=\"" << escapeXml(l.message) << "\"/>\n";
    out << "  </testcase>\n";
  }
  out << "</testsuite>\n</testsuites>\n";
  file.commit();
}

}  // namespace render::golden
