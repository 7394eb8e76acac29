// SPDX-License-Identifier: GPL-3.0-or-later
// The drive-side watchdog (issue #14): the host's heartbeat, the drives' consumer heartbeat
// (0x1016) and their quick stop when it is lost (0x6007 = 3), on the loopback bus; the Unix
// datagram transport that carries the bus between processes; the fatal-signal quick stop.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "hal/linux/can/unix_transport.hpp"
#include "kernel/signals.hpp"
#include "tests/can/can_rig.hpp"

namespace robuter::test {
namespace {

using hal::DriveHealth;
using State = hal::can::cia402::State;

void drive_forward(CanRig& r) {
  ASSERT_TRUE(r.until([&] { return r.drive().health() == DriveHealth::ok; }, 60));
  r.drive().set_servo(true);
  r.drive().command_wheels(30, 30);
  ASSERT_TRUE(r.until([&] { return r.left.velocity() > 1000 && r.right.velocity() < -1000; }, 20));
}

TEST(CanWatchdog, BringUpMakesTheDrivesWatchTheHostsHeartbeat) {
  CanRig r;
  ASSERT_TRUE(r.until([&] { return r.drive().health() == DriveHealth::ok; }, 60));
  for (const auto* d : {&r.left, &r.right}) {
    EXPECT_EQ(d->consumer_node(), 127);  // can.host_node
    EXPECT_EQ(d->consumer_ms(), 300);    // can.drive_watchdog_ms
    EXPECT_EQ(d->abort_option(), 3);     // quick stop
  }
  // The host's heartbeat: 0x77F, operational, every host_heartbeat_ms (50 ms = 5 ticks).
  const std::uint64_t before = r.backend.host_heartbeats();
  r.ticks(100);  // 1 s
  EXPECT_EQ(r.backend.host_heartbeats() - before, 20u);
  r.loop_on_time = false;
  r.ticks(100);  // a late loop sends none
  EXPECT_EQ(r.backend.host_heartbeats() - before, 20u);
}

TEST(CanWatchdog, WatchdogOffWritesNoConsumerHeartbeat) {
  Config c;
  c.can.drive_watchdog_ms = 0;
  CanRig r(c);
  ASSERT_TRUE(r.until([&] { return r.drive().health() == DriveHealth::ok; }, 60));
  EXPECT_EQ(r.left.consumer_ms(), 0);
  EXPECT_EQ(r.left.abort_option(), 1);  // untouched default
}

// A late or hung loop sends no heartbeat: the drives quick-stop within their consumer time, say
// so with EMCY 0x8130 (the host's emergency trips on it), and reset it when the heartbeat is back.
TEST(CanWatchdog, LostHostHeartbeatQuickStopsTheDrivesWithinTheirTime) {
  CanRig r;
  drive_forward(r);
  r.loop_on_time = false;
  const std::int64_t last = r.left.last_consumed_us();
  ASSERT_TRUE(r.until([&] { return r.left.state() == State::quick_stop_active; }, 100));
  const std::int64_t reacted = r.now - last;
  EXPECT_GT(reacted, 300'000);
  EXPECT_LE(reacted, 300'000 + CanRig::kTickUs);
  EXPECT_EQ(r.right.state(), State::quick_stop_active);
  EXPECT_EQ(r.left.heartbeat_events(), 1u);
  r.tick();
  EXPECT_EQ(r.left.velocity(), 0.0);  // the rig's drives stop at once (1e9 increments/s²)
  EXPECT_EQ(r.right.velocity(), 0.0);
  EXPECT_EQ(r.drive().health(), DriveHealth::fault);  // EMCY 0x8130 at the host
  EXPECT_EQ(r.drive().left().status().emcy_code, 0x8130);
  r.loop_on_time = true;  // the loop is back: the drives reset the error, the host brings them up
  ASSERT_TRUE(r.until([&] { return r.drive().health() == DriveHealth::ok; }, 100));
  EXPECT_EQ(r.left.heartbeat_events(), 1u);
}

TEST(CanWatchdog, FatalSignalHookSendsQuickStopThroughTheTransport) {
  // The loopback cannot send from a signal handler; a Unix-socket bus can.
  const std::string dir = [] {
    char t[] = "/tmp/robuter-can-XXXXXX";
    return std::string(mkdtemp(t));
  }();
  std::string err;
  auto server = hal::can::UnixTransport::open(dir + "/bus", hal::can::UnixTransport::Role::server, err);
  ASSERT_TRUE(server) << err;
  auto client = hal::can::UnixTransport::open(dir + "/bus", hal::can::UnixTransport::Role::client, err);
  ASSERT_TRUE(client) << err;
  {
    hal::can::CanBackend backend(*client, CanConfig{}, 600, true, false);
    backend.start(0);
    ASSERT_TRUE(signals::add_fatal_hook(hal::can::CanBackend::quick_stop_from_signal, &backend, "test"));
    EXPECT_EQ(signals::run_fatal_hooks_for_test(), 1);
    signals::remove_fatal_hooks(&backend);
  }
  can_frame f{};
  int quick_stops = 0;
  while (server->receive(f))
    if ((f.can_id == 0x201 || f.can_id == 0x202) && f.data[0] == 0x02 && (f.data[2] | f.data[3] | f.data[4] | f.data[5]) == 0)
      ++quick_stops;
  EXPECT_EQ(quick_stops, 2);
  server.reset();
  std::filesystem::remove_all(dir);
}

TEST(UnixTransport, ClientAndServerExchangeFramesAndEitherMayStartFirst) {
  char t[] = "/tmp/robuter-can-XXXXXX";
  const std::string dir = mkdtemp(t);
  std::string err;
  auto client = hal::can::UnixTransport::open(dir + "/bus", hal::can::UnixTransport::Role::client, err);
  ASSERT_TRUE(client) << err;
  const can_frame hello = hal::can::cia402::heartbeat(127, hal::can::cia402::NmtState::operational);
  client->send(hello);
  client->flush();  // no server yet: counted, not fatal
  EXPECT_EQ(client->counters().send_failed, 1u);
  auto server = hal::can::UnixTransport::open(dir + "/bus", hal::can::UnixTransport::Role::server, err);
  ASSERT_TRUE(server) << err;
  server->send(hello);
  server->flush();  // nobody to answer yet
  EXPECT_EQ(server->counters().send_failed, 1u);
  client->send(hello);
  client->send(hello);
  client->flush();  // two frames, one datagram
  can_frame got{};
  ASSERT_TRUE(server->receive(got));
  EXPECT_EQ(got.can_id, 0x77Fu);
  EXPECT_EQ(got.data[0], 0x05);
  ASSERT_TRUE(server->receive(got));
  EXPECT_FALSE(server->receive(got));
  EXPECT_EQ(client->counters().sent, 2u);
  server->send(hal::can::cia402::sync());
  server->flush();
  ASSERT_TRUE(client->receive(got));
  EXPECT_EQ(got.can_id, 0x080u);
  EXPECT_FALSE(client->receive(got));  // non-blocking
  // A restarted client (a new address) is answered from its first frame on.
  auto client2 = hal::can::UnixTransport::open(dir + "/bus", hal::can::UnixTransport::Role::client, err);
  ASSERT_TRUE(client2);
  client2->send(hello);
  client2->flush();
  ASSERT_TRUE(server->receive(got));
  server->send(hal::can::cia402::sync());
  server->flush();
  EXPECT_TRUE(client2->receive(got));
  EXPECT_FALSE(client->receive(got));
  server.reset();
  EXPECT_FALSE(std::filesystem::exists(dir + "/bus"));  // the server removes its socket
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace robuter::test
