// SPDX-License-Identifier: GPL-3.0-or-later
// A ring of f-buckets with O(1) push, move and pop, for searches with bounded edge costs.
#pragma once

#include <algorithm>
#include <cstdint>
#include <memory>
#include <vector>

namespace robuter::plan {

// Open list for A* with a consistent heuristic whose edges cost at most `max_edge`: open nodes'
// f values then lie within 2 * max_edge of the lowest, so a ring of buckets of width `width`
// covers them. Buckets are doubly linked lists through per-node arrays (no allocation after
// reserve()); within a bucket the order is last-in first-out, so the order is exact only to
// `width`: searches using it reopen a closed node whose cost still improves and stop when
// lower() reaches the best goal cost (see GridSearch for the same scheme inlined). A key below
// the current bucket (an inconsistent heuristic can lower f along an edge) is filed in the
// current bucket, and lower() then returns that key: it bounds every queued key from below.
class BucketRing {
 public:
  static constexpr std::uint32_t kNil = 0xFFFFFFFFu;

  // Why: size the per-node links once for `nodes` nodes. The links are left uninitialised
  // (a node's are written when it is linked, before any read), so the memory is only
  // resident for the nodes a search actually pushes.
  void reserve(std::size_t nodes) {
    if (capacity_ < nodes) {
      next_.reset(new std::uint32_t[nodes]);
      prev_.reset(new std::uint32_t[nodes]);
      capacity_ = nodes;
    }
    head_.reserve(1u << 12);
  }

  // Why: start a search: bucket width and the largest edge cost fix the ring size. Returns
  // false if the ring would exceed 4096 buckets (the caller then uses a heap).
  bool reset(double width, double max_edge, double first_f) {
    std::uint32_t ring = 8;
    const double need = 2.0 * max_edge / width + 4.0;
    if (need > 4096.0) return false;
    while (ring < static_cast<std::uint32_t>(need)) ring <<= 1;
    mask_ = ring - 1;
    inv_width_ = 1.0 / width;
    width_ = width;
    head_.assign(ring, kNil);
    cur_ = bucket(first_f);
    below_ = kNone;
    size_ = 0;
    return true;
  }

  bool empty() const { return size_ == 0; }
  // Lowest f the next pop can have: the start of the current bucket, or the lowest key filed
  // below it since the ring reached it.
  double lower() const { return std::min(static_cast<double>(cur_) * width_, below_); }

  // Why: insert a node that is not in the ring.
  void push(std::uint32_t v, double f) {
    link(v, file(f));
    ++size_;
  }
  // Why: a node in the ring got a lower f (old_f must be the f it was pushed with).
  void lower_key(std::uint32_t v, double old_f, double new_f) {
    unlink(v, std::max(bucket(old_f), cur_));
    link(v, file(new_f));
  }
  // Why: take a node from the lowest non-empty bucket (the ring must not be empty).
  std::uint32_t pop() {
    while (head_[slot(cur_)] == kNil) {
      ++cur_;
      below_ = kNone;  // the keys filed below the old bucket left with it
    }
    const std::uint32_t v = head_[slot(cur_)];
    unlink(v, cur_);
    --size_;
    return v;
  }

 private:
  static constexpr double kNone = 1e300;  // below_ when no key was filed below the bucket

  std::uint64_t bucket(double f) const { return static_cast<std::uint64_t>(f * inv_width_); }
  // Why: the bucket a key goes to: its own, or the current one if it lies below (remembered
  // for lower()). A node stays in the current bucket until popped, so unlink() finds it there.
  std::uint64_t file(double f) {
    const std::uint64_t b = bucket(f);
    if (b >= cur_) return b;
    below_ = std::min(below_, f);
    return cur_;
  }
  // Why: a bucket's place in the ring. Below 4096 (reset()), so exact where size_t has 32 bits (armhf);
  // the absolute bucket index itself stays 64-bit.
  std::size_t slot(std::uint64_t b) const { return static_cast<std::size_t>(b & mask_); }
  void link(std::uint32_t v, std::uint64_t b) {
    std::uint32_t& h = head_[slot(b)];
    next_[v] = h;
    prev_[v] = kNil;
    if (h != kNil) prev_[h] = v;
    h = v;
  }
  void unlink(std::uint32_t v, std::uint64_t b) {
    const std::uint32_t p = prev_[v], n = next_[v];
    if (p != kNil) next_[p] = n;
    else head_[slot(b)] = n;
    if (n != kNil) prev_[n] = p;
  }

  std::unique_ptr<std::uint32_t[]> next_;  // per node: next in its bucket, or kNil
  std::unique_ptr<std::uint32_t[]> prev_;  // per node: previous in its bucket, or kNil (head)
  std::size_t capacity_ = 0;               // nodes next_ and prev_ hold
  std::vector<std::uint32_t> head_;  // per bucket: first node, or kNil
  std::uint64_t mask_ = 7;           // ring size - 1
  std::uint64_t cur_ = 0;            // absolute index of the lowest possibly non-empty bucket
  double below_ = kNone;             // f units: lowest key filed below bucket cur_ (kNone: none)
  double width_ = 1.0;               // f units per bucket
  double inv_width_ = 1.0;           // 1 / width_
  std::size_t size_ = 0;             // nodes in the ring
};

}  // namespace robuter::plan
