// A polymorphic object owned by value: copying the owner copies the object (its clone()), so that
// a copy of a world has a copy of its collision method's state (2D and 3D alike).
#pragma once

#include <memory>
#include <utility>

namespace sim::core {

template <class T>
class Cloned {
 public:
  Cloned() = default;
  explicit Cloned(std::unique_ptr<T> object) : object_(std::move(object)) {}
  Cloned(const Cloned& o) : object_(o.object_ ? o.object_->clone() : nullptr) {}
  Cloned& operator=(const Cloned& o) {
    object_ = o.object_ ? o.object_->clone() : nullptr;
    return *this;
  }
  Cloned(Cloned&&) = default;
  Cloned& operator=(Cloned&&) = default;
  explicit operator bool() const { return object_ != nullptr; }
  T& operator*() const { return *object_; }
  T* operator->() const { return object_.get(); }

 private:
  std::unique_ptr<T> object_;
};

}  // namespace sim::core
