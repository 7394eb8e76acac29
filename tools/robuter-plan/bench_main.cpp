// SPDX-License-Identifier: GPL-3.0-or-later
// robuter-plan-bench: our optimal search vs Boost Graph Library astar_search, big grids, replans.
#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/astar_search.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include <time.h>

#include "modules/planner/lib/cost_field.hpp"
#include "modules/planner/lib/cspace.hpp"
#include "modules/planner/lib/grid_search.hpp"
#include "modules/planner/lib/movingai.hpp"
#include "modules/planner/lib/plan_snapshot.hpp"
#include "modules/planner/lib/planner.hpp"

namespace {

using namespace robuter::plan;
using Clock = std::chrono::steady_clock;

// Why: milliseconds between two instants.
double ms(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::directedS, boost::no_property,
                                    boost::property<boost::edge_weight_t, double>>;
using Vertex = boost::graph_traits<Graph>::vertex_descriptor;

// The explicit 8-connected graph of a grid (same octile costs, no corner cutting).
struct ExplicitGraph {
  Graph graph;                      // one vertex per traversable cell
  std::vector<int> vertex_of;       // per PassGrid index: vertex, or -1
  std::vector<int> x, y;            // per vertex: cell coordinates
};

// Why: the peer we measure against, built once per map (not timed).
void build_graph(const PassGrid& g, ExplicitGraph& e) {
  e.vertex_of.assign(g.stored(), -1);
  int n = 0;
  for (int yy = 0; yy < g.height; ++yy)
    for (int xx = 0; xx < g.width; ++xx)
      if (g.at({xx, yy}) != kBlocked) {
        e.vertex_of[g.index({xx, yy})] = n++;
        e.x.push_back(xx);
        e.y.push_back(yy);
      }
  for (int v = 0; v < n; ++v) boost::add_vertex(e.graph);
  const MoveTable mt(g.stride);
  for (int v = 0; v < n; ++v) {
    const std::uint32_t u = g.index({e.x[static_cast<std::size_t>(v)], e.y[static_cast<std::size_t>(v)]});
    for (int m = 0; m < 8; ++m) {
      const std::uint32_t w = u + static_cast<std::uint32_t>(mt.step[m]);
      if (g.cls[w] == kBlocked) continue;
      if (m >= 4 && (g.cls[u + static_cast<std::uint32_t>(mt.side_a[m])] == kBlocked ||
                     g.cls[u + static_cast<std::uint32_t>(mt.side_b[m])] == kBlocked))
        continue;
      boost::add_edge(static_cast<Vertex>(v), static_cast<Vertex>(e.vertex_of[w]), m < 4 ? 1.0 : kSqrt2, e.graph);
    }
  }
}

// Octile distance to the goal, for BGL.
class OctileHeuristic : public boost::astar_heuristic<Graph, double> {
 public:
  OctileHeuristic(const ExplicitGraph& e, Vertex goal) : e_(&e), goal_(goal) {}
  double operator()(Vertex v) const {
    return octile(e_->x[v] - e_->x[goal_], e_->y[v] - e_->y[goal_]);
  }

 private:
  const ExplicitGraph* e_;  // coordinates
  Vertex goal_;             // target vertex
};

struct FoundGoal {};  // thrown by the visitor to stop BGL's search (BGL's documented idiom)

// Stops the search when the goal is examined.
class GoalVisitor : public boost::default_astar_visitor {
 public:
  explicit GoalVisitor(Vertex goal) : goal_(goal) {}
  void examine_vertex(Vertex u, const Graph&) const {
    if (u == goal_) throw FoundGoal{};
  }

 private:
  Vertex goal_;  // target vertex
};

// Why: BGL's answer for one problem (-1 when unreachable).
double bgl_length(const ExplicitGraph& e, std::vector<Vertex>& pred, std::vector<double>& dist,
                  Cell s, Cell t, const PassGrid& g) {
  const int sv = e.vertex_of[g.index(s)], tv = e.vertex_of[g.index(t)];
  if (sv < 0 || tv < 0) return -1.0;
  const auto goal = static_cast<Vertex>(tv);
  try {
    boost::astar_search(e.graph, static_cast<Vertex>(sv), OctileHeuristic(e, goal),
                        boost::predecessor_map(pred.data()).distance_map(dist.data()).visitor(GoalVisitor(goal)));
  } catch (const FoundGoal&) {
    return dist[goal];
  }
  return -1.0;
}

// Why: per map, all scenarios with our engines and BGL, lengths checked against the published.
void bench_movingai(const std::string& dir, const char* name, bool& lengths_ok, bool& faster) {
  const auto map = load_movingai_map(dir + "/" + name + ".map");
  const auto scen = load_movingai_scen(dir + "/" + name + ".map.scen");
  if (!map || !scen) {
    std::printf("%-14s cannot load: %s\n", name, (!map ? map.error() : scen.error()).text().c_str());
    lengths_ok = false;
    return;
  }
  PassGrid g;
  pass_grid_from_map(*map, g);
  GridSearch ours(g.width, g.height);
  // Why: all scenarios with one engine, best of 5 runs; counts lengths equal to the published.
  auto run = [&](GridSearch::Engine engine, int& ok) {
    ours.set_engine(engine);
    double best = 1e300;
    for (int rep = 0; rep < 5; ++rep) {
      ok = 0;
      const auto t0 = Clock::now();
      for (const Scenario& s : *scen) {
        const PlanResult r = ours.find(g, s.start, s.goal, SearchMode::Optimal);
        ok += r.found() && std::fabs(r.length - s.optimal) <= 1e-3 ? 1 : 0;
      }
      best = std::min(best, ms(t0, Clock::now()));
    }
    return best;
  };
  int ok_ours = 0, ok_jps = 0, ok_bkt = 0, ok_bgl = 0;
  const double best_ours = run(GridSearch::Engine::Auto, ok_ours);
  const double best_jps = run(GridSearch::Engine::JumpPoints, ok_jps);
  const double best_bkt = run(GridSearch::Engine::Buckets, ok_bkt);
  ExplicitGraph e;
  build_graph(g, e);
  std::vector<Vertex> pred(boost::num_vertices(e.graph));
  std::vector<double> dist(boost::num_vertices(e.graph));
  double best_bgl = 1e300;
  for (int rep = 0; rep < 2; ++rep) {
    ok_bgl = 0;
    const auto t0 = Clock::now();
    for (const Scenario& s : *scen) {
      const double len = bgl_length(e, pred, dist, s.start, s.goal, g);
      ok_bgl += len >= 0.0 && std::fabs(len - s.optimal) <= 1e-3 ? 1 : 0;
    }
    best_bgl = std::min(best_bgl, ms(t0, Clock::now()));
  }
  const int n = static_cast<int>(scen->size());
  std::printf("%-13s %4dx%-4d %5d %9.2f %9.2f %9.2f %9.2f %7.1fx  %4d/%-4d %4d/%-4d\n", name, g.width,
              g.height, n, best_ours, best_jps, best_bkt, best_bgl, best_bgl / best_ours, ok_ours, n, ok_bgl, n);
  lengths_ok = lengths_ok && ok_ours == n && ok_jps == n && ok_bkt == n;
  faster = faster && best_ours < best_bgl;
}

// Why: the search's own cost on a shared machine: the thread's CPU time, ms (wall time also
// counts the time other processes held the core; both are printed).
double cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) * 1e3 + static_cast<double>(ts.tv_nsec) * 1e-6;
}

