// SPDX-License-Identifier: GPL-3.0-or-later
// Blackboard topics: one struct per topic, a single writer enforced by the types, readers
// that tell new data by a generation counter (PX4 uORB's updated()/copy(), with the owner
// made a compile-time fact instead of a convention).
#pragma once

#include <cstdint>

namespace robuter {

template <typename T, typename Owner>
class Topic;

// The stored value of a topic and how many times it was published.
template <typename T>
struct TopicData {
  T value{};                    // last published value
  std::uint32_t generation = 0; // publications so far (0: never published)
};

// Read-only handle: anyone may hold one.
template <typename T>
class Reader {
 public:
  Reader() = default;
  explicit Reader(const TopicData<T>& d) : data_(&d) {}
  // True when a publication happened since this reader's last copy().
  bool updated() const { return data_->generation != seen_; }
  // Returns the value and marks it seen.
  T copy() {
    seen_ = data_->generation;
    return data_->value;
  }
  // Reads without marking seen (for readers that just want the latest value).
  const T& peek() const { return data_->value; }
  std::uint32_t generation() const { return data_->generation; }
  bool valid() const { return data_ != nullptr; }

 private:
  const TopicData<T>* data_ = nullptr;  // the topic read
  std::uint32_t seen_ = 0;              // generation at the last copy()
};

// Writable handle: only a topic's owner can obtain one (Topic::writer() is private to it).
template <typename T>
class Writer {
 public:
  Writer() = default;
  // Replaces the value and bumps the generation.
  void publish(const T& v) {
    data_->value = v;
    ++data_->generation;
  }
  // Edits the value in place, then bumps the generation once.
  template <typename F>
  void modify(F&& f) {
    f(data_->value);
    ++data_->generation;
  }
  const T& current() const { return data_->value; }
  bool valid() const { return data_ != nullptr; }

 private:
  template <typename, typename>
  friend class Topic;
  explicit Writer(TopicData<T>& d) : data_(&d) {}
  TopicData<T>* data_ = nullptr;  // the topic written
};

// A topic whose only writer is `Owner`: its writer() is private, and only Owner is a friend.
template <typename T, typename Owner>
class Topic {
 public:
  using value_type = T;
  using owner_type = Owner;
  Topic() = default;
  Topic(const Topic&) = delete;
  Topic& operator=(const Topic&) = delete;
  // A read-only handle, for any module.
  Reader<T> reader() const { return Reader<T>(data_); }

 private:
  friend Owner;
  // The writable handle, for the owner only.
  Writer<T> writer() { return Writer<T>(data_); }
  TopicData<T> data_;  // value and generation
};

}  // namespace robuter
