// The default ring table: the same positions and directions as docs/SIMULATOR.md's table.
#include "modules/planner/ring_geometry.hpp"

#include <numbers>

namespace robuter::planner {

namespace {
constexpr double kDeg = std::numbers::pi / 180.0;  // rad per degree

// x (m), y (m), direction (degrees → rad) of sensors 1..24.
constexpr RingGeometry kRing = {{
    {0.6950, 0.0000, 0.0 * kDeg},       {0.6950, -0.09954, -12.8 * kDeg}, {0.6950, -0.22175, -28.5 * kDeg},
    {0.6950, -0.27677, -35.6 * kDeg},   {0.6950, -0.3500, -45.0 * kDeg},  {0.61196, -0.3500, -90.0 * kDeg},
    {0.3765, -0.3500, -90.0 * kDeg},    {0.1410, -0.3500, -90.0 * kDeg},  {-0.0945, -0.3500, -90.0 * kDeg},
    {-0.3300, -0.3500, -135.0 * kDeg},  {-0.3300, -0.2333, -150.0 * kDeg}, {-0.3300, -0.1167, -165.0 * kDeg},
    {-0.3300, 0.0000, 180.0 * kDeg},    {-0.3300, 0.1167, 165.0 * kDeg},  {-0.3300, 0.2333, 150.0 * kDeg},
    {-0.3300, 0.3500, 135.0 * kDeg},    {-0.0945, 0.3500, 90.0 * kDeg},   {0.1410, 0.3500, 90.0 * kDeg},
    {0.3765, 0.3500, 90.0 * kDeg},      {0.61196, 0.3500, 90.0 * kDeg},   {0.6950, 0.3500, 45.0 * kDeg},
    {0.6950, 0.27677, 35.6 * kDeg},     {0.6950, 0.22175, 28.5 * kDeg},   {0.6950, 0.09954, 12.8 * kDeg},
}};
}  // namespace

// A constant table: no allocation, usable from any activation.
const RingGeometry& default_ring_geometry() { return kRing; }

}  // namespace robuter::planner