// Why: a 1000 x 1000 grid, corner to corner; density of random blocked cells, seeded.
PassGrid big_grid(double density, unsigned seed) {
  PassGrid g(1000, 1000);
  std::mt19937 rng(seed);
  std::bernoulli_distribution blocked(density);
  for (int y = 0; y < 1000; ++y)
    for (int x = 0; x < 1000; ++x) g.set({x, y}, blocked(rng) ? kBlocked : kFree);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 3; ++x) g.set({x, y}, kFree), g.set({999 - x, 999 - y}, kFree);
  return g;
}

// Why: the full-plan target (< 20 ms) on the open grid and the 20 % random grid (5, 10 and
// 30 % shown for the trend). Returns whether the target holds; `lengths_ok` turns false if a
// plan fails.
bool bench_big(bool& lengths_ok) {
  bool target = true;
  GridSearch s(1000, 1000);
  for (double density : {0.0, 0.05, 0.10, 0.20, 0.30}) {
    const PassGrid g = big_grid(density, 2024);
    double best = 1e300, best_cpu = 1e300;
    PlanResult r;
    for (int rep = 0; rep < 7; ++rep) {
      const double c0 = cpu_ms();
      const auto t0 = Clock::now();
      r = s.find(g, {0, 0}, {999, 999}, SearchMode::Optimal);
      best = std::min(best, ms(t0, Clock::now()));
      best_cpu = std::min(best_cpu, cpu_ms() - c0);
    }
    const bool counted = density == 0.0 || density == 0.20;
    std::printf("1000x1000 %3.0f%% blocked: %-6s length %8.2f  expanded %7u  %7.2f ms wall  %7.2f ms CPU  %s\n",
                density * 100, std::string(to_string(r.status)).c_str(), r.length, r.expanded, best, best_cpu,
                counted ? (best_cpu < 20.0 ? "target < 20 ms (CPU): met" : "target < 20 ms (CPU): MISSED") : "");
    if (counted) target = target && best_cpu < 20.0;
    lengths_ok = lengths_ok && r.found();
  }
  return target;
}

