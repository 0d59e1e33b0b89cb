#include "render/cli/check_tally.h"

#include "render/golden/golden_report.h"

namespace render::cli {

void CheckTally::add(const std::string& file, const std::string& variant, std::vector<std::string> failures) {
  variants_.push_back({file, variant, std::move(failures)});
}

void CheckTally::failLast(const std::string& failure) { variants_.back().failures.push_back(failure); }

void CheckTally::failScene(const std::string& file, const std::string& failure) {
  variants_.push_back({file, "scene", {failure}});
}

bool CheckTally::failed(const std::string& file) const {
  for (const Variant& v : variants_)
    if (v.file == file && !v.failures.empty()) return true;
  return false;
}

std::string CheckTally::summary() const {
  size_t failed = 0;
  for (const Variant& v : variants_) failed += !v.failures.empty();
  return std::to_string(scenes_) + " scenes, " + std::to_string(variants_.size()) +
         " variants: " + std::to_string(variants_.size() - failed) + " passed, " + std::to_string(failed) + " failed";
}

void CheckTally::writeJunit(const std::string& path) const {
  using render::golden::LevelResult;
  std::vector<render::golden::JunitCase> cases;
  for (const Variant& v : variants_) {
    std::string message;
    for (const std::string& f : v.failures) message += (message.empty() ? "" : "\n") + f;
    cases.push_back({v.file, v.variant.empty() ? "base" : v.variant, v.file,
                     v.failures.empty() ? LevelResult::Status::Ok : LevelResult::Status::Failed, message});
  }
  render::golden::writeJunit(cases, "rigidreel check", path);
}

}  // namespace render::cli
