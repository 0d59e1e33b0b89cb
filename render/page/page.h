// The lecture pack as one page, DIR/index.html: a table of contents, then per scene its title,
// description and closed-form checks, each variant's video (with its poster, size and duration),
// the poll panels labeled question and answer, and links to every file; last, what each job took.
// Plain HTML and CSS, no script and nothing from the network: it works opened from disk and served
// by any static server, so the folder can be copied to a course's web site as it is.
//
// The page is built from what the folder holds: every DIR/<scene>/page.json (scene_record.h) and
// the files they name, read for their sizes and durations. A job rebuilds it after writing its own
// record, under a lock on DIR, so jobs that end together write it one after the other and the last
// sees every record; `rigidreel lecture --page DIR` rebuilds it alone.
#pragma once

#include <string>
#include <vector>

#include "render/page/media_info.h"
#include "render/page/scene_record.h"

namespace render::page {

inline constexpr const char* kPageName = "index.html";
// the page's title, a line in DIR/title.txt (`lecture --title TEXT` writes it), so that every job
// and `--page` rebuild the page under the same title
inline constexpr const char* kTitleName = "title.txt";
inline constexpr const char* kDefaultTitle = "Lecture pack";

// a scene's record with what its files hold
struct PageScene {
  SceneRecord record;
  std::vector<MediaInfo> videos, posters, panels;  // in the record's order
};

// the scenes of the pack in `dir`, in their folders' order.txt (scene_record.h's order) first, the
// others by folder name; throws render::jobs::UsageError for a missing
// folder, a malformed record (PATH:LINE:COL) or a file a record names that is missing or unreadable
std::vector<PageScene> readPack(const std::string& dir);

// the page, under `title`
std::string pageHtml(const std::vector<PageScene>& scenes, const std::string& title = kDefaultTitle);

// the pack's title: DIR/title.txt's line, or kDefaultTitle
std::string packTitle(const std::string& dir);
// writes DIR/title.txt atomically; throws UsageError for an empty title or one of several lines
void writePackTitle(const std::string& dir, const std::string& title);

// reads the pack in `dir` and writes DIR/index.html atomically, under an exclusive lock on `dir`;
// returns the number of scenes on it. Throws as readPack does, and UsageError for a folder that
// holds no scenes
size_t writePage(const std::string& dir);

// text for HTML: & < > " ' escaped, control characters and bytes that are not UTF-8 replaced
// (render/jobs/xml_text.h)
std::string escapeHtml(const std::string& text);
// a relative URL of a path: each byte outside [A-Za-z0-9-._~/] percent-encoded
std::string urlOf(const std::string& path);

}  // namespace render::page