// Why: what a replan after a few new obstacle cells costs with the cost field, vs a full plan.
void bench_incremental() {
  const int w = 300, h = 300;  // the thesis' 15 m x 15 m at 5 cm
  PassGrid g = big_grid(0.0, 1);
  g.resize(w, h);
  std::mt19937 rng(5);
  std::bernoulli_distribution blocked(0.15);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) g.set({x, y}, blocked(rng) ? kBlocked : kFree);
  const Cell goal{280, 280};
  Cell start{20, 20};
  g.set(goal, kFree);
  g.set(start, kFree);
  CostField field;
  GridSearch astar(w, h);
  std::vector<Cell> path;
  auto t0 = Clock::now();
  field.compute(g, goal);
  const double full = ms(t0, Clock::now());
  const std::uint32_t full_settled = field.last_settled();
  double repair = 0, extract = 0, replan = 0;
  std::uint64_t settled = 0;
  const int rounds = 200;
  std::vector<ClassChange> changes;
  changes.reserve(16);
  for (int i = 0; i < rounds; ++i) {
    // A few new obstacle cells on the current path near the robot (what a scan finds).
    field.path_from(start, path);
    if (path.size() < 12) break;
    changes.clear();
    for (int k = 0; k < 5; ++k) {
      const Cell c = path[static_cast<std::size_t>(6 + k % 3)];
      const Cell d{c.x + (k - 2), c.y};
      if (!g.contains(d) || g.at(d) == kBlocked || d == goal || d == start) continue;
      changes.push_back({g.index(d), g.at(d)});
      g.set(d, kBlocked);
    }
    t0 = Clock::now();
    field.update(changes);
    repair += ms(t0, Clock::now());
    settled += field.last_settled();
    t0 = Clock::now();
    field.path_from(start, path);
    extract += ms(t0, Clock::now());
    t0 = Clock::now();
    astar.find(g, start, goal, SearchMode::Optimal);
    replan += ms(t0, Clock::now());
    start = path[3];  // the robot moves on
  }
  std::printf("replan 300x300 (15%% blocked), %d scans of 5 new cells near the robot:\n", rounds);
  std::printf("  full cost field %.3f ms (%u nodes); per replan: repair %.3f ms (%.0f nodes) + path %.4f ms;"
              " A* from scratch %.3f ms\n",
              full, full_settled, repair / rounds, static_cast<double>(settled) / rounds, extract / rounds,
              replan / rounds);
}


