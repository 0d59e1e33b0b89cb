// What `check` ran, variant by variant, for a course's CI: the one summary line a log ends with
// ("3 scenes, 5 variants: 4 passed, 1 failed") and a JUnit testcase per variant with its failures.
#pragma once

#include <string>
#include <vector>

namespace render::cli {

class CheckTally {
 public:
  // a scene file begun (counted even when it cannot be read)
  void addScene() { ++scenes_; }
  // one variant ("" for the base scene) and what failed in it (nothing when it passed)
  void add(const std::string& file, const std::string& variant, std::vector<std::string> failures);
  // a failure of the last variant added (the scene's `--render` plan)
  void failLast(const std::string& failure);
  // a file that stopped before its variants were all run (bad input): a failed testcase of its own,
  // named "scene", counted as a variant
  void failScene(const std::string& file, const std::string& failure);

  // whether a variant of `file` tallied so far failed
  bool failed(const std::string& file) const;

  // "N scenes, M variants: P passed, F failed"
  std::string summary() const;
  // the JUnit XML, a testcase per variant named by its file and variant; throws std::runtime_error
  void writeJunit(const std::string& path) const;

 private:
  struct Variant {
    std::string file, variant;
    std::vector<std::string> failures;
  };
  size_t scenes_ = 0;
  std::vector<Variant> variants_;
};

}  // namespace render::cli
