#include "sim/yaml/first_document.h"

#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/node/detail/node.h>
#include <yaml-cpp/parser.h>

#include <memory>
#include <sstream>
#include <utility>
#include <vector>

namespace sim::yaml {

namespace {

namespace detail = YAML::detail;

// The nodes of one document from the parser's events, as yaml-cpp's NodeBuilder (src/nodebuilder.cpp)
// makes them: each node made in one memory with its mark, kept on a stack until its collection
// takes it; a map takes its entries two at a time, key then value; an alias is the node its
// anchor named.
class Builder : public YAML::EventHandler {
 public:
  void OnDocumentStart(const YAML::Mark&) override {}
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& at, YAML::anchor_t anchor) override {
    made(at, anchor).set_null();
    done();
  }
  void OnAlias(const YAML::Mark&, YAML::anchor_t anchor) override {
    push(*anchors_.at(anchor - 1));
    done();
  }
  void OnScalar(const YAML::Mark& at, const std::string& tag, YAML::anchor_t anchor, const std::string& value) override {
    detail::node& n = made(at, anchor);
    n.set_scalar(value);
    n.set_tag(tag);
    done();
  }
  void OnSequenceStart(const YAML::Mark& at, const std::string& tag, YAML::anchor_t anchor,
                       YAML::EmitterStyle::value style) override {
    detail::node& n = made(at, anchor);
    n.set_tag(tag);
    n.set_type(YAML::NodeType::Sequence);
    n.set_style(style);
  }
  void OnSequenceEnd() override { done(); }
  void OnMapStart(const YAML::Mark& at, const std::string& tag, YAML::anchor_t anchor, YAML::EmitterStyle::value style) override {
    detail::node& n = made(at, anchor);
    n.set_type(YAML::NodeType::Map);
    n.set_tag(tag);
    n.set_style(style);
    ++mapDepth_;
  }
  void OnMapEnd() override {
    --mapDepth_;
    done();
  }

  // the document's root as a YAML::Node sharing the memory the nodes were made in. A Node is made
  // from a detail::node only by yaml-cpp's own classes; its iterator is one of them, and public.
  YAML::Node root() const {
    if (!root_) return YAML::Node();
    std::vector<detail::node*> one{root_};
    const YAML::iterator at(detail::node_iterator(one.begin()), memory_);
    return YAML::Node(*at);
  }

 private:
  detail::node& made(const YAML::Mark& at, YAML::anchor_t anchor) {
    detail::node& n = memory_->create_node();
    n.set_mark(at);
    // anchors are numbered 1, 2, ... in the order the parser meets them
    if (anchor) anchors_.push_back(&n);
    push(n);
    return n;
  }

  void push(detail::node& n) {
    const bool isKey = !stack_.empty() && stack_.back()->type() == YAML::NodeType::Map && keys_.size() < mapDepth_;
    stack_.push_back(&n);
    if (isKey) keys_.push_back({&n, false});
  }

  // the node on top is whole: its collection takes it, or it is the root
  void done() {
    detail::node& n = *stack_.back();
    stack_.pop_back();
    if (stack_.empty()) {
      root_ = &n;
      return;
    }
    detail::node& collection = *stack_.back();
    if (collection.type() == YAML::NodeType::Sequence) {
      collection.push_back(n, memory_);
    } else if (keys_.back().second) {
      collection.insert(*keys_.back().first, n, memory_);
      keys_.pop_back();
    } else {
      keys_.back().second = true;  // the key is whole; its value comes next
    }
  }

  detail::shared_memory_holder memory_ = std::make_shared<detail::memory_holder>();
  detail::node* root_ = nullptr;
  std::vector<detail::node*> stack_;
  std::vector<detail::node*> anchors_;
  std::vector<std::pair<detail::node*, bool>> keys_;  // the maps' keys still open, and whether each is whole
  size_t mapDepth_ = 0;
};

// the second document's start, thrown as soon as the parser announces it: nothing of it is read
struct SecondStart {
  YAML::Mark at;
};
struct StopAtStart : YAML::EventHandler {
  void OnDocumentStart(const YAML::Mark& at) override { throw SecondStart{at}; }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark&, YAML::anchor_t) override {}
  void OnAlias(const YAML::Mark&, YAML::anchor_t) override {}
  void OnScalar(const YAML::Mark&, const std::string&, YAML::anchor_t, const std::string&) override {}
  void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {}
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {}
  void OnMapEnd() override {}
};

}  // namespace

FirstDocument loadFirstDocument(const std::string& text) {
  std::istringstream in(text);
  YAML::Parser parser(in);
  Builder builder;
  FirstDocument out;
  if (!parser.HandleNextDocument(builder)) return out;
  out.root.reset(builder.root());
  try {
    StopAtStart stop;
    parser.HandleNextDocument(stop);
  } catch (const SecondStart& s) {
    out.second = s.at;
  }
  return out;
}

}  // namespace sim::yaml
