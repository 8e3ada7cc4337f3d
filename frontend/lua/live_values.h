// The C++ values behind the recipe's Lua values (curves, meshes, grammars, volumes), owned here rather
// than by their userdata. Lua frees a userdata's block without running its finalizer when the finalizer
// cannot run (at the C-stack limit every call fails, finalizers too), and a value the block owned would
// then never be freed and stay counted against --max-points. So the userdata holds only an id; its
// finalizer releases the id, and a sweep releases every id whose userdata a weak-keyed table no longer
// holds (gone for good: a weak key outlives its object's finalizer until the next collection).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <unordered_map>

namespace selfsim::interp {

struct LiveValue {
  std::shared_ptr<const void> value;
  double points = 0;                   // counted against --max-points while alive
  std::size_t bytes = 0;               // C++ memory counted against --max-memory while alive
  bool held = false;                   // a userdata holds it (and its points are counted): until then no sweep takes it
  std::shared_ptr<const void> growth;  // how the value grew, level by level, when a kernel said (growth.h)
};

class LiveValues {
 public:
  std::uint64_t add(LiveValue v) {
    values_.emplace(next_, std::move(v));
    return next_++;
  }
  LiveValue* find(std::uint64_t id) {
    const auto it = values_.find(id);
    return it == values_.end() ? nullptr : &it->second;
  }
  // Removes the value and gives back what it counted (nothing when it was released already).
  LiveValue take(std::uint64_t id) {
    LiveValue v;
    if (const auto it = values_.find(id); it != values_.end()) {
      v = std::move(it->second);
      values_.erase(it);
    }
    return v;
  }
  template <class Visit>
  void each_held(Visit&& visit) const {
    for (const auto& [id, v] : values_)
      if (v.held) visit(id);
  }

  bool sweep_due = false;  // a finalizer failed: some userdata may be gone without releasing its value

 private:
  std::unordered_map<std::uint64_t, LiveValue> values_;
  std::uint64_t next_ = 1;
};

}  // namespace selfsim::interp
