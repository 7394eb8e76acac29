// SPDX-License-Identifier: GPL-3.0-or-later
// The whole firmware, composed: clock, HAL backend, links, modules, process table and kernel.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "modules/places/place_graph.hpp"
#include "modules/places/route_table.hpp"
#include "modules/planner/lib/occupancy_map.hpp"
#include "hal/api/byte_stream.hpp"
#include "hal/sitl/sim_robot.hpp"
#include "kernel/clock.hpp"
#include "kernel/config.hpp"
#include "kernel/kernel.hpp"
#include "modules/topics.hpp"

namespace robuter::hal::can {
class FrameTransport;
class CanBackend;
}  // namespace robuter::hal::can

namespace robuter::emergency {
class KnownStructure;
}  // namespace robuter::emergency

namespace robuter {
namespace hal {
class GpioLines;
class PipeEnd;
class OdometryFrame;
}

class HeartbeatModule;
class SerialModule;
namespace planner {
class PictureMailbox;
class PictureWriter;
}  // namespace planner
namespace places {
class PlaceGridMailbox;
class PlaceGridWriter;
}  // namespace places
namespace localise {
class StateFileWriter;
}  // namespace localise
class LocaliseModule;

// How robuterd was asked to run (command line).
struct FirmwareOptions {
  bool sim = false;                   // run on the simulated robot
  hal::SimOptions sim_options;        // world, seed, noise
  double speed = 1.0;                 // simulated seconds per second; 0 = as fast as possible
  std::vector<std::string> ptys;      // pty links to create (symbolic link paths)
  std::string serial_device;          // serial link device, empty = none
  unsigned baud = 0;                  // serial link rate, bit/s (0: [links.serial] baud)
  bool stdio = false;                 // serve a link on standard input/output
  std::uint64_t ticks = 0;            // stop after this many ticks (0 = run until stopped)
  std::string ptu_pty;                // pan-tilt emulator's pty (symbolic link path), empty = none
  std::string ptu_port;               // the pan-tilt unit's port for the PTU module (overrides [ptu] port)
  bool ptu_sweep = false;             // built-in pan-tilt sweep and channel-7 firing (no PTU module)
  bool sim_ptu = true;                // --sim: the simulated pan-tilt unit wired to the PTU module inside the
                                      // process when no port is given (--no-ptu: the robot without one)
  std::string picture;                // .png/.svg written at exit (world, robot, trail, ranges)
  bool open_devices = true;           // open serial devices and GPIO chips (false: --check-config)
  std::string planner_pictures;       // folder for a PNG of every plan (map and path), empty = none
  hal::can::FrameTransport* can_transport = nullptr;  // tests: the CAN backends use this bus instead of SocketCAN
  std::string notify_socket;          // systemd's $NOTIFY_SOCKET (Type=notify), empty = none
  std::uint64_t watchdog_usec = 0;    // systemd's $WATCHDOG_USEC, µs (0: no watchdog pings)
  int test_raise_signal = 0;          // tests (ROBUTERD_TEST_RAISE): raise this signal from the periodic path…
  std::uint64_t test_raise_tick = 0;  // …at this tick
};

class Firmware {
 public:
  Firmware(const Config& cfg, const FirmwareOptions& opt);
  ~Firmware();
  Firmware(const Firmware&) = delete;
  Firmware& operator=(const Firmware&) = delete;

  // Builds backend, links, modules and table; the problem when something cannot start.
  std::optional<std::string> setup();
  // Runs until stopped; the exit status.
  int run();

