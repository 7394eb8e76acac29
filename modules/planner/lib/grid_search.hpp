// One-shot 2D searches on a PassGrid: optimal A* (octile) and the thesis' breadth-first search.
#pragma once

#include <cstdint>
#include <vector>

#include "modules/planner/lib/geometry.hpp"
#include "modules/planner/lib/indexed_heap.hpp"
#include "modules/planner/lib/pass_grid.hpp"
#include "modules/planner/lib/plan_result.hpp"

namespace robuter::plan {

// Which 2D search to run.
enum class SearchMode : std::uint8_t {
  Optimal,  // A*, octile costs, octile heuristic: shortest path (default)
  Bfs,      // the thesis: breadth-first, fewest moves, orthogonal neighbours tried first
};

// 8-connected search without corner cutting (a diagonal move needs both side cells
// traversable). All per-node state lives in arrays sized by reserve(); a generation stamp
// marks which entries belong to the current search, so nothing is cleared between searches
// and a search never allocates once the grid size is known.
class GridSearch {
 public:
  GridSearch() = default;
  GridSearch(int width, int height) { reserve(width, height); }

  // Why: size every buffer for grids up to width x height (the only allocation).
  void reserve(int width, int height);

  // Why: the one entry point; the path (start..goal cells) is then in path().
  PlanResult find(const PassGrid& grid, Cell start, Cell goal, SearchMode mode,
                  const CostModel& costs = {});

  const std::vector<Cell>& path() const { return path_; }

 private:
  // Per stored cell search state.
  struct Node {
    double g;             // cells: best cost from the start so far
    std::uint32_t stamp;  // generation that last wrote this node
    std::uint8_t parent;  // move that reached this node, kNoMove for the start
    std::uint8_t closed;  // 1 once expanded in this generation
  };

  void next_generation();
  PlanResult astar(const PassGrid& grid, std::uint32_t s, std::uint32_t t, const CostModel& c);
  PlanResult bfs(const PassGrid& grid, std::uint32_t s, std::uint32_t t, const CostModel& c);
  void build_path(const PassGrid& grid, const MoveTable& mt, std::uint32_t s, std::uint32_t t,
                  PlanResult& r, const CostModel& c);

  std::vector<Node> nodes_;            // per stored cell
  std::vector<std::uint32_t> queue_;   // BFS FIFO
  IndexedHeap open_;                   // A* open list
  std::vector<Cell> path_;             // last path, start first
  std::uint32_t gen_ = 0;              // current generation stamp
};

}  // namespace robuter::plan
