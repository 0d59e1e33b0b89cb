// A bad scene must throw sim::yaml::SceneError at a given FILE:LINE:COL with a message naming the
// fault: the check the 2D and the 3D readers' tests share.
#pragma once

#include <doctest/doctest.h>

#include <initializer_list>
#include <string>

#include "sim/yaml/scene_error.h"

namespace scene_errors {

// load(text, file, variant) must throw a SceneError at `line`:`column` (1-based; column 0: not
// checked) whose message contains every one of `words`
template <class Load>
void expectSceneError(Load load, const std::string& file, const std::string& text, int line, int column,
                      std::initializer_list<std::string> words, const std::string& variant = "") {
  INFO("scene text:\n", text);
  INFO("variant: '", variant, "'");
  try {
    (void)load(text, file, variant);
    FAIL_CHECK("the scene loaded; expected a SceneError");
  } catch (const sim::yaml::SceneError& e) {
    INFO("what(): ", std::string(e.what()));
    CHECK(e.file == file);
    CHECK(e.line == line);
    if (column > 0) CHECK(e.column == column);
    for (const std::string& w : words) CHECK_MESSAGE(e.message.find(w) != std::string::npos, "message lacks '" << w << "'");
    // what() is FILE:LINE:COL: message
    CHECK(std::string(e.what()) == file + ":" + std::to_string(e.line) + ":" + std::to_string(e.column) + ": " + e.message);
  } catch (const std::exception& e) {
    FAIL_CHECK("expected a SceneError, got another exception: " << e.what());
  }
}

// the name the readers' tests give their inline scene texts
inline const std::string kInlineFile = "inline.yaml";

// the check of one reader's inline scene text, for the readers' tests: `load(text, file, variant)` is
// the 2D or the 3D reader's loadSceneText, and `file` names the text in its messages
template <class Load>
struct InlineSceneErrors {
  Load load;
  std::string file = kInlineFile;

  // loading `text` (with `variant`) must throw as expectSceneError says
  void operator()(const std::string& text, int line, int column, std::initializer_list<std::string> words,
                  const std::string& variant = "") const {
    expectSceneError(load, file, text, line, column, words, variant);
  }
};
// (spelled out: clang 14, the sanitizers' compiler, does not deduce an aggregate's arguments)
template <class Load>
InlineSceneErrors(Load, std::string) -> InlineSceneErrors<Load>;
template <class Load>
InlineSceneErrors(Load) -> InlineSceneErrors<Load>;

}  // namespace scene_errors

// EXPECT_SCENE_ERROR(text, line, column, {words}[, variant]): the test file's expectSceneError (an
// InlineSceneErrors), with the line of the call named in the failures reported from inside it
#define EXPECT_SCENE_ERROR(...)                    \
  do {                                             \
    INFO("EXPECT_SCENE_ERROR at line ", __LINE__); \
    expectSceneError(__VA_ARGS__);                 \
  } while (false)
