// SPDX-License-Identifier: GPL-3.0-or-later
// Composition of the firmware from options and configuration; everything allocated here, once.
#include "modules/firmware/firmware.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <string_view>
#include <system_error>

#include "hal/linux/can/can_backend.hpp"
#include "hal/linux/can/socketcan_transport.hpp"
#include "hal/linux/can/unix_transport.hpp"
#include "hal/link/pty_link.hpp"
#include "hal/link/stdio_link.hpp"
#include "hal/linux/gpio_lines.hpp"
#include "hal/linux/serial_stream.hpp"
#include "hal/sitl/byte_pipe.hpp"
#include "hal/sitl/odometry_frame.hpp"
#include "hal/sitl/sim_picture.hpp"
#include "hal/sitl/sim_stepper.hpp"
#include "kernel/log.hpp"
#include "kernel/signals.hpp"
#include "modules/firmware/process_table.hpp"
#include "modules/firmware/topic_claims.hpp"
#include "modules/emergency/emergency.hpp"
#include "modules/executor/executor.hpp"
#include "modules/heartbeat/heartbeat.hpp"
#include "modules/notify/notify_module.hpp"
#include "modules/planner/picture_writer.hpp"
#include "modules/planner/planner_module.hpp"
#include "modules/planner/prior_map.hpp"
#include "modules/places/place_graph_file.hpp"
#include "modules/places/place_grid_memory.hpp"
#include "modules/places/place_grid_writer.hpp"
#include "modules/places/wall_raster.hpp"
#include "modules/localise/localise_module.hpp"
#include "modules/firmware/prior_structure.hpp"
#include "modules/demo/demo_module.hpp"
#include "modules/doors/doors_module.hpp"
#include "modules/gate/gate_module.hpp"
#include "modules/ptu/ptu_module.hpp"
#include "modules/ptu/ptu_settings.hpp"
#include "modules/serial/serial_module.hpp"
#include "modules/us/ultrasonic.hpp"

namespace robuter {

namespace {
// Stops the kernel after a fixed number of ticks (--ticks), for scripts and measurements.
class TickLimit final : public Process {
 public:
  explicit TickLimit(std::uint64_t ticks) : ticks_(ticks) {}
  void run(Kernel& k) override {
    if (k.tick() + 1 >= ticks_) k.request_stop();
  }

 private:
  std::uint64_t ticks_;  // ticks to run, then stop
};
// Raises a signal from the periodic path at a given tick (ROBUTERD_TEST_RAISE): a crash of a
// module, for the tests of the fatal-signal path.
class TestRaise final : public Process {
 public:
  TestRaise(int sig, std::uint64_t tick) : sig_(sig), tick_(tick) {}
  void run(Kernel& k) override {
    if (k.tick() >= tick_) std::raise(sig_);
  }

