// The lecture pack's page (render/page): a scene's record written and read back, its faults at
// FILE:LINE:COL; sizes and durations read from the files themselves; the page's HTML; the page
// built from what a folder holds, atomically and by one writer at a time.
#include "render/page/page.h"

#include <doctest/doctest.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <regex>
#include <sstream>
#include <thread>

#include "render/jobs/exit_status.h"

namespace fs = std::filesystem;
using namespace render::page;

namespace {

// a fresh directory for one test case, removed after
struct TempDir {
  explicit TempDir(const std::string& name)
      : path(fs::temp_directory_path() / ("rigidreel-page-" + name + "-" + std::to_string(::getpid()))) {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
  fs::path path;
};

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void spit(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

// a real MP4 (H.264, as the renderer writes) and a PNG, made by ffmpeg
void makeVideo(const fs::path& p, int w, int h, double seconds) {
  const std::string command = "ffmpeg -v error -y -f lavfi -i testsrc=size=" + std::to_string(w) + "x" + std::to_string(h) +
                              ":rate=10 -t " + std::to_string(seconds) + " -c:v libx264 -pix_fmt yuv420p -movflags +faststart '" +
                              p.string() + "'";
  REQUIRE(std::system(command.c_str()) == 0);
}
void makePng(const fs::path& p, int w, int h) {
  const std::string command = "ffmpeg -v error -y -f lavfi -i testsrc=size=" + std::to_string(w) + "x" + std::to_string(h) +
                              " -frames:v 1 '" + p.string() + "'";
  REQUIRE(std::system(command.c_str()) == 0);
}

SceneRecord impulses() {
  SceneRecord r;
  r.scene = "05_impulses";
  r.file = "scenes/lecture/05_impulses.yaml";
  r.title = "Impulses";
  r.description = "A bar struck at its end: \"j\" = (1, 0) N·s; <b>not</b> bold & kept as text.\nSecond line.";
  r.question = "Which moves faster, <A> or B?";
  r.answer = "Both at 1/3 m/s; only B turns.";
  r.seconds = 1.25;
  r.videos = {{"center", "05_impulses-center.mp4", "05_impulses-center.png", 10},
              {"end", "05_impulses-end.mp4", "05_impulses-end.png", 10}};
  r.panels = {{"05_impulses-panels-t0.png", "t = 0 s", true}, {"05_impulses-panels-t2.5.png", "t = 2.5 s", false, true}};
  r.checks = {{"end", 2.5, "bar.angular_velocity", {-0.5}, {-0.5000000000000001}, 1.1e-16, 1e-9},
              {"end", 2.5, "bar.velocity", {1.0 / 3, 0}, {1.0 / 3, NAN}, 0.2, 1e-9}};
  return r;
}

// a video of 160×90 and 1.5 s, a poster of 160×90 and a panel of 320×90, made once for the run
const fs::path& sample(const std::string& name) {
  static TempDir dir("samples");
  static const bool made = [] {
    makeVideo(dir.path / "video.mp4", 160, 90, 1.5);
    makePng(dir.path / "poster.png", 160, 90);
    makePng(dir.path / "panel.png", 320, 90);
    return true;
  }();
  static std::map<std::string, fs::path> paths;
  (void)made;
  return paths.emplace(name, dir.path / name).first->second;
}

// the record's files in `dir`/<scene>/, copies of the samples
void writeScene(const fs::path& dir, const SceneRecord& r) {
  const fs::path folder = dir / r.scene;
  fs::create_directories(folder);
  for (const VideoRecord& v : r.videos) {
    fs::copy_file(sample("video.mp4"), folder / v.video, fs::copy_options::skip_existing);
    fs::copy_file(sample("poster.png"), folder / v.poster, fs::copy_options::skip_existing);
  }
  for (const PanelRecord& p : r.panels) fs::copy_file(sample("panel.png"), folder / p.image, fs::copy_options::skip_existing);
  writeSceneRecord(r, (folder / kRecordName).string());
}

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const render::jobs::UsageError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("a scene's record reads back as it was written, text and numbers exact, non-finite as null") {
  TempDir dir("record");
  const SceneRecord r = impulses();
  writeSceneRecord(r, (dir.path / "page.json").string());
  const SceneRecord back = readSceneRecord((dir.path / "page.json").string());
  CHECK(back.scene == r.scene);
  CHECK(back.description == r.description);
  CHECK(back.seconds == r.seconds);
  REQUIRE(back.videos.size() == 2);
  CHECK(back.videos[1].poster == "05_impulses-end.png");
  CHECK(back.videos[1].fps == 10);
  REQUIRE(back.panels.size() == 2);
  CHECK(back.panels[0].question);
  CHECK_FALSE(back.panels[1].question);
  CHECK(back.panels[1].answer);
  CHECK(back.question == r.question);
  CHECK(back.answer == r.answer);
  REQUIRE(back.checks.size() == 2);
  CHECK(back.checks[0].actual[0] == -0.5000000000000001);
  CHECK(back.checks[1].expected[0] == 1.0 / 3);
  CHECK(std::isnan(back.checks[1].actual[1]));
  CHECK_FALSE(back.checks[1].passed());
  // written whole or not at all: no temporary file left beside it
  CHECK(std::distance(fs::directory_iterator(dir.path), fs::directory_iterator()) == 1);
}

TEST_CASE("a malformed record is reported at FILE:LINE:COL with what to do") {
  TempDir dir("bad");
  const std::string path = (dir.path / "page.json").string();
  spit(path, "{\"scene\": \"a\",\n \"file\": \"a.yaml\", \"title\": \"A\", \"description\": \"\",\n \"seconds\": \"soon\"}\n");
  CHECK(errorOf([&] { readSceneRecord(path); }).starts_with(path + ":3:13: 'soon' is not a number"));
  spit(path, "{\"scene\": \"a\",\n  \"file\": [1, 2]}\n");
  CHECK(errorOf([&] { readSceneRecord(path); }).starts_with(path + ":2:11: 'file' has the wrong type"));
  spit(path, "{\"scene\": \"a\", \"file\": \"f\"\n");
  CHECK(errorOf([&] { readSceneRecord(path); }).starts_with(path + ":2:1: not a page record"));
  spit(path, R"({"scene": "a", "file": "f", "title": "t", "description": "", "seconds": 1,
 "videos": [{"variant": "", "video": "../../etc/passwd", "poster": "p.png", "fps": 10}], "panels": [], "checks": []})");
  CHECK(errorOf([&] { readSceneRecord(path); }).find("'video' must name a file in the scene's folder") != std::string::npos);
  CHECK(errorOf([&] { readSceneRecord(path); }).ends_with("render the scene again to rewrite it"));
}

TEST_CASE("an MP4's duration and frame size and a PNG's size come from the files") {
  TempDir dir("media");
  makeVideo(dir.path / "v.mp4", 160, 90, 1.3);
  makePng(dir.path / "p.png", 64, 48);
  const std::optional<MediaInfo> v = mp4Info((dir.path / "v.mp4").string());
  REQUIRE(v);
  CHECK(v->width == 160);
  CHECK(v->height == 90);
  CHECK(v->duration == doctest::Approx(1.3).epsilon(1e-6));
  const std::optional<MediaInfo> p = pngInfo((dir.path / "p.png").string());
  REQUIRE(p);
  CHECK(p->width == 64);
  CHECK(p->height == 48);
  CHECK_FALSE(mp4Info((dir.path / "p.png").string()));
  CHECK_FALSE(pngInfo((dir.path / "v.mp4").string()));
  CHECK_FALSE(pngInfo((dir.path / "none.png").string()));
}

TEST_CASE("the page: a section per scene with its videos, posters, panels as question and answer, and checks") {
  TempDir dir("html");
  writeScene(dir.path, impulses());
  const std::vector<PageScene> scenes = readPack(dir.path.string());
  REQUIRE(scenes.size() == 1);
  CHECK(scenes[0].videos[0].duration == doctest::Approx(1.5));
  const std::string html = pageHtml(scenes);
  CHECK(html.starts_with("<!DOCTYPE html>\n<html lang=\"en\">"));
  // the contents numbered by the file's own number
  CHECK(html.find("<li><span class=\"number\">05</span><a href=\"#scene-05_impulses\">Impulses</a></li>") != std::string::npos);
  CHECK(html.find("<h2><span class=\"muted\">05</span> Impulses</h2>") != std::string::npos);
  CHECK(html.find("<title>Lecture pack: 1 scenes</title>") != std::string::npos);
  CHECK(html.find("<section id=\"scene-05_impulses\">") != std::string::npos);
  CHECK(
      html.find("<video controls preload=\"metadata\" width=\"160\" height=\"90\" poster=\"05_impulses/05_impulses-center.png\" "
                "data-duration=\"1.5\" style=\"--ratio: 0.5625\"><source src=\"05_impulses/05_impulses-center.mp4\" "
                "type=\"video/mp4\">") != std::string::npos);
  CHECK(html.find("<span class=\"question\">question</span> · t = 0 s") != std::string::npos);
  CHECK(html.find("<span class=\"answer\">answer</span> · t = 2.5 s") != std::string::npos);
  CHECK(html.find("width=\"320\" height=\"90\"") != std::string::npos);
  // the description is text, never markup
  CHECK(html.find("&lt;b&gt;not&lt;/b&gt; bold &amp; kept") != std::string::npos);
  CHECK(html.find("<b>not") == std::string::npos);
  CHECK(html.find("<td class=\"ok\" data-label=\"\">ok</td>") != std::string::npos);
  CHECK(html.find("<td class=\"failed\" data-label=\"\">FAILED</td>") != std::string::npos);
  // both checks are closed forms: one heading, and every table in a box of its own that scrolls
  CHECK(html.find("<h3>Closed forms, checked</h3>\n<div class=\"table\">\n<table>") != std::string::npos);
  CHECK(html.find("earlier run") == std::string::npos);
  CHECK(html.find("<table>") != std::string::npos);
  size_t tables = 0, boxed = 0;
  for (size_t at = html.find("<table>"); at != std::string::npos; at = html.find("<table>", at + 1)) ++tables;
  for (size_t at = html.find("<div class=\"table\">\n<table>"); at != std::string::npos;
       at = html.find("<div class=\"table\">\n<table>", at + 1))
    ++boxed;
  CHECK(tables == 2);
  CHECK(boxed == tables);
  CHECK(html.find("<script") == std::string::npos);
  CHECK(html.find("http") == std::string::npos);  // nothing from the network
}

TEST_CASE("the page: the question above the videos, the answer only inside a closed <details> after them") {
  TempDir dir("poll");
  SceneRecord r = impulses();
  // a mid-run panel before `reveal`: neither question nor answer
  r.panels.push_back({"05_impulses-panels-t1.png", "t = 1 s", false, false});
  writeScene(dir.path, r);
  const std::string html = pageHtml(readPack(dir.path.string()));
  const size_t question =
      html.find("<p class=\"poll-question\"><strong>Question.</strong> Which moves faster, &lt;A&gt; or B?</p>");
  const size_t video = html.find("<video");
  const size_t details = html.find("<details class=\"poll-answer\"><summary>Answer</summary>");
  REQUIRE(question != std::string::npos);
  REQUIRE(details != std::string::npos);
  CHECK(question < video);
  CHECK(video < details);
  // once, inside the details, which is closed (no `open`)
  const size_t answer = html.find("Both at 1/3 m/s; only B turns.");
  CHECK(answer > details);
  CHECK(answer < html.find("</details>", details));
  CHECK(html.find("Both at 1/3", answer + 1) == std::string::npos);
  CHECK(html.find("<details open") == std::string::npos);
  CHECK(html.find("<figcaption>t = 1 s · ") != std::string::npos);
  CHECK(html.find("answer</span> · t = 1 s") == std::string::npos);
  // the answer's panel (t = 2.5 s) folded away with the text, the question's in the open before it
  const size_t questionPanel = html.find("<img src=\"05_impulses/" + r.panels[0].image + "\"");
  const size_t answerPanel = html.find("<img src=\"05_impulses/" + r.panels[1].image + "\"");
  REQUIRE(r.panels[1].answer);
  REQUIRE(questionPanel != std::string::npos);
  REQUIRE(answerPanel != std::string::npos);
  CHECK(questionPanel < details);
  CHECK(answerPanel > details);
  CHECK(answerPanel < html.find("</details>", details));
  CHECK(html.find("<img src=\"05_impulses/" + r.panels[1].image + "\"", answerPanel + 1) == std::string::npos);
  // the checks (the outcome's numbers) folded away as well
  const size_t closedForms = html.find("<h3>Closed forms, checked</h3>");
  const size_t earlier = html.find("<h3>Checked against an earlier run</h3>");
  REQUIRE(closedForms != std::string::npos);
  CHECK(closedForms > details);
  CHECK(html.find("</table>", closedForms) < html.find("</details>", details));
  CHECK(earlier == std::string::npos);  // (both of impulses() are closed forms)
}

TEST_CASE("the page: a scene that asks nothing shows its checks in the open") {
  TempDir dir("shown");
  SceneRecord r = impulses();
  r.question.clear(), r.answer.clear();
  for (PanelRecord& p : r.panels) p.question = p.answer = false;
  writeScene(dir.path, r);
  const std::string html = pageHtml(readPack(dir.path.string()));
  CHECK(html.find("<details") == std::string::npos);
  CHECK(html.find("<h3>Closed forms, checked</h3>") != std::string::npos);
}

// each table's column headings, and the data-label of every cell of each of its rows
struct TableLabels {
  std::vector<std::string> headings;
  std::vector<std::vector<std::string>> rows;
};
std::vector<TableLabels> tableLabels(const std::string& html) {
  static const std::regex kHeading("<th>([^<]*)</th>"), kRow("<tr>(.*?)</tr>"), kCell("<td[^>]*>"),
      kLabel(" data-label=\"([^\"]*)\"");
  std::vector<TableLabels> tables;
  for (size_t at = html.find("<table>"); at != std::string::npos; at = html.find("<table>", at + 1)) {
    const std::string table = html.substr(at, html.find("</table>", at) - at);
    const std::string head = table.substr(0, table.find("</thead>")), body = table.substr(head.size());
    TableLabels t;
    for (std::sregex_iterator h(head.begin(), head.end(), kHeading), end; h != end; ++h) t.headings.push_back((*h)[1]);
    for (std::sregex_iterator r(body.begin(), body.end(), kRow), end; r != end; ++r) {
      const std::string row = (*r)[1];
      std::vector<std::string> labels;
      for (std::sregex_iterator c(row.begin(), row.end(), kCell); c != end; ++c) {
        const std::string cell = c->str();
        std::smatch label;
        labels.push_back(std::regex_search(cell, label, kLabel) ? label[1].str() : "(none)");
      }
      t.rows.push_back(labels);
    }
    tables.push_back(t);
  }
  return tables;
}

TEST_CASE("on a phone each table row is a card: every cell carries its column's heading") {
  TempDir dir("cards");
  SceneRecord r = impulses();
  r.checks[1].earlierRun = true;
  writeScene(dir.path, r);
  const std::string html = pageHtml(readPack(dir.path.string()));
  const std::vector<TableLabels> tables = tableLabels(html);
  // the closed forms, the earlier run's values, how the pack was made
  REQUIRE(tables.size() == 3);
  CHECK(tables[0].headings ==
        std::vector<std::string>{"variant", "t (s)", "quantity", "closed form", "simulated", "error", "tolerance", ""});
  CHECK(tables[1].headings[3] == "earlier run");
  CHECK(tables[2].headings == std::vector<std::string>{"scene", "videos", "frame size", "fps", "job (s)"});
  for (const TableLabels& t : tables) {
    CHECK(t.rows.size() >= 1);
    for (const std::vector<std::string>& row : t.rows) CHECK(row == t.headings);
  }
  // the cards are laid out on narrow screens alone, the labels drawn from the cells' data-label
  const size_t phone = html.find("@media (max-width: 600px)");
  REQUIRE(phone != std::string::npos);
  const size_t labels = html.find(".table td::before { content: attr(data-label)");
  CHECK(labels > phone);
  CHECK(labels < html.find("</style>"));
}

TEST_CASE("closed forms and values an earlier run gave are headed apart") {
  TempDir dir("sources");
  SceneRecord r = impulses();
  r.checks[1].earlierRun = true;
  writeScene(dir.path, r);
  const std::vector<PageScene> scenes = readPack(dir.path.string());
  CHECK(scenes[0].record.checks[1].earlierRun);
  CHECK_FALSE(scenes[0].record.checks[0].earlierRun);
  const std::string html = pageHtml(scenes);
  const size_t closed = html.find("<h3>Closed forms, checked</h3>"),
               earlier = html.find("<h3>Checked against an earlier run</h3>");
  REQUIRE(closed != std::string::npos);
  REQUIRE(earlier != std::string::npos);
  // each table has its own row and its own column heading
  CHECK(html.find("<th>closed form</th>", closed) < earlier);
  CHECK(html.find("bar.angular_velocity", closed) < earlier);
  CHECK(html.find("<th>earlier run</th>", earlier) != std::string::npos);
  CHECK(html.find("bar.velocity", earlier) != std::string::npos);
  CHECK(html.find("bar.velocity", closed) > earlier);
}

TEST_CASE("the contents number scenes by their files' own numbers; the title is the pack's") {
  SceneRecord a = impulses(), b = impulses(), c = impulses();
  a.file = "scenes/lecture/10a_energy_gain.yaml", a.scene = "10a_energy_gain";
  b.file = "scenes/lecture/11_state_in_3d.yaml", b.scene = "11_state_in_3d";
  c.file = "scenes/extra/notes.yaml", c.scene = "notes";
  // (no files: the contents and headings are what is looked at)
  for (SceneRecord* r : {&a, &b, &c}) r->videos.clear(), r->panels.clear();
  const std::string html = pageHtml({{a, {}, {}, {}}, {b, {}, {}, {}}, {c, {}, {}, {}}}, "Rigid <body> motion");
  CHECK(html.find("<span class=\"number\">10a</span><a href=\"#scene-10a_energy_gain\">") != std::string::npos);
  CHECK(html.find("<span class=\"number\">11</span><a href=\"#scene-11_state_in_3d\">") != std::string::npos);
  // a file without a number has none (never a count of its own)
  CHECK(html.find("<span class=\"number\"></span><a href=\"#scene-notes\">") != std::string::npos);
  CHECK(html.find("<title>Rigid &lt;body&gt; motion: 3 scenes</title>") != std::string::npos);
  CHECK(html.find("<h1>Rigid &lt;body&gt; motion</h1>") != std::string::npos);
  CHECK(html.find("Lecture pack") == std::string::npos);
}

TEST_CASE("the pack's title lives in DIR/title.txt; scenes follow their order.txt places, then their names") {
  TempDir dir("order");
  CHECK(packTitle(dir.path.string()) == "Lecture pack");
  writePackTitle(dir.path.string(), "Rigid body motion");
  CHECK(packTitle(dir.path.string()) == "Rigid body motion");
  CHECK(errorOf([&] { writePackTitle(dir.path.string(), "two\nlines"); }).find("--title") != std::string::npos);
  CHECK(errorOf([&] { writePackTitle(dir.path.string(), ""); }).find("--title") != std::string::npos);
  CHECK(packTitle(dir.path.string()) == "Rigid body motion");
  SceneRecord a = impulses(), b = impulses(), c = impulses();
  a.scene = "a_first", b.scene = "b_second", c.scene = "c_third";
  a.order = 0, b.order = 2, c.order = 1;
  for (SceneRecord* r : {&a, &b, &c}) writeScene(dir.path, *r);
  const std::vector<PageScene> scenes = readPack(dir.path.string());
  REQUIRE(scenes.size() == 3);
  CHECK(scenes[0].record.scene == "c_third");
  CHECK(scenes[1].record.scene == "b_second");
  CHECK(scenes[2].record.scene == "a_first");  // no place in order.txt: after those that have one
  CHECK(scenes[0].record.order == 1);
  writePage(dir.path.string());
  CHECK(slurp(dir.path / kPageName).find("<h1>Rigid body motion</h1>") != std::string::npos);
}

TEST_CASE("links are relative and percent-encoded; text is escaped") {
  CHECK(urlOf("a b/ç?.png") == "a%20b/%C3%A7%3F.png");
  CHECK(escapeHtml("<a href=\"x\">'&'</a>") == "&lt;a href=&quot;x&quot;&gt;&#39;&amp;&#39;&lt;/a&gt;");
}

TEST_CASE("the page is built from what the folder holds; a file a record names must be there") {
  TempDir dir("pack");
  CHECK(errorOf([&] { writePage(dir.path.string()); }).find("no scenes here") != std::string::npos);
  CHECK(errorOf([&] { writePage((dir.path / "nope").string()); }).find("no such directory") != std::string::npos);
  SceneRecord a = impulses();
  SceneRecord b = impulses();
  b.scene = "02_other", b.title = "Other", b.panels.clear();
  for (VideoRecord& v : b.videos) v.video = "02_" + v.video, v.poster = "02_" + v.poster;
  writeScene(dir.path, a);
  writeScene(dir.path, b);
  // a folder without a record and a hidden one are not scenes
  fs::create_directories(dir.path / "notes");
  fs::create_directories(dir.path / ".staging" / "x");
  CHECK(writePage(dir.path.string()) == 2);
  const std::string html = slurp(dir.path / kPageName);
  // in the folders' order
  CHECK(html.find("scene-02_other") < html.find("scene-05_impulses"));
  CHECK_FALSE(fs::exists(dir.path / (std::string(kPageName) + ".part-" + std::to_string(::getpid()))));

  fs::remove(dir.path / "05_impulses" / "05_impulses-end.png");
  const std::string missing = errorOf([&] { writePage(dir.path.string()); });
  CHECK(missing.find("'05_impulses-end.png' is missing") != std::string::npos);
  // the old page stays as it was
  CHECK(slurp(dir.path / kPageName) == html);
  spit(dir.path / "05_impulses" / "05_impulses-end.png", "not a png");
  CHECK(errorOf([&] { writePage(dir.path.string()); }).find("'05_impulses-end.png' is not a readable PNG") != std::string::npos);
  fs::rename(dir.path / "02_other", dir.path / "03_moved");
  CHECK(errorOf([&] { readPack(dir.path.string()); }).find("names scene '02_other' but lies in folder '03_moved'") !=
        std::string::npos);
}

TEST_CASE("jobs that end together never lose a scene from the page: one writer at a time, the last sees all") {
  TempDir dir("race");
  // one scene's files, copied into twelve folders; then twelve writers at once, each writing its
  // record and the page, as twelve `lecture` jobs of a GNU Parallel run do
  SceneRecord first = impulses();
  first.panels.clear();
  writeScene(dir.path, first);
  std::vector<SceneRecord> records;
  for (int i = 0; i < 12; ++i) {
    SceneRecord r = first;
    r.scene = "scene" + std::to_string(10 + i);
    fs::create_directories(dir.path / r.scene);
    for (const VideoRecord& v : r.videos) {
      fs::copy_file(dir.path / first.scene / v.video, dir.path / r.scene / v.video);
      fs::copy_file(dir.path / first.scene / v.poster, dir.path / r.scene / v.poster);
    }
    records.push_back(r);
  }
  std::vector<std::thread> writers;
  for (const SceneRecord& r : records)
    writers.emplace_back([&dir, r] {
      writeSceneRecord(r, (dir.path / r.scene / kRecordName).string());
      writePage(dir.path.string());
    });
  for (std::thread& w : writers) w.join();
  const std::string html = slurp(dir.path / kPageName);
  for (const SceneRecord& r : records) CHECK(html.find("<section id=\"scene-" + r.scene + "\">") != std::string::npos);
  CHECK(html.find("<title>Lecture pack: 13 scenes</title>") != std::string::npos);
}

TEST_CASE("a check's simulated round-off reads 0, its error still says how far off it was") {
  TempDir dir("roundoff");
  SceneRecord r = impulses();
  r.question.clear(), r.answer.clear();
  r.checks = {{"", 1.5, "box.position", {0, 0}, {8.88178e-16, 2.22045e-16}, 9.2e-16, 1e-12},
              {"", 3, "box.velocity", {2, 0}, {2.001, 3e-5}, 1e-3, 1e-2}};
  writeScene(dir.path, r);
  const std::string html = pageHtml(readPack(dir.path.string()));
  CHECK(html.find("8.88178e-16") == std::string::npos);
  CHECK(html.find("<td class=\"number\" data-label=\"closed form\">(0, 0)</td><td class=\"number\" data-label=\"simulated\">(0, "
                  "0)</td><td class=\"number\" data-label=\"error\">9.2e-16</td>") != std::string::npos);
  // a small value that is no round-off of its row is data: shown
  CHECK(html.find("(2, 0)</td><td class=\"number\" data-label=\"simulated\">(2.001, 3e-05)</td>") != std::string::npos);
}
