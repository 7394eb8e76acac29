// SPDX-License-Identifier: GPL-3.0-or-later
// Acceptance (issue #8): a serial device removed and restored under a running robuterd — a pty
// that disappears and comes back stands in for it — and the link resumes without a restart;
// the same for the pan-tilt unit's port. The whole firmware on the simulated robot.
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <string_view>
#include <thread>

#include "hal/link/pty_link.hpp"
#include "hal/sitl/sim_stepper.hpp"
#include "modules/firmware/sim_firmware.hpp"
#include "tests/hal_linux/fake_device.hpp"

namespace robuter {
namespace {

struct TempDir {
  std::string path;
  TempDir() {
    char tmpl[] = "/tmp/robuter-serialfw-XXXXXX";
    path = mkdtemp(tmpl);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
};

// Steps the firmware (virtual clock) until `pred`, sleeping a little between ticks so the
// serial helper thread (wall clock) gets its turn; bounded (~20 s), never a speed claim.
template <typename Pred>
bool step_until(test::SimFirmware& fw, Pred pred) {
  for (int i = 0; i < 4000; ++i) {
    if (pred()) return true;
    fw.step();
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return pred();
}

// Sends `line` from the device's far end and returns the first reply line (empty if none).
std::string ask_serial(test::SimFirmware& fw, test::FakeSerialDevice& dev, const std::string& line) {
  if (!dev.send(line + "\r")) return {};
  std::string got;
  for (int i = 0; i < 200; ++i) {
    fw.step();
    got += dev.receive();
    if (const auto end = got.find('\r'); end != std::string::npos) return got.substr(0, end);
  }
  return {};
}

const LinkStatus& status(test::SimFirmware& fw) { return fw.bb().link_status.reader().peek(); }

Config serial_config(const std::string& device) {
  Config cfg;
  cfg.links.serial.device = device;
  cfg.links.serial.retry_ms = 10;
  return cfg;
}

TEST(SerialFirmware, LinkResumesAfterTheDeviceIsRemovedAndRestored) {
  TempDir dir;
  const std::string path = dir.path + "/robuter-link";
  test::FakeSerialDevice dev(path);
  ASSERT_TRUE(dev.ok());
  test::SimFirmware fw("", serial_config(path));
  ASSERT_TRUE(fw.ok()) << fw.error();
  fw.run_ticks(5);
  EXPECT_EQ(ask_serial(fw, dev, "BO").substr(0, 2), "S ");
  EXPECT_EQ(status(fw).links_open, 2u);  // the harness's pty and the serial device

  // Device gone: master closed, DEV removed. robuterd keeps running and ticking.
  dev.unplug();
  const std::uint64_t t0 = fw.kernel().tick();
  fw.run_ticks(300);
  EXPECT_EQ(fw.kernel().tick(), t0 + 300);
  EXPECT_EQ(status(fw).devices_lost, 1u);
  EXPECT_EQ(status(fw).links_open, 1u);
  EXPECT_EQ(fw.ask("BO")->substr(0, 2), "S ");  // the other link is served meanwhile
  for (int i = 0; i < 20; ++i) {  // it stays gone while looked for
    fw.step();
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  EXPECT_EQ(status(fw).devices_back, 0u);

  // A new pty, DEV pointing at it: the link answers again, no restart.
  ASSERT_TRUE(dev.plug());
  ASSERT_TRUE(step_until(fw, [&] { return status(fw).devices_back == 1; }));
  EXPECT_EQ(ask_serial(fw, dev, "BO").substr(0, 2), "S ");
  EXPECT_EQ(status(fw).links_open, 2u);

  // DEV re-pointed at another pty while the old one never hangs up (a node replaced).
  ASSERT_TRUE(dev.plug(/*keep_old=*/true));
  ASSERT_TRUE(step_until(fw, [&] { return status(fw).devices_back == 2; }));
  EXPECT_EQ(status(fw).devices_lost, 2u);
  EXPECT_EQ(ask_serial(fw, dev, "BO").substr(0, 2), "S ");
  const auto i = fw.kernel().find("serial");
  ASSERT_TRUE(i);
  EXPECT_EQ(fw.kernel().stats(*i).overruns, 0u);
}

// A missing serial device at start-up stops robuterd with a message naming it.
TEST(SerialFirmware, MissingDeviceAtStartUpIsNamed) {
  test::SimFirmware fw("", serial_config("/tmp/robuter-no-such-link"));
  ASSERT_FALSE(fw.ok());
  EXPECT_NE(fw.error().find("/tmp/robuter-no-such-link"), std::string::npos) << fw.error();
}

// [hardware.gpio] naming a chip this machine lacks stops start-up, naming the chip.
TEST(SerialFirmware, MissingGpioChipIsNamed) {
  Config cfg;
  cfg.source = "robot.toml";
  cfg.gpio.chip = "/dev/gpiochip-robuter-test";
  cfg.gpio.bumper_lines = {17, 27};
  cfg.gpio.line = 3;
  test::SimFirmware fw("", cfg);
  ASSERT_FALSE(fw.ok());
  EXPECT_NE(fw.error().find("robot.toml:3"), std::string::npos) << fw.error();
  EXPECT_NE(fw.error().find("/dev/gpiochip-robuter-test"), std::string::npos) << fw.error();
}

// The pan-tilt's state as XD words it.
std::string_view ptu_state(test::SimFirmware& fw) { return word(fw.bb().pan_tilt_status.reader().peek().state); }

// The pan-tilt unit's port (SerialStream too): unplugged, failed; a new unit at the same path
// is found by the operator's next Ap without a restart.
TEST(SerialFirmware, PanTiltPortResumesAfterReplug) {
  Config cfg;
  cfg.ptu.retry_ms = 10;
  test::SimFirmware fw("", cfg, {}, /*with_ptu=*/true);
  ASSERT_TRUE(fw.ok()) << fw.error();
  auto* stepper = fw.module<hal::SimStepper>("sim");
  ASSERT_NE(stepper, nullptr);
  const std::string name = stepper->ptu_port()->stream().name();  // "pty PATH"
  const std::string path = name.substr(4);
  EXPECT_EQ(fw.ask("Ap"), "ack");
  ASSERT_TRUE(fw.run_until([&] { return std::string(ptu_state(fw)) == "scanning"; }, 600));
  fw.unplug_ptu();
  ASSERT_TRUE(fw.run_until([&] { return std::string(ptu_state(fw)) == "failed"; }, 300));

  // A new emulated unit at the same path (the old link's destructor removes the path: re-link).
  auto pty = std::make_unique<hal::PtyLink>(path);
  ASSERT_FALSE(pty->error()) << *pty->error();
  const std::string slave = pty->slave_name();
  stepper->attach_ptu(std::move(pty));
  ::unlink(path.c_str());
  ASSERT_EQ(::symlink(slave.c_str(), path.c_str()), 0);

  // The operator retries Ap until the port is back (the helper thread opens it meanwhile).
  ASSERT_TRUE(step_until(fw, [&] {
    if (std::string(ptu_state(fw)) == "scanning") return true;
    if (fw.kernel().tick() % 50 == 0) (void)fw.ask("Ap");
    return false;
  }));
  const std::uint32_t readings = fw.bb().pan_tilt_scan.reader().peek().readings;
  fw.run_ticks(400);
  EXPECT_GT(fw.bb().pan_tilt_scan.reader().peek().readings, readings);  // sweeping again
}

}  // namespace
}  // namespace robuter
