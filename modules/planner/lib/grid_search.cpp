// A* with an octile heuristic and the thesis' breadth-first search, on preallocated arrays.
#include "modules/planner/lib/grid_search.hpp"

#include <algorithm>
#include <limits>

namespace robuter::plan {

void GridSearch::reserve(int width, int height) {
  const auto stored = static_cast<std::size_t>(width + 2) * static_cast<std::size_t>(height + 2);
  if (nodes_.size() < stored) {
    nodes_.assign(stored, Node{0.0, 0, kNoMove, 0});
    gen_ = 0;
  }
  if (queue_.size() < stored) queue_.resize(stored);
  open_.reserve(stored);
  path_.reserve(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) + 1);
}

// Why: a new stamp invalidates every node at once; on wrap-around the stamps are reset.
void GridSearch::next_generation() {
  if (++gen_ == 0) {
    for (Node& n : nodes_) n.stamp = 0;
    gen_ = 1;
  }
}

PlanResult GridSearch::find(const PassGrid& grid, Cell start, Cell goal, SearchMode mode,
                            const CostModel& costs) {
  PlanResult r;
  path_.clear();
  if (!grid.contains(start)) return r.status = PlanStatus::StartOutside, r;
  if (!grid.contains(goal)) return r.status = PlanStatus::GoalOutside, r;
  if (grid.at(start) == kBlocked) return r.status = PlanStatus::StartBlocked, r;
  if (grid.at(goal) == kBlocked) return r.status = PlanStatus::GoalBlocked, r;
  reserve(grid.width, grid.height);
  next_generation();
  const std::uint32_t s = grid.index(start);
  const std::uint32_t t = grid.index(goal);
  return mode == SearchMode::Bfs ? bfs(grid, s, t, costs) : astar(grid, s, t, costs);
}

// Why: the default mode. Octile h is consistent, so a node is final when popped; ties on f go
// to the smaller h (deeper node), which keeps open-field searches close to the straight line.
PlanResult GridSearch::astar(const PassGrid& grid, std::uint32_t s, std::uint32_t t,
                             const CostModel& costs) {
  const MoveTable mt(grid.stride);
  const auto cost = costs.table();
  const std::uint8_t* cls = grid.cls.data();
  Node* nodes = nodes_.data();
  const auto stride = static_cast<std::uint32_t>(grid.stride);
  const int tx = static_cast<int>(t % stride);
  const int ty = static_cast<int>(t / stride);
  PlanResult r;

  open_.clear();
  nodes[s] = Node{0.0, gen_, kNoMove, 0};
  {
    const double h = octile(static_cast<int>(s % stride) - tx, static_cast<int>(s / stride) - ty);
    open_.push(s, h, static_cast<float>(h));
  }
  while (!open_.empty()) {
    const std::uint32_t u = open_.pop().node;
    Node& nu = nodes[u];
    nu.closed = 1;
    ++r.expanded;
    if (u == t) {
      r.status = PlanStatus::Found;
      build_path(grid, mt, s, t, r, costs);
      return r;
    }
    const int ux = static_cast<int>(u % stride);
    const int uy = static_cast<int>(u / stride);
    const double gu = nu.g;
    const std::uint8_t cu = cls[u];
    for (int m = 0; m < 8; ++m) {
      const std::uint32_t v = u + static_cast<std::uint32_t>(mt.step[m]);
      const std::uint8_t cv = cls[v];
      if (cv == kBlocked) continue;
      if (m >= 4 && (cls[u + static_cast<std::uint32_t>(mt.side_a[m])] == kBlocked ||
                     cls[u + static_cast<std::uint32_t>(mt.side_b[m])] == kBlocked))
        continue;
      const double ng = gu + cost[m][cu][cv];
      Node& nv = nodes[v];
      if (nv.stamp != gen_) {
        nv = Node{ng, gen_, static_cast<std::uint8_t>(m), 0};
        const double h = octile(ux + kMoveDx[m] - tx, uy + kMoveDy[m] - ty);
        open_.push(v, ng + h, static_cast<float>(h));
      } else if (!nv.closed && ng < nv.g) {
        nv.g = ng;
        nv.parent = static_cast<std::uint8_t>(m);
        const double h = octile(ux + kMoveDx[m] - tx, uy + kMoveDy[m] - ty);
        open_.decrease(v, ng + h, static_cast<float>(h));
      }
    }
  }
  return r;  // Unreachable
}

// Why: the thesis' algorithm (gera_trajetoria) kept as a mode, with its neighbour order and
// the corner-cutting rule fixed: fewest moves, not shortest length.
PlanResult GridSearch::bfs(const PassGrid& grid, std::uint32_t s, std::uint32_t t,
                           const CostModel& costs) {
  const MoveTable mt(grid.stride);
  const std::uint8_t* cls = grid.cls.data();
  Node* nodes = nodes_.data();
  std::uint32_t* queue = queue_.data();
  PlanResult r;
  std::size_t head = 0;
  std::size_t tail = 0;
  nodes[s] = Node{0.0, gen_, kNoMove, 0};
  queue[tail++] = s;
  while (head < tail) {
    const std::uint32_t u = queue[head++];
    ++r.expanded;
    if (u == t) {
      r.status = PlanStatus::Found;
      build_path(grid, mt, s, t, r, costs);
      return r;
    }
    for (int m = 0; m < 8; ++m) {
      const std::uint32_t v = u + static_cast<std::uint32_t>(mt.step[m]);
      if (cls[v] == kBlocked || nodes[v].stamp == gen_) continue;
      if (m >= 4 && (cls[u + static_cast<std::uint32_t>(mt.side_a[m])] == kBlocked ||
                     cls[u + static_cast<std::uint32_t>(mt.side_b[m])] == kBlocked))
        continue;
      nodes[v] = Node{0.0, gen_, static_cast<std::uint8_t>(m), 0};
      queue[tail++] = v;
    }
  }
  return r;  // Unreachable
}

// Why: walk the parent moves back from the goal, then reverse; cost and length are summed
// from the moves so both modes report them the same way.
void GridSearch::build_path(const PassGrid& grid, const MoveTable& mt, std::uint32_t s,
                            std::uint32_t t, PlanResult& r, const CostModel& costs) {
  const auto cost = costs.table();
  std::uint32_t v = t;
  int orth = 0;
  int diag = 0;
  double c = 0.0;
  path_.clear();
  path_.push_back(grid.cell(v));
  while (v != s) {
    const int m = nodes_[v].parent;
    const std::uint32_t u = v - static_cast<std::uint32_t>(mt.step[m]);
    (m < 4 ? orth : diag) += 1;
    c += cost[m][grid.cls[u]][grid.cls[v]];
    v = u;
    path_.push_back(grid.cell(v));
  }
  std::reverse(path_.begin(), path_.end());
  r.length = static_cast<double>(orth) + kSqrt2 * static_cast<double>(diag);
  r.cost = c;
}

}  // namespace robuter::plan