// Why: the thesis' 15 m x 15 m map at 5 cm with 70 random boxes (0.2-0.6 m), the start and goal
// corners clear: a cluttered room for the facade's replan figures.
OccupancyMap boxes_map(unsigned seed) {
  OccupancyMap map(MapGeometry{300, 300, 0.05, {}});
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> pos(0, 299), side(4, 12);
  for (int y = 0; y < 300; ++y)
    for (int x = 0; x < 300; ++x) map.mark_free({x, y});
  for (int b = 0; b < 70; ++b) {
    const int x0 = pos(rng), y0 = pos(rng), sx = side(rng), sy = side(rng);
    for (int y = y0; y < y0 + sy; ++y)
      for (int x = x0; x < x0 + sx; ++x)
        if (map.contains({x, y}) && std::hypot(x - 20, y - 20) > 30 && std::hypot(x - 280, y - 280) > 30)
          map.mark_occupied({x, y});
  }
  map.clear_changes();
  return map;
}

// Why: "a replan after a few new cells should not cost a full plan", measured on the facade the
// firmware uses: the Robuter's rectangle (16 slices, 25 cm turn clearance, as the firmware's
// default) and the thesis' 0.30 m disc (incremental cost field). A full plan rebuilds every
// C-space layer, the goal's cost field and searches; a replan after k new obstacle cells (a
// square blob across the path 1-1.5 m ahead of the robot, what one scan finds) folds them into
// the layers, repairs the field and searches. Mean of 6 placements per k.
void bench_replan_cells() {
  const OccupancyMap base = boxes_map(11);
  const Pose2 start{1.0, 1.0, 0.0};
  const Point2 goal{14.0, 14.0};
  std::printf("replan after k new obstacle cells vs a full plan (Planner facade, 300x300 cells of 5 cm,"
              " 70 random boxes, corner to corner):\n");
  std::printf("%-24s %10s %10s %9s %9s %9s %9s %9s  %s\n", "footprint", "full ms", "field+srch", "k=1",
              "k=5", "k=20", "k=100", "k=400", "full / replan(k=5)");
  for (int kind = 0; kind < 2; ++kind) {
    PlannerConfig cfg;
    if (kind == 0) {
      cfg.footprint = FootprintKind::Rectangle;
      cfg.turn_clearance = 0.25;
    } else {
      cfg.footprint = FootprintKind::Disc;
      cfg.radius = 0.30;
    }
    Planner p(cfg);
    p.set_map(base);
    double full = 1e300, fresh_goal = 1e300;
    std::vector<Waypoint> path;
    for (int rep = 0; rep < 3; ++rep) {
      auto t0 = Clock::now();
      p.set_map(base);  // buffers already sized: the layers are rebuilt, nothing else
      const PlanResult r = p.plan(start, goal);
      full = std::min(full, ms(t0, Clock::now()));
      if (!r.found()) {
        std::printf("%-24s no path on the bench map\n", kind == 0 ? "rectangle" : "disc");
        break;
      }
      path = p.waypoints();
      // The same map, the goal moved by a cell: the field and the search, no layer built.
      t0 = Clock::now();
      p.plan(start, Point2{goal.x - 0.05 * (rep + 1), goal.y});
      fresh_goal = std::min(fresh_goal, ms(t0, Clock::now()));
    }
    if (path.size() < 40) continue;
    {  // The firmware's copy of a plan for its picture (robuterd --planner-pictures), per plan.
      PlanSnapshot snap;
      snap.reserve(p, 8192);
      const PlanResult last = p.plan(start, goal);
      double copy = 1e300;
      for (int rep = 0; rep < 5; ++rep) {
        const auto t0 = Clock::now();
        snap.capture(p, last, start, goal);
        copy = std::min(copy, ms(t0, Clock::now()));
      }
      std::printf("%-24s picture snapshot of a plan (%d layers, %zu waypoints): %.3f ms\n",
                  kind == 0 ? "rectangle, 16 slices" : "disc 0.30 m, incremental", p.slices(), snap.path_len, copy);
    }
    double per_k[5] = {}, sync_ms[5] = {}, expanded[5] = {};
    const int ks[5] = {1, 5, 20, 100, 400};
    for (int ki = 0; ki < 5; ++ki) {
      const int k = ks[ki];
      const int side = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(k))));
      double total = 0.0;
      const int placements = 6;
      for (int pl = 0; pl < placements; ++pl) {
        p.set_map(base);
        if (!p.plan(start, goal).found()) continue;
        const std::vector<Waypoint> here = p.waypoints();
        const CellPose wc = here[std::min<std::size_t>(here.size() - 1, static_cast<std::size_t>(20 + 2 * pl))].cell;
        const Cell c{wc.x, wc.y};
        int marked = 0;
        for (int dy = 0; dy < side && marked < k; ++dy)
          for (int dx = 0; dx < side && marked < k; ++dx) {
            const Cell d{c.x - side / 2 + dx, c.y - side / 2 + dy};
            if (p.map().contains(d) && p.map().state(d) != CellState::Occupied) {
              p.map().mark_occupied(d);
              ++marked;
            }
          }
        const auto t0 = Clock::now();
        p.sync();
        const auto t1 = Clock::now();
        const PlanResult rr = p.plan(start, goal);
        total += ms(t0, Clock::now());
        sync_ms[ki] += ms(t0, t1) / placements;
        expanded[ki] += static_cast<double>(rr.expanded) / placements;
      }
      per_k[ki] = total / placements;
    }
    std::printf("%-24s %10.2f %10.2f %9.3f %9.3f %9.3f %9.3f %9.3f  %.0fx\n",
                kind == 0 ? "rectangle, 16 slices" : "disc 0.30 m, incremental", full, fresh_goal, per_k[0],
                per_k[1], per_k[2], per_k[3], per_k[4], full / per_k[1]);
    std::printf("%-24s %21s %9.3f %9.3f %9.3f %9.3f %9.3f  (of which layers + field repair, ms)\n", "", "",
                sync_ms[0], sync_ms[1], sync_ms[2], sync_ms[3], sync_ms[4]);
    std::printf("%-24s %21s %9.0f %9.0f %9.0f %9.0f %9.0f  (states expanded by the search)\n", "", "", expanded[0],
                expanded[1], expanded[2], expanded[3], expanded[4]);
  }
  std::printf("(full = every C-space layer rebuilt + cost field + search; field+srch = the same map, a new"
              " goal: no layer built; k = replan after k new cells)\n");
}

