#pragma once
// Load memory: the start values of every technology object of a runtime (spec 04 §0.3: a data block's start
// values are what MC_Reset Restart copies into it and what a RES variable's write changes). The runtime keeps
// them apart from the TOs' work memory, so that the cyclic data of an axis stays small (docs/performance.md,
// "Memory per axis").
#include <memory>
#include <vector>

namespace tomc::techobjects {

class StartValueStore {
 public:
  // Takes the start values over; the reference stays valid as long as the store lives (set-up only).
  template <typename Data>
  Data& adopt(std::unique_ptr<Data> values) {
    Data& kept = *values;
    items_.emplace_back(std::move(values));  // shared_ptr<void> keeps the deleter of Data
    return kept;
  }
  std::size_t size() const noexcept { return items_.size(); }

 private:
  std::vector<std::shared_ptr<void>> items_;
};

// The start values of one TO: owned by the TO until the runtime adopts them into its StartValueStore
// (TechnologyObject::attach), then kept there. Access is the same either way.
template <typename Data>
class StartValues {
 public:
  explicit StartValues(const Data& values) : own_(std::make_unique<Data>(values)), values_(own_.get()) {}
  const Data& operator*() const noexcept { return *values_; }
  Data& operator*() noexcept { return *values_; }
  const Data* operator->() const noexcept { return values_; }
  Data* operator->() noexcept { return values_; }
  // Bytes of heap the TO still owns for them (0 once the runtime's store has them).
  std::size_t owned_bytes() const noexcept { return own_ ? sizeof(Data) : 0; }
  void move_to(StartValueStore& store) {
    if (own_) values_ = &store.adopt(std::move(own_));
  }

 private:
  std::unique_ptr<Data> own_;
  Data* values_;
};

}  // namespace tomc::techobjects
