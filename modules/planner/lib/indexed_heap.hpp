// SPDX-License-Identifier: GPL-3.0-or-later
// A 4-ary min-heap of node indexes with decrease-key, preallocated for a fixed node count.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

namespace robuter::plan {

// Min-heap ordered by (key, tie); knows each node's position so keys can be lowered in place.
// Sized once by reserve(); push/pop/decrease never allocate afterwards. Which nodes are in the
// heap is tracked by the caller (the searches keep an open/closed flag per node).
class IndexedHeap {
 public:
  // One heap slot.
  struct Entry {
    double key;          // priority: f = g + h for A*, g for Dijkstra (cost units)
    float tie;           // secondary priority, smaller first (A*: h, to prefer deep nodes)
    std::uint32_t node;  // node index
  };

  // Why: one allocation for the largest node count this heap will see.
  // Positions are left uninitialised (written when a node enters the heap, before any read),
  // so they are only resident for the nodes a search pushes.
  void reserve(std::size_t nodes) {
    heap_.reserve(nodes);
    if (pos_capacity_ < nodes) {
      pos_.reset(new std::uint32_t[nodes]);
      pos_capacity_ = nodes;
    }
  }
  bool empty() const { return heap_.empty(); }
  std::size_t size() const { return heap_.size(); }
  void clear() { heap_.clear(); }
  const Entry& top() const { return heap_.front(); }

  // Why: insert a node not currently in the heap.
  void push(std::uint32_t node, double key, float tie) {
    heap_.push_back({key, tie, node});
    sift_up(heap_.size() - 1);
  }

  // Why: lower the key of a node already in the heap (A*/Dijkstra relaxations).
  void decrease(std::uint32_t node, double key, float tie) {
    const std::size_t i = pos_[node];
    heap_[i].key = key;
    heap_[i].tie = tie;
    sift_up(i);
  }

  // Why: remove and return the smallest entry.
  Entry pop() {
    const Entry best = heap_.front();
    const Entry last = heap_.back();
    heap_.pop_back();
    if (!heap_.empty()) {
      heap_.front() = last;
      pos_[last.node] = 0;
      sift_down(0);
    }
    return best;
  }

 private:
  static bool less(const Entry& a, const Entry& b) {
    return a.key < b.key || (a.key == b.key && a.tie < b.tie);
  }

  // Why: restore order after a key went down at slot i.
  void sift_up(std::size_t i) {
    const Entry e = heap_[i];
    while (i > 0) {
      const std::size_t parent = (i - 1) >> 2;
      if (!less(e, heap_[parent])) break;
      heap_[i] = heap_[parent];
      pos_[heap_[i].node] = static_cast<std::uint32_t>(i);
      i = parent;
    }
    heap_[i] = e;
    pos_[e.node] = static_cast<std::uint32_t>(i);
  }

  // Why: restore order after slot i received a larger entry.
  void sift_down(std::size_t i) {
    const Entry e = heap_[i];
    const std::size_t n = heap_.size();
    for (;;) {
      const std::size_t first = (i << 2) + 1;
      if (first >= n) break;
      std::size_t best = first;
      const std::size_t end = first + 4 < n ? first + 4 : n;
      for (std::size_t c = first + 1; c < end; ++c)
        if (less(heap_[c], heap_[best])) best = c;
      if (!less(heap_[best], e)) break;
      heap_[i] = heap_[best];
      pos_[heap_[i].node] = static_cast<std::uint32_t>(i);
      i = best;
    }
    heap_[i] = e;
    pos_[e.node] = static_cast<std::uint32_t>(i);
  }

  std::vector<Entry> heap_;          // the 4-ary heap
  std::unique_ptr<std::uint32_t[]> pos_;  // per node: its slot in heap_ while it is in the heap
  std::size_t pos_capacity_ = 0;          // nodes pos_ holds
};

}  // namespace robuter::plan