// Why: the C-space layers' own costs on the firmware's default map (12 m x 12 m at 5 cm = 240 x
// 240 cells; the Robuter's rectangle, body centre 183 mm ahead of the axle, 16 slices over a
// half turn = 32 body + 32 turn-clearance (25 cm) layers + the inscribed disc = 65 layers):
// set_map (every layer built), and a sync() of 100 changed cells, which runs inside the planner
// module's 20 ms activation. Thread CPU ms: best of 5 for set_map, mean and worst of 20
// placements for a sync (each on a fresh copy of the map).
void bench_cspace_layers() {
  const int n = 240;
  OccupancyMap base(MapGeometry{n, n, 0.05, {}});
  std::mt19937 rng(7);
  {
    std::uniform_int_distribution<int> pos(0, n - 1), side(4, 12);
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) base.mark_free({x, y});
    for (int b = 0; b < 45; ++b) {
      const int x0 = pos(rng), y0 = pos(rng), sx = side(rng), sy = side(rng);
      for (int y = y0; y < y0 + sy; ++y)
        for (int x = x0; x < x0 + sx; ++x)
          if (base.contains({x, y})) base.mark_occupied({x, y});
    }
    base.clear_changes();
  }
  PlannerConfig cfg;
  cfg.footprint = FootprintKind::Rectangle;
  cfg.rectangle = RectangleFootprint{1.025, 0.700, 0.183, 0.0};
  cfg.heading_slices = 16;
  cfg.turn_clearance = 0.25;
  Planner p(cfg);
  p.set_map(base);
  double build = 1e300;
  for (int rep = 0; rep < 5; ++rep) {
    const double c0 = cpu_ms();
    p.set_map(base);
    build = std::min(build, cpu_ms() - c0);
  }
  std::printf("C-space layers, 240x240 cells (45 random boxes), rectangle with 16 slices and 25 cm turn"
              " clearance (%d body layers):\n", p.slices());
  std::printf("  set_map (all layers built): %.2f ms CPU (best of 5)\n", build);
  std::uniform_int_distribution<int> pos(12, n - 13);
  // kind 0: a 10 x 10 blob newly occupied in free space; 1: 100 scattered free cells newly
  // occupied; 2: a 10 x 10 blob of a box freed; 3: 100 scattered isolated obstacle cells freed
  // (each alone under the masks: every blocked cell around it is re-checked to the end).
  const char* names[4] = {"100 cells newly occupied (10x10 blob)", "100 cells newly occupied (scattered)",
                          "100 cells freed (10x10 of a box)", "100 cells freed (scattered, isolated)"};
  for (int kind = 0; kind < 4; ++kind) {
    double sum = 0.0, worst = 0.0;
    const int placements = 20;
    for (int pl = 0; pl < placements; ++pl) {
      p.set_map(base);
      std::vector<Cell> cells;
      if (kind == 0 || kind == 2) {
        Cell c{};
        for (int tries = 0; tries < 100000; ++tries) {
          c = Cell{pos(rng), pos(rng)};
          int occ = 0;
          for (int dy = 0; dy < 10; ++dy)
            for (int dx = 0; dx < 10; ++dx) occ += p.map().state({c.x + dx, c.y + dy}) == CellState::Occupied;
          if (kind == 0 ? occ == 0 : occ == 100) break;
        }
        for (int dy = 0; dy < 10; ++dy)
          for (int dx = 0; dx < 10; ++dx) cells.push_back({c.x + dx, c.y + dy});
      } else {
        while (cells.size() < 100) {
          const Cell c{pos(rng), pos(rng)};
          if (p.map().state(c) == CellState::Free) cells.push_back(c);
        }
      }
      if (kind == 3) {  // the isolated obstacles first, folded in untimed
        for (const Cell c : cells) p.map().mark_occupied(c);
        p.sync();
      }
      for (const Cell c : cells) {
        if (kind < 2) p.map().mark_occupied(c);
        else p.map().mark_free(c);
      }
      const double c0 = cpu_ms();
      p.sync();
      const double t = cpu_ms() - c0;
      sum += t;
      worst = std::max(worst, t);
    }
    std::printf("  sync of %-40s mean %7.3f ms CPU, worst %7.3f ms (%d placements)\n", names[kind],
                sum / placements, worst, placements);
  }
}
}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::string(argv[1]) == "--layers") {  // the C-space layers' figures alone
    bench_cspace_layers();
    return 0;
  }
  const std::string dir = argc > 1 ? argv[1] : ROBUTER_MOVINGAI_DIR;
  bool lengths_ok = true;  // every MovingAI length equals the published one
  bool faster = true;      // faster than BGL on every map
  std::printf("MovingAI, all scenarios, optimal search vs Boost Graph Library astar_search (same costs):\n");
  std::printf("(ours = Auto engine: jump points on these maps; the bucket A* shown for comparison)\n");
  std::printf("%-13s %-9s %5s %9s %9s %9s %9s %8s  %-9s %-9s\n", "map", "size", "scen", "ours ms", "JPS ms",
              "bucket ms", "BGL ms", "BGL/ours", "ours ok", "BGL ok");
  for (const char* name : {"arena", "den101d", "den312d", "lak303d", "Berlin_0_256"})
    bench_movingai(dir, name, lengths_ok, faster);
  std::printf("\n");
  const bool big = bench_big(lengths_ok);
  std::printf("\n");
  bench_incremental();
  std::printf("\n");
  bench_replan_cells();
  std::printf("\n");
  bench_cspace_layers();
  std::printf("\nplanner bench: lengths %s; faster than BGL on every map: %s; 1000x1000 under 20 ms: %s\n",
              lengths_ok ? "all correct" : "WRONG", faster ? "yes" : "NO", big ? "yes" : "NO");
  return lengths_ok ? 0 : 1;  // timing targets are reported, correctness decides the status
}
