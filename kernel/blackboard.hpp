// SPDX-License-Identifier: GPL-3.0-or-later
// Blackboard topics: one struct per topic, a single writer enforced by the types and claimed
// once, readers that tell new data by a generation counter (PX4 uORB's updated()/copy() and
// advertised(), with the owner made a compile-time fact instead of a convention).
#pragma once

#include <cstdint>

namespace robuter {

template <typename T, typename Owner>
class Topic;

// The tests' way to a topic's writer: declared here, defined only in tests/support/test_writer.hpp
// (a test target's header), so no firmware code can name it (tests/kernel/compile_fail/).
template <typename TopicType>
struct TestWriterAccess;

// The stored value of a topic and how many times it was published.
template <typename T>
struct TopicData {
  T value{};                    // last published value
  std::uint32_t generation = 0; // publications so far (0: never published)
  bool advertised = false;      // the owner has published or advertised (it runs in this firmware)
  std::uint8_t claims = 0;      // writers asked for (1 when composed right; saturates at 255)
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
  // True once the owner has published or advertised: the module runs in this firmware (uORB's
  // advertised()); a module that is composed but never ran leaves it false.
  bool advertised() const { return data_->advertised; }
  bool valid() const { return data_ != nullptr; }

 private:
  const TopicData<T>* data_ = nullptr;  // the topic read
  std::uint32_t seen_ = 0;              // generation at the last copy()
};

// Writable handle: only a topic's owner can obtain one (Topic::writer() is private to it, and
// yields it once). Move-only: it is held by its owner, never lent as a copy.
template <typename T>
class Writer {
 public:
  Writer() = default;
  Writer(const Writer&) = delete;
  Writer& operator=(const Writer&) = delete;
  Writer(Writer&& o) noexcept : data_(o.data_) { o.data_ = nullptr; }
  Writer& operator=(Writer&& o) noexcept {
    data_ = o.data_;
    o.data_ = nullptr;
    return *this;
  }
  // Replaces the value and bumps the generation.
  void publish(const T& v) {
    data_->value = v;
    ++data_->generation;
    data_->advertised = true;
  }
  // Edits the value in place, then bumps the generation once.
  template <typename F>
  void modify(F&& f) {
    f(data_->value);
    ++data_->generation;
    data_->advertised = true;
  }
  // Says the owner runs without publishing a value (readers' advertised() turns true).
  void advertise() { data_->advertised = true; }
  const T& current() const { return data_->value; }
  // Publications so far: what a reader that reports "taken" echoes back (read-your-writes).
  std::uint32_t generation() const { return data_->generation; }
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
  // How many times the writer was asked for: the firmware's start-up check wants exactly 1
  // (topic_claims(), modules/topics.hpp).
  int claims() const { return data_.claims; }

 private:
  friend Owner;
  template <typename>
  friend struct TestWriterAccess;
  // The writable handle, for the owner only and only once: a second request gets an empty
  // handle (valid() false) and is counted, so the start-up check names the topic.
  Writer<T> writer() {
    if (data_.claims < 255) ++data_.claims;
    return data_.claims == 1 ? Writer<T>(data_) : Writer<T>();
  }
  TopicData<T> data_;  // value, generation, advertised, claims
};

}  // namespace robuter
