// Internal header: a hash map from pair keys (pairKey) to small values, for the failsafe's
// per-step bookkeeping (the projector's row of each contact, last step's impulses).
//
// Why not std::unordered_map: a zone's growth asks "has this pair a row?" for every candidate of
// every particle it reaches (hundreds of thousands of lookups a step on rain at N = 10^5), and
// each new row allocated a node: the lookups' cache misses and the allocations took about 5% of
// the step. Here keys and values sit in one flat array, probed linearly from a multiplicative
// hash, and clearing keeps the storage: after the first steps nothing is allocated.
//
// The empty slot is marked by a key no pair has: pairKey's kind bits are 0, 1 or 2, never 3.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace fosssim {

template <class Value>
class PairKeyMap {
 public:
  /// Not a pair key (kind bits 3).
  static constexpr uint64_t kEmpty = ~uint64_t{0};

  /// Forgets every entry; the storage stays for the next step.
  void clear() {
    if (size_ == 0) return;
    for (Slot& s : slots_) s.key = kEmpty;
    size_ = 0;
  }
  int size() const { return size_; }

  /// The value of `key`, or nullptr.
  const Value* find(uint64_t key) const {
    if (slots_.empty()) return nullptr;
    for (std::size_t s = home(key);; s = (s + 1) & mask_) {
      if (slots_[s].key == key) return &slots_[s].value;
      if (slots_[s].key == kEmpty) return nullptr;
    }
  }
  bool contains(uint64_t key) const { return find(key) != nullptr; }

  /// Inserts key -> value if key is absent (it keeps its value otherwise); returns whether it did.
  bool insert(uint64_t key, const Value& value) {
    if (2 * (size_ + 1) > static_cast<int>(slots_.size())) grow();
    for (std::size_t s = home(key);; s = (s + 1) & mask_) {
      if (slots_[s].key == key) return false;
      if (slots_[s].key == kEmpty) {
        slots_[s] = Slot{key, value};
        ++size_;
        return true;
      }
    }
  }

  /// Calls f(key, value) for every entry, in no particular order.
  template <class F>
  void forEach(F&& f) const {
    for (const Slot& s : slots_)
      if (s.key != kEmpty) f(s.key, s.value);
  }

 private:
  struct Slot {
    uint64_t key = kEmpty;
    Value value{};
  };
  // Fibonacci hashing: the key times 2^64 / golden ratio, top bits. Keys of one particle differ
  // in their low bits (the other object) and neighbours' in the high ones; the multiplication
  // spreads both over the table.
  std::size_t home(uint64_t key) const { return static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> shift_); }
  void grow() {
    std::vector<Slot> old = std::move(slots_);
    const std::size_t capacity = old.empty() ? 64 : 2 * old.size();
    slots_.assign(capacity, Slot{});
    mask_ = capacity - 1;
    shift_ = 64;
    for (std::size_t c = capacity; c > 1; c >>= 1) --shift_;
    size_ = 0;
    for (const Slot& s : old)
      if (s.key != kEmpty) insert(s.key, s.value);
  }

  std::vector<Slot> slots_;  ///< capacity (a power of two, at most half full): key and value, kEmpty when free
  std::size_t mask_ = 0;     ///< capacity - 1
  int shift_ = 64;           ///< 64 - log2(capacity): home() keeps the hash's top bits
  int size_ = 0;             ///< entries
};

}  // namespace fosssim
