// SPDX-License-Identifier: GPL-3.0-or-later
// Test rig: a loopback bus with two simulated CiA 402 drives, six sonar nodes and the host's CAN backend, on explicit time.
#pragma once

#include <array>
#include <memory>

#include "hal/linux/can/can_backend.hpp"
#include "hal/linux/can/loopback_bus.hpp"
#include "hal/linux/can/sim_nodes.hpp"

namespace robuter::test {

struct CanRig {
  static constexpr std::int64_t kTickUs = 10'000;  // the kernel's default tick, µs

  explicit CanRig(const Config& c = Config{}, bool sonar = true)
      : cfg(c.can),
        host(bus.attach("host")),
        tap(bus.attach("tap")),
        left_ep(bus.attach("left")),
        right_ep(bus.attach("right")),
        left(left_ep, static_cast<std::uint8_t>(cfg.left_node)),
        right(right_ep, static_cast<std::uint8_t>(cfg.right_node)),
        backend(host, cfg, c.robot.wheel_base_mm, true, sonar) {
    for (int n = 0; n < 6; ++n) {
      sonar_ep[n] = &bus.attach("sonar");
      nodes[n] = std::make_unique<hal::can::SimSonarNode>(*sonar_ep[n], static_cast<std::uint8_t>(cfg.sonar_node_base + n));
    }
    backend.start(now);
  }
  // One tick: the nodes answer what the host sent last tick, then the host's activation.
  void tick() {
    now += kTickUs;
    left.step(now);
    right.step(now);
    for (auto& n : nodes) n->step(now);
    backend.service(now, loop_on_time);
    can_frame f;
    while (tap.receive(f)) last_tapped = f;  // keep the tap's queue short
  }
  void ticks(int n) {
    for (int i = 0; i < n; ++i) tick();
  }
  template <typename Pred>
  bool until(Pred p, int max_ticks) {
    for (int i = 0; i < max_ticks; ++i) {
      if (p()) return true;
      tick();
    }
    return p();
  }
  hal::can::CanDrive& drive() { return *backend.drive(); }
  hal::can::CanSonarRing& ring() { return *backend.ring(); }

  CanConfig cfg;
  hal::can::LoopbackBus bus;
  hal::can::LoopbackEndpoint& host;
  hal::can::LoopbackEndpoint& tap;
  hal::can::LoopbackEndpoint& left_ep;
  hal::can::LoopbackEndpoint& right_ep;
  hal::can::SimDriveNode left;
  hal::can::SimDriveNode right;
  std::array<hal::can::LoopbackEndpoint*, 6> sonar_ep{};
  std::array<std::unique_ptr<hal::can::SimSonarNode>, 6> nodes;
  hal::can::CanBackend backend;
  std::int64_t now = 0;  // µs
  can_frame last_tapped{};
  bool loop_on_time = true;  // what the kernel tells the backend (false: a stalled or late loop)
};

}  // namespace robuter::test
