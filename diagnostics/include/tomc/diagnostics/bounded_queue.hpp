#pragma once
// A fixed-capacity multi-producer queue with one consumer (D. Vyukov's bounded queue): the web server's
// threads push commands for the axis control panel, the cycle pops them. Neither side ever waits for the
// other: a full queue refuses a push, and a slot a producer is still writing reads as "empty" for the cycle.
// No allocation after construction.

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <type_traits>

namespace tomc::diagnostics {

template <typename T, std::size_t Capacity>
class BoundedQueue {
  static_assert(Capacity >= 2 && (Capacity & (Capacity - 1)) == 0, "capacity must be a power of two");
  static_assert(std::is_trivially_copyable_v<T>, "queued values are copied as plain data");

 public:
  BoundedQueue() noexcept {
    for (std::size_t i = 0; i < Capacity; ++i)
      cells_[i].sequence.store(i, std::memory_order_relaxed);
  }
  BoundedQueue(const BoundedQueue&) = delete;
  BoundedQueue& operator=(const BoundedQueue&) = delete;

  // Any thread. False when the queue is full.
  bool push(const T& value) noexcept {
    std::size_t position = enqueue_.load(std::memory_order_relaxed);
    Cell* cell = nullptr;
    for (;;) {
      cell = &cells_[position & (Capacity - 1)];
      const std::size_t sequence = cell->sequence.load(std::memory_order_acquire);
      const auto difference = static_cast<std::intptr_t>(sequence) - static_cast<std::intptr_t>(position);
      if (difference == 0) {
        if (enqueue_.compare_exchange_weak(position, position + 1, std::memory_order_relaxed)) break;
      } else if (difference < 0) {
        return false;
      } else {
        position = enqueue_.load(std::memory_order_relaxed);
      }
    }
    cell->value = value;
    cell->sequence.store(position + 1, std::memory_order_release);
    return true;
  }

  // The one consumer. False when nothing is ready.
  bool pop(T& out) noexcept {
    const std::size_t position = dequeue_.load(std::memory_order_relaxed);
    Cell& cell = cells_[position & (Capacity - 1)];
    const std::size_t sequence = cell.sequence.load(std::memory_order_acquire);
    if (sequence != position + 1) return false;
    out = cell.value;
    dequeue_.store(position + 1, std::memory_order_relaxed);
    cell.sequence.store(position + Capacity, std::memory_order_release);
    return true;
  }

 private:
  struct Cell {
    std::atomic<std::size_t> sequence{0};
    T value{};
  };
  std::array<Cell, Capacity> cells_{};
  alignas(64) std::atomic<std::size_t> enqueue_{0};
  alignas(64) std::atomic<std::size_t> dequeue_{0};
};

}  // namespace tomc::diagnostics