  Kernel& kernel() { return *kernel_; }
  Blackboard& blackboard() { return bb_; }
  hal::SimRobot* sim() { return sim_.get(); }
  // The PTU module's end of the in-process pipe to the simulated unit (--sim without a port),
  // else null: tests unplug it.
  hal::PipeEnd* ptu_pipe() { return ptu_pipe_; }
  // The CAN backend process when [hardware] uses CAN (not with --sim), else null.
  hal::can::CanBackend* can() { return can_; }
  // The virtual clock when running as fast as possible (tests step it), else null.
  VirtualClock* virtual_clock() { return dynamic_cast<VirtualClock*>(clock_.get()); }
  // Paths of the pty slaves created, in the order of FirmwareOptions::ptys.
  std::vector<std::string> pty_slaves() const;
  // The planner's picture writer (--planner-pictures), or null. run() drives it on its own
  // thread; a harness stepping a virtual clock calls its drain() between ticks.
  planner::PictureWriter* planner_pictures() { return picture_writer_.get(); }
  // The place grid writer ([places] grids_dir), or null; driven like planner_pictures().
  places::PlaceGridWriter* place_grids() { return place_grid_writer_.get(); }
  // The localisation's state file writer ([localise] state_file), or null; driven the same way.
  localise::StateFileWriter* state_file() { return state_writer_.get(); }
  // What setup() made of [planner] map_file (one line for --check-config), empty without one.
  const std::string& planner_map_note() const { return planner_map_note_; }
  const std::string& places_note() const { return places_note_; }

 private:
  // [localise] state_file: the kept map pose read, its writer made (docs/LOCALISATION.md).
  std::optional<std::string> keep_map_pose(LocaliseModule& localise);
  Config cfg_;
  FirmwareOptions opt_;
  std::string planner_map_note_;  // [planner] map_file as loaded, for --check-config
  std::unique_ptr<const places::PlaceGraph> places_;  // [places] file as loaded (XN, XI); null = none
  std::unique_ptr<const places::RouteTable> routes_;  // its routes as via points (XQ)
  std::string places_note_;       // [places] file as loaded, for --check-config
  Blackboard bb_;
  std::unique_ptr<Clock> clock_;
  std::unique_ptr<const plan::OccupancyMap> walls_;  // the place graph's walls, when no a-priori map (planner, narrowing)
  std::unique_ptr<localise::StateFileWriter> state_writer_;  // [localise] state_file, written off the kernel's thread
  std::unique_ptr<const plan::OccupancyMap> localise_map_;  // the a-priori map as loaded, for the localisation
  std::unique_ptr<const plan::OccupancyMap> memory_;  // saved place grids read back ([places] load_grids): the planner's only
  std::vector<plan::Point2> openings_;  // the place graph's door openings, kept free in the planner's map
  std::unique_ptr<emergency::KnownStructure> known_;  // the a-priori map as the safety core's known structure, when loaded
  // The robot's hardware without --sim: [hardware] backends (docs/CAN.md).
  std::optional<std::string> setup_hardware();

  std::unique_ptr<hal::SimRobot> sim_;
  std::unique_ptr<hal::can::FrameTransport> can_bus_;  // the SocketCAN socket, when opened here
  hal::can::CanBackend* can_ = nullptr;                // the CAN process (owned by processes_)
  std::unique_ptr<hal::Bumpers> own_bumpers_;          // stand-in when no bumper backend exists
  std::unique_ptr<hal::SonarRing> own_ring_;           // stand-in when [hardware] sonar = "none"
  hal::Drive* drive_ = nullptr;                        // the executor's drive
  hal::SonarRing* ring_ = nullptr;                     // the ultrasonic ring (and pan-tilt channel)
  hal::Bumpers* bumpers_ = nullptr;                    // the contact bumpers
  std::vector<std::unique_ptr<hal::ByteStream>> links_;
  std::unique_ptr<hal::GpioLines> gpio_;             // bumpers and inputs on GPIO, when configured
  std::unique_ptr<hal::ByteStream> ptu_link_;        // the pan-tilt unit's port, when configured
  hal::PipeEnd* ptu_pipe_ = nullptr;                 // ptu_link_ when it is the in-process pipe
  std::vector<std::unique_ptr<Process>> processes_;  // modules and helpers, owned
  std::unique_ptr<Kernel> kernel_;
  std::unique_ptr<hal::OdometryFrame> odometry_frame_;     // the odometry frame in the world (--sim), for the pictures
  std::unique_ptr<planner::PictureMailbox> picture_box_;   // plans handed from the planner
  std::unique_ptr<planner::PictureWriter> picture_writer_; // draws them outside the kernel
  std::unique_ptr<places::PlaceGridMailbox> place_grid_box_;   // place grids handed from the planner ([places] grids_dir)
  std::unique_ptr<places::PlaceGridWriter> place_grid_writer_; // saves them outside the kernel
};

}  // namespace robuter
