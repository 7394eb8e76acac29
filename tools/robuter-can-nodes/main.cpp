// SPDX-License-Identifier: GPL-3.0-or-later
// robuter-can-nodes: two simulated CiA 402 wheel drives and six ultrasonic nodes on a bus shared with robuterd.
#include <CLI/CLI.hpp>

#include <time.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "cli/parse_or_usage.hpp"
#include "hal/linux/can/loopback_bus.hpp"
#include "hal/linux/can/sim_nodes.hpp"
#include "hal/linux/can/socketcan_transport.hpp"
#include "hal/linux/can/unix_transport.hpp"
#include "tools/robuter-can-nodes/node_commands.hpp"
#include "tools/robuter-can-nodes/node_report.hpp"

namespace {
volatile std::sig_atomic_t g_stop = 0;  // SIGINT/SIGTERM
void on_stop(int) { g_stop = 1; }  // C++ linkage: kernel/signals.cpp defines a C-linkage on_stop

std::int64_t monotonic_us() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1'000'000 + ts.tv_nsec / 1000;
}
}  // namespace

int main(int argc, char** argv) {
  using namespace robuter::hal::can;
  CLI::App app{"robuter-can-nodes — simulated CiA 402 drives and ultrasonic nodes on a CAN bus shared with robuterd"};
  std::string bus_name;
  unsigned left = 1, right = 2, sonar_base = 16, step_ms = 2;
  double accel = 1e6, seconds = 0.0;
  bool no_sonar = false;
  bool script = false;
  app.add_option("--bus", bus_name, "unix:/path (robuterd's [can] interface = \"unix:/path\") or a SocketCAN interface (vcan0)")
      ->required();
  app.add_option("--left", left, "node id of the left drive (default 1)");
  app.add_option("--right", right, "node id of the right drive (default 2)");
  app.add_option("--sonar-base", sonar_base, "node id of ultrasonic node 0; nodes base..base+5 (default 16)");
  app.add_flag("--no-sonar", no_sonar, "no ultrasonic nodes");
  app.add_option("--accel", accel, "drive acceleration and quick-stop deceleration, increments/s² (default 1e6)");
  app.add_option("--step-ms", step_ms, "the nodes' time step, ms (default 2)")->check(CLI::Range(1u, 100u));
  app.add_flag("--script", script, "read commands from standard input: range, silent, fault, reboot, busoff (docs/CAN.md)");
  app.add_option("--seconds", seconds, "stop after this long (default: until SIGINT/SIGTERM)");
  if (const auto status = robuter::cli::parse_or_usage(app, argc, argv)) return *status;
  if (left < 1 || left > 127 || right < 1 || right > 127 || left == right || sonar_base < 1 || sonar_base > 120) {
    std::fprintf(stderr, "robuter-can-nodes: node ids: drives 1..127 and distinct, sonar base 1..120\n");
    return 2;
  }
  std::string err;
  std::unique_ptr<FrameTransport> wire;
  if (bus_name.rfind("unix:", 0) == 0) wire = UnixTransport::open(bus_name.substr(5), UnixTransport::Role::server, err);
  else wire = SocketCanTransport::open(bus_name, err);
  if (!wire) {
    std::fprintf(stderr, "robuter-can-nodes: %s\n", err.c_str());
    return 2;
  }
  std::signal(SIGINT, on_stop);
  std::signal(SIGTERM, on_stop);
  std::signal(SIGPIPE, SIG_IGN);

  // The nodes share an in-process bus; one endpoint bridges it to the wire.
  LoopbackBus bus;
  LoopbackEndpoint& bridge = bus.attach("bridge");
  SimDriveNode left_drive(bus.attach("left"), static_cast<std::uint8_t>(left), accel);
  SimDriveNode right_drive(bus.attach("right"), static_cast<std::uint8_t>(right), accel);
  std::vector<std::unique_ptr<SimSonarNode>> sonars;
  if (!no_sonar)
    for (unsigned n = 0; n < 6; ++n)
      sonars.push_back(std::make_unique<SimSonarNode>(bus.attach("sonar"), static_cast<std::uint8_t>(sonar_base + n)));
  robuter::tools::NodeReport left_report(left_drive, static_cast<std::uint8_t>(left));
  robuter::tools::NodeReport right_report(right_drive, static_cast<std::uint8_t>(right));
  std::printf("robuter-can-nodes: %s: drives %u and %u", wire->name(), left, right);
  if (no_sonar) std::printf(", no ultrasonic nodes\n");
  else std::printf(", ultrasonic nodes %u..%u\n", sonar_base, sonar_base + 5);
  std::fflush(stdout);

  std::unique_ptr<robuter::tools::NodeCommands> commands;
  if (script) {
    robuter::tools::ScriptedNodes scripted{&left_drive, &right_drive, {}, wire.get()};
    for (auto& s : sonars) scripted.sonars.push_back(s.get());
    commands = std::make_unique<robuter::tools::NodeCommands>(STDIN_FILENO, scripted, stdout);
  }
  const std::int64_t t0 = monotonic_us();
  std::int64_t next = t0;
  std::int64_t last_flush = 0;  // µs, the tool's clock
  while (!g_stop) {
    const std::int64_t now = monotonic_us() - t0;
    if (seconds > 0.0 && static_cast<double>(now) >= seconds * 1e6) break;
    if (commands && !commands->poll(now)) break;
    can_frame f;
    while (wire->receive(f)) bridge.send(f);
    left_drive.step(now);
    right_drive.step(now);
    for (auto& s : sonars) s->step(now);
    while (bridge.receive(f)) wire->send(f);
    // One datagram per robuterd tick at most: its socket queues only net.unix.max_dgram_qlen (10)
    // datagrams, and it reads them once per tick (docs/CAN.md).
    if (now - last_flush >= 10'000) {
      wire->flush();
      last_flush = now;
    }
    left_report.update(now, stdout);
    right_report.update(now, stdout);
    next += static_cast<std::int64_t>(step_ms) * 1000;
    const timespec ts{static_cast<time_t>(next / 1'000'000), static_cast<long>(next % 1'000'000) * 1000};
    clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr);
  }
  std::printf("robuter-can-nodes: stopped\n");
  return 0;
}