 private:
  int sig_;             // the signal
  std::uint64_t tick_;  // when, ticks
};

// The simulated drive's emergency stop from the fatal-signal handler: plain stores only.
void stop_sim_drive(void* drive) { static_cast<hal::Drive*>(drive)->set_servo(false); }

// The line settings of a serial port from its (validated) configuration words.
hal::SerialSettings line_settings(const hal::SerialPortConfig& c) {
  hal::SerialSettings s;
  s.baud = c.baud;
  s.parity = from_word<hal::Parity>(c.parity).value_or(s.parity);
  s.flow = from_word<hal::FlowControl>(c.flow_control).value_or(s.flow);
  s.stop_bits = c.stop_bits;
  s.retry_ms = c.retry_ms;
  return s;
}

// Bumpers on hardware when [hardware.gpio] names no bumper lines (docs/HARDWARE.md): never pressed.
class NoBumpers final : public hal::Bumpers {
 public:
  std::uint32_t pressed() const override { return 0; }
};

// A ring when [hardware] sonar = "none": every firing refused, so the ultrasonic watch has no
// data and the emergency gate holds every motion (ultrasonic detection must be masked off to move).
class NoSonarRing final : public hal::SonarRing {
 public:
  void configure(std::uint32_t, std::uint32_t) override {}
  bool fire(int, std::uint8_t, std::uint32_t = 0) override { return false; }
  bool read(int, hal::NodeRanges&) override { return false; }
};

// Decided: a missing output folder is created (a new run's output folder), and the log says so
// (`log_name` dir did not exist); an existing path that is not a folder is refused. The error
// names the folder as the operator gave it (`name` dir: …); none when the folder is there.
std::optional<std::string> output_folder(const std::string& dir, const std::string& name, std::string_view log_name) {
  std::error_code ec;
  if (std::filesystem::exists(dir, ec) && !std::filesystem::is_directory(dir, ec))
    return name + " " + dir + ": exists and is not a folder";
  if (!std::filesystem::exists(dir, ec)) {
    std::filesystem::create_directories(dir, ec);
    if (ec) return name + " " + dir + ": cannot create the folder: " + ec.message();
    log::info("{} {} did not exist: created it", log_name, dir);
  }
  return std::nullopt;
}

// The link's sections and the keys of its neighbours' it checks commands against (the serial
// module is given these, not the whole configuration).
LinkSettings link_settings(const Config& cfg) {
  LinkSettings s;
  s.permissions = cfg.permissions;
  s.stop_when_clients_leave = cfg.links.stop_when_clients_leave;
  s.max_speed_cm_s = cfg.robot.max_speed_cm_s;
  s.model = robot_model(cfg);
  s.planner = cfg.planner;
  s.report_corrected = cfg.localise.report_corrected;
  s.comm_limit_ticks = cfg.emergency.comm_limit_ticks;
  s.initial_us = UltrasonicSettings{0xFFFFFF, cfg.sonar.node_delay_ticks, cfg.sonar.timeout_ms, cfg.emergency.auto_toggle};
  return s;
}
}  // namespace

Firmware::Firmware(const Config& cfg, const FirmwareOptions& opt) : cfg_(cfg), opt_(opt) {}

Firmware::~Firmware() {
  if (sim_) signals::remove_fatal_hooks(static_cast<hal::Drive*>(&sim_->drive()));
}

std::vector<std::string> Firmware::pty_slaves() const {
  std::vector<std::string> out;
  for (const auto& l : links_)
    if (auto* p = dynamic_cast<const hal::PtyLink*>(l.get())) out.push_back(p->slave_name());
  return out;
}

// Without --sim: the CAN backend when configured (SocketCAN, or the tests' transport); a kernel
// without AF_CAN ends the start here with the transport's message.
std::optional<std::string> Firmware::setup_hardware() {
  const bool can_drive = cfg_.hardware.drive == "can";
  const bool can_sonar = cfg_.hardware.sonar == "can";
  if (!can_drive)
    return std::string("no hardware backend configured ([hardware] drive = \"none\"): run with --sim, or set "
                       "[hardware] drive = \"can\" (docs/CAN.md)");
  if (!opt_.ptu_pty.empty()) return std::string("--ptu-pty serves the simulated pan-tilt unit: it needs --sim");
  if (!opt_.picture.empty()) return std::string("--picture draws the simulated world: it needs --sim");
  hal::can::FrameTransport* bus = opt_.can_transport;
  if (bus == nullptr) {
    std::string err;
    const std::string& ifname = cfg_.can.interface;
    if (ifname.rfind("unix:", 0) == 0)  // a bus between processes: robuter-can-nodes (docs/CAN.md)
      can_bus_ = hal::can::UnixTransport::open(ifname.substr(5), hal::can::UnixTransport::Role::client, err);
    else
      can_bus_ = hal::can::SocketCanTransport::open(ifname, err);
    if (!can_bus_) return err;
    bus = can_bus_.get();
  }
  auto backend = std::make_unique<hal::can::CanBackend>(*bus, cfg_.can, cfg_.robot.wheel_base_mm, can_drive, can_sonar);
  can_ = backend.get();
  processes_.push_back(std::move(backend));
  drive_ = can_->drive();
  if (can_sonar) {
    ring_ = can_->ring();
  } else {
    own_ring_ = std::make_unique<NoSonarRing>();
    ring_ = own_ring_.get();
  }
  own_bumpers_ = std::make_unique<NoBumpers>();
  bumpers_ = own_bumpers_.get();
  return std::nullopt;
}

std::optional<std::string> Firmware::setup() {
  // The a-priori map first: it decides the planner's geometry, which the link's goal check and
  // the planner module are built from (docs/PLANNER.md "The module").
  std::optional<plan::OccupancyMap> prior_map;
  if (!cfg_.planner.map_file.empty()) {
    auto loaded = planner::load_prior_map(cfg_.planner, cfg_.source);
    if (!loaded) return "configuration error: planner.map_file: " + loaded.error().text();
    planner_map_note_ = std::move(loaded->note);
    prior_map = std::move(loaded->map);
  }
  if (!cfg_.places.file.empty()) {
    auto graph = places::load_place_graph(cfg_.places.file);
    if (!graph) return "configuration error: places.file: " + graph.error().describe();
    places_ = std::make_unique<const places::PlaceGraph>(std::move(graph).value());
    routes_ = std::make_unique<const places::RouteTable>(*places_);
    places_note_ = fmt::format("{}: {} places, {} doors", cfg_.places.file, places_->places().size(), places_->doors().size());
  }
  if (opt_.speed == 0.0) clock_ = std::make_unique<VirtualClock>();
  else if (opt_.speed == 1.0) clock_ = std::make_unique<RealClock>();
  else clock_ = std::make_unique<ScaledClock>(opt_.speed);

  if (opt_.sim) {
    sim_ = std::make_unique<hal::SimRobot>(cfg_, opt_.sim_options);
    if (sim_->error()) return *sim_->error();
    drive_ = &sim_->drive();
    signals::add_fatal_hook(stop_sim_drive, drive_, "drive stopped (simulated drive: zero speed, servo off)");
    ring_ = &sim_->ring();
    bumpers_ = &sim_->bumpers();
  } else if (auto err = setup_hardware()) {
    return err;
  }

  for (std::size_t i = 0; i < opt_.ptys.size(); ++i) {
    const std::string& path = opt_.ptys[i];
    const auto same = [&](const std::string& other) {
      return std::filesystem::absolute(other).lexically_normal() == std::filesystem::absolute(path).lexically_normal();
    };
    for (std::size_t j = 0; j < i; ++j)
      if (same(opt_.ptys[j])) return "--pty " + path + ": given twice (one link per path)";
    if (!opt_.ptu_pty.empty() && same(opt_.ptu_pty)) return "--pty " + path + ": also the --ptu-pty path";
    auto pty = std::make_unique<hal::PtyLink>(path, hal::PtyLink::Mode::sessions);
    if (pty->error()) return "--pty " + path + ": " + *pty->error();
    links_.push_back(std::move(pty));
  }
  // The serial command link: [links.serial], --serial and --baud override (docs/HARDWARE.md).
  const auto& ls = cfg_.links.serial;
  const std::string& serial_device = opt_.serial_device.empty() ? ls.device : opt_.serial_device;
  if (!serial_device.empty() && opt_.open_devices) {
    hal::SerialSettings s = line_settings(ls);
    if (opt_.baud != 0) s.baud = opt_.baud;
    if (!hal::valid_baud(s.baud)) return fmt::format("--baud {}: not a supported rate", s.baud);
    auto l = std::make_unique<hal::SerialStream>(serial_device, s, "serial " + serial_device);
    if (l->error()) return "serial link: " + *l->error();
    links_.push_back(std::move(l));
  }
  if (opt_.stdio) links_.push_back(std::make_unique<hal::StdioLink>());
  std::vector<hal::ByteStream*> streams;
  for (auto& l : links_) streams.push_back(l.get());

  auto heartbeat = std::make_unique<HeartbeatModule>(bb_);
  auto serial = std::make_unique<SerialModule>(bb_, link_settings(cfg_), streams);
  std::unique_ptr<hal::SimStepper> stepper;
  if (sim_) {
    stepper = std::make_unique<hal::SimStepper>(*sim_);
    if (!opt_.ptu_pty.empty()) {  // the pan-tilt emulator on its own pty
      auto pty = std::make_unique<hal::PtyLink>(opt_.ptu_pty);
      if (pty->error()) return "--ptu-pty: " + *pty->error();
      stepper->attach_ptu(std::move(pty));
    }
    stepper->set_ptu_sweep(opt_.ptu_sweep);
  }
  // The pan-tilt unit's port (after the emulator's pty exists, so its path can be opened).
  const std::string& ptu_port = opt_.ptu_port.empty() ? cfg_.ptu.device : opt_.ptu_port;
  if (!ptu_port.empty() && opt_.open_devices) {
    auto link = std::make_unique<hal::SerialStream>(ptu_port, line_settings(cfg_.ptu), "pan-tilt " + ptu_port);
    if (link->error()) return "pan-tilt port: " + *link->error();
    ptu_link_ = std::move(link);
  } else if (stepper && opt_.sim_ptu && opt_.ptu_pty.empty() && !opt_.ptu_sweep) {
    // Decided (docs/SIMULATOR.md): the simulated robot has its pan-tilt unit by default, wired to
    // the PTU module inside the process — nothing on the filesystem, so simulated runs side by
    // side never collide. A port given, --ptu-pty (the unit is someone else's), --ptu-sweep (the
    // sweep drives it) or --no-ptu leave it unwired.
    auto [host, unit] = hal::make_byte_pipe("pan-tilt (simulated, in-process)", "pan-tilt unit (in-process)");
    ptu_pipe_ = host.get();
    ptu_link_ = std::move(host);
    stepper->attach_ptu(std::move(unit));
  }
  if (!opt_.picture.empty() && !hal::picture_path_ok(opt_.picture))
    return "--picture " + opt_.picture + ": expected a .png, .svg or .pdf file";
  auto us = std::make_unique<UltrasonicModule>(bb_, *ring_, cfg_.sonar);
  // Bumpers on GPIO lines when [hardware.gpio] names a chip; a missing chip stops start-up.
  if (!cfg_.gpio.chip.empty() && opt_.open_devices) {
    gpio_ = std::make_unique<hal::GpioLines>(cfg_.gpio.chip, cfg_.gpio.bumper_lines, cfg_.gpio.input_lines,
                                             cfg_.gpio.active_low, cfg_.gpio.debounce_us);
    if (gpio_->error()) return fmt::format("{}:{}: {}", cfg_.source, cfg_.gpio.line, *gpio_->error());
  }
  hal::Bumpers& bumpers = gpio_ && !cfg_.gpio.bumper_lines.empty() ? static_cast<hal::Bumpers&>(*gpio_) : *bumpers_;
  auto emergency = std::make_unique<EmergencyModule>(bb_, bumpers, cfg_.emergency, cfg_.robot);
  if (prior_map) {
    // The map's walls explain the ring's echoes where they meet them (docs/SAFETY.md §13, "Narrowing").
    known_ = std::make_unique<PriorMapStructure>(*prior_map, bb_.localisation.reader(), bb_.posture.reader());
    emergency->set_known_structure(known_.get());
  } else if (places_) {
    // No a-priori map, a place graph: the walls it implies (its places' edges but the doors) are
    // the known structure, for the safety core's narrowing and the planner's moving window
    // (docs/PLACES.md, "Walls from the place graph").
    walls_ = std::make_unique<const plan::OccupancyMap>(
        places::wall_raster(*places_, static_cast<double>(cfg_.planner.cell_mm) * 1e-3));
    known_ = std::make_unique<PriorMapStructure>(*walls_, bb_.localisation.reader(), bb_.posture.reader());
    emergency->set_known_structure(known_.get());
  }
  auto executor = std::make_unique<ExecutorModule>(bb_, *drive_, cfg_.robot);
  // Localisation on the map the robot is given (docs/LOCALISATION.md, "The module"): the
  // a-priori map as loaded (the planner's copy changes as it sees), else the place graph's walls.
  std::unique_ptr<LocaliseModule> localise;
  if (cfg_.localise.enabled) {
    if (prior_map) localise_map_ = std::make_unique<const plan::OccupancyMap>(*prior_map);
    const plan::OccupancyMap* map = localise_map_ ? localise_map_.get() : walls_.get();
    if (map == nullptr) return "configuration error: localise.enabled: needs a map (planner.map_file or places.file)";
    localise = std::make_unique<LocaliseModule>(bb_, cfg_.localise, robot_model(cfg_));
    localise->set_map(*map);
    if (auto err = keep_map_pose(*localise)) return *err;
  }
  auto planner = std::make_unique<PlannerModule>(bb_, cfg_.planner, robot_model(cfg_),
                                                 planner::PlannerNeighbours{cfg_.ptu.cap_mm, cfg_.places.cross_doors});  // sized at init, only if its row runs
  if (prior_map) planner->set_prior_map(std::move(*prior_map));
  if (walls_) {
    planner->set_structure(walls_.get());
    openings_ = places::door_openings(*places_, *walls_);
    planner->set_openings(openings_);
  }
  if (cfg_.places.load_grids) {
    // The grids an earlier run saved: the planner's memory of the floor, on the walls' cells;
    // not the safety core's (a remembered obstacle explains no echo: docs/PLACES.md).
    if (!walls_) return "configuration error: places.load_grids: not with planner.map_file (the a-priori map is the memory)";
    auto memory = places::load_grid_memory(*places_, cfg_.places.grids_dir, walls_->geometry(),
                                           planner->settings().hit_threshold);
    if (!memory.ok()) return "configuration error: places.load_grids: " + memory.error().text();
    log::info("places: {} saved place grids read from {}: the planner's memory of the floor", memory.value().grids,
              cfg_.places.grids_dir);
    memory_ = std::make_unique<const plan::OccupancyMap>(std::move(memory.value().map));
    planner->set_memory(memory_.get());
  }
  if (places_) planner->set_places(places_.get());
  auto ptu = std::make_unique<PtuModule>(bb_, ptu_link_.get(), *ring_, ptu::ptu_settings(cfg_.ptu));
  // The passage finder and the door crossing read the same echoes: one geometry for both, from
  // the robot model and the two keys that group and bound them (doors.same_echo_mm, gate.max_mm).
  const robot::RobotModel model = robot_model(cfg_);
  const ptu::EchoGeometry echoes = ptu::echo_geometry(model, static_cast<std::int32_t>(cfg_.doors.same_echo_mm),
                                                      static_cast<std::int32_t>(cfg_.gate.max_mm));
  auto gate = std::make_unique<GateModule>(bb_, cfg_.gate, model, echoes);
  auto doors = std::make_unique<DoorsModule>(bb_, cfg_.doors, model, echoes, emergency.get());
  emergency->add_motion_source(MotionSource::gate, bb_.gate_motion.reader());
  emergency->add_motion_source(MotionSource::doors, bb_.doors_motion.reader());
  gate->set_emergency(emergency.get());
  auto demo = std::make_unique<DemoModule>(bb_, cfg_.demo, model);
  emergency->add_motion_source(MotionSource::demo, bb_.demo_motion.reader());
  demo->set_emergency(emergency.get());
  emergency->add_motion_source(MotionSource::planner, bb_.planner_motion.reader());
  emergency->set_modes(cfg_.gate.hand_over, cfg_.demo.enabled);
  emergency->set_door_loans(cfg_.places.cross_doors);
  planner->set_emergency(emergency.get());
  if (!opt_.planner_pictures.empty()) {
    if (auto error = output_folder(opt_.planner_pictures, "--planner-pictures", "planner: --planner-pictures"))
      return error;
    picture_box_ = std::make_unique<planner::PictureMailbox>();
    // Under --sim the odometry frame's place in the world is known (the stepper publishes it each
    // tick): the pictures are drawn in the world frame.
    planner::PictureWriter::FrameSource frame;
    if (sim_ && stepper) {
      odometry_frame_ = std::make_unique<hal::OdometryFrame>();
      stepper->publish_frame(odometry_frame_.get());
      frame = [f = odometry_frame_.get()]() -> std::optional<plan::Pose2> {
        const sim::Pose p = f->read();
        return plan::Pose2{p.x, p.y, p.theta};
      };
    }
    picture_writer_ = std::make_unique<planner::PictureWriter>(opt_.planner_pictures, *picture_box_, frame);
    planner->set_pictures(picture_box_.get());
  }
  if (!cfg_.places.grids_dir.empty() && places_) {
    const std::string& dir = cfg_.places.grids_dir;
    if (auto error = output_folder(dir, "configuration error: places.grids_dir", "places: grids_dir")) return error;
    place_grid_box_ = std::make_unique<places::PlaceGridMailbox>();
    place_grid_box_->reserve(*places_, static_cast<double>(cfg_.planner.cell_mm) * 1e-3);
    place_grid_writer_ = std::make_unique<places::PlaceGridWriter>(dir, *places_, *place_grid_box_);
    planner->set_place_grids(places_.get(), place_grid_box_.get());
  }
  // New data is acted on in the same tick: ranges → emergency verdict → motors.
  us->set_emergency(emergency.get());
  emergency->set_executor(executor.get());
  serial->set_emergency(emergency.get());
  serial->set_executor(executor.get());  // read-your-writes: ASN, AC then BO
  if (localise) serial->set_localise(localise.get());  // AC or XA then XW
  serial->set_places(places_.get(), routes_.get());
  const NamedProcess modules[] = {{"sim", stepper.get()},         {"can", can_},
                                  {"heartbeat", heartbeat.get()},
                                  {"serial", serial.get()},        {"us", us.get()},
                                  {"emergency", emergency.get()},  {"executor", executor.get()},
                                  {"planner", planner.get()},      {"ptu", ptu.get()},
                                  {"gate", gate.get()},            {"doors", doors.get()},
                                  {"demo", demo.get()},            {"localise", localise.get()}};
  std::vector<ProcessRow> table;
  if (auto err = build_table(cfg_, modules, table)) return err;
  // One writer per topic, claimed once by its module (the localisation's only when it is composed).
  const std::string_view unowned[] = {"localisation"};
  if (auto err = topic_claims_error(bb_, localise ? std::span<const std::string_view>{} : unowned)) return err;
  if (stepper) processes_.push_back(std::move(stepper));
  processes_.push_back(std::move(heartbeat));
  processes_.push_back(std::move(serial));
  processes_.push_back(std::move(us));
  processes_.push_back(std::move(emergency));
  processes_.push_back(std::move(executor));
  processes_.push_back(std::move(planner));
  processes_.push_back(std::move(ptu));
  processes_.push_back(std::move(gate));
  processes_.push_back(std::move(doors));
  processes_.push_back(std::move(demo));
  if (localise) processes_.push_back(std::move(localise));
  // Rows of the firmware itself (not in the configurable table), budgets within one tick.
  const std::uint32_t small_budget = std::min<std::uint32_t>(1000, cfg_.kernel.tick_us);
  if (!opt_.notify_socket.empty()) {
    auto notify = std::make_unique<NotifyModule>(opt_.notify_socket, opt_.watchdog_usec);
    if (notify->error()) return *notify->error();
    processes_.push_back(std::move(notify));
    table.push_back(ProcessRow{"notify", processes_.back().get(), 1, 0, 0, small_budget});
  }
  if (opt_.ticks > 0) {
    processes_.push_back(std::make_unique<TickLimit>(opt_.ticks));
    table.push_back(ProcessRow{"ticklimit", processes_.back().get(), 1, 0, 0, small_budget});
  }
  if (opt_.test_raise_signal != 0) {
    processes_.push_back(std::make_unique<TestRaise>(opt_.test_raise_signal, opt_.test_raise_tick));
    table.push_back(ProcessRow{"test-raise", processes_.back().get(), 1, 0, 0, small_budget});
  }
  kernel_ = std::make_unique<Kernel>(*clock_, static_cast<Nanos>(cfg_.kernel.tick_us) * kNanosPerMicro);
  if (auto err = kernel_->set_table(table)) return "process table: " + *err;
  return std::nullopt;
}

// [localise] state_file: the last run's map pose starts the filter; a missing file is a first
// run, a broken one is said and ignored (the robot starts from its odometry: a file robuterd
// writes itself must not keep it from starting); its folder must exist.
std::optional<std::string> Firmware::keep_map_pose(LocaliseModule& localise) {
  const std::string& path = cfg_.localise.state_file;
  if (path.empty()) return std::nullopt;
  std::error_code ec;
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  if (!folder.empty() && !std::filesystem::is_directory(folder, ec))
    return "configuration error: localise.state_file " + path + ": its folder does not exist";
  if (std::filesystem::exists(path, ec)) {
    std::string why;
    if (const auto p = localise::read_state_file(path, why)) {
      localise.set_start(*p);
      log::info("localise: {}: the last run's map pose {} {} {}", path, p->x, p->y, p->theta);
    } else {
      log::warn("localise: {} — ignored: starting from the odometry", why);
    }
  } else {
    log::info("localise: {} does not exist yet: starting from the odometry", path);
  }
  state_writer_ = std::make_unique<localise::StateFileWriter>(path);
  localise.set_state_file(state_writer_.get());
  return std::nullopt;
}

int Firmware::run() {
  if (state_writer_) state_writer_->start();
  if (picture_writer_) picture_writer_->start();
  if (place_grid_writer_) place_grid_writer_->start();
  int status = kernel_->run();
  if (state_writer_) state_writer_->stop();  // the module's close() handed over the last pose
  if (place_grid_writer_) {
    place_grid_writer_->stop();
    std::fprintf(stderr, "robuterd: place grids: %u written, %u failed, %u dropped (writer busy) in %s\n",
                 place_grid_writer_->written(), place_grid_writer_->failed(), place_grid_writer_->dropped(),
                 place_grid_writer_->dir().c_str());
  }
  if (picture_writer_) {
    picture_writer_->stop();
    // Every plan is accounted for: written, failed, or dropped (each drop was also logged).
    std::fprintf(stderr, "robuterd: planner pictures: %u written, %u failed, %u dropped (writer busy) in %s\n",
                 picture_writer_->written(), picture_writer_->failed(), picture_writer_->dropped(), picture_writer_->dir().c_str());
  }
  const bool picture = !opt_.picture.empty() && sim_;
  if (picture) {
    const auto& ranges = bb_.ranges.reader().peek();  // what the firmware last read
    const auto& em = bb_.emergency.reader().peek();
    const std::string outcome = em.latched ? "emergency latched (" + std::string(word(em.cause)) + ")" : "no emergency latched";
    if (const auto laid = hal::write_sim_picture(*sim_, ranges.mm, ranges.no_echo, outcome, opt_.picture); !laid) {
      std::fprintf(stderr, "robuterd: picture: %s\n", laid.error().describe().c_str());
      if (status == 0) status = 1;
    }
  }
  if (picture || picture_writer_) hal::release_picture_caches();  // the last text drawn: LeakSanitizer
  return status;
}

}  // namespace robuter
