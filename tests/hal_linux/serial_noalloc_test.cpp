// SPDX-License-Identifier: GPL-3.0-or-later
// Proves the serial link allocates nothing on the periodic path: lines exchanged over a serial
// device, the device lost and found again, more lines — all inside the counted region.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <memory>
#include <thread>

#include "modules/firmware/sim_firmware.hpp"
#include "tests/hal_linux/fake_device.hpp"
#include "tests/support/alloc_counter.hpp"

namespace robuter {
namespace {

TEST(SerialNoAlloc, ExchangeLossAndReturnAllocateNothing) {
#if defined(ROBUTER_SANITIZE)
  GTEST_SKIP() << "the sanitizers own malloc; this proof runs in the normal build";
#else
  char tmpl[] = "/tmp/robuter-serialna-XXXXXX";
  const std::string dir = mkdtemp(tmpl);
  const std::string path = dir + "/robuter-link";
  test::FakeSerialDevice dev(path);
  ASSERT_TRUE(dev.ok());
  Config cfg;
  cfg.links.serial.device = path;
  cfg.links.serial.retry_ms = 10;
  test::SimFirmware fw("", cfg);
  ASSERT_TRUE(fw.ok()) << fw.error();
  char buf[4096];
  // Reads what the firmware wrote to the device into a fixed buffer; counts carriage returns.
  auto drain = [&] {
    int lines = 0;
    for (;;) {
      const ssize_t n = ::read(dev.master(), buf, sizeof buf);
      if (n <= 0) break;
      for (ssize_t i = 0; i < n; ++i) lines += buf[i] == '\r';
    }
    return lines;
  };
  // Warm-up: every path once (replies, the loss and return logs).
  for (int i = 0; i < 50; ++i) {
    if (i % 10 == 0) dev.send("BO\r");
    fw.step();
  }
  drain();

  int replies = 0;
  auto counter = std::make_unique<test::AllocCounter>();
  for (int i = 0; i < 2000; ++i) {
    if (i % 10 == 0) {
      dev.send("BO\r");
      dev.send("BU\r");
    }
    fw.step();
    replies += drain();
  }
  const int before = replies;
  const auto lost = fw.bb().link_status.reader().peek().devices_lost;
  dev.unplug();
  fw.run_ticks(50);
  std::uint64_t allocations = counter->count();
  counter.reset();
  const bool plugged = dev.plug();  // the test's own pty (allocates a name): not counted
  counter = std::make_unique<test::AllocCounter>();
  bool back = false;
  for (int i = 0; i < 4000 && !back; ++i) {
    fw.step();
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
    back = fw.bb().link_status.reader().peek().devices_back > 0;
  }
  for (int i = 0; i < 200; ++i) {
    if (i % 10 == 0) dev.send("BO\r");
    fw.step();
    replies += drain();
  }
  allocations += counter->count();
  EXPECT_EQ(allocations, 0u);
  EXPECT_EQ(before, 400);  // every request answered while connected
  EXPECT_TRUE(plugged);
  EXPECT_TRUE(back);
  EXPECT_EQ(fw.bb().link_status.reader().peek().devices_lost, lost + 1);
  EXPECT_GE(replies - before, 18);  // answered again after the return
  std::error_code ec;
  std::filesystem::remove_all(dir, ec);
#endif
}

}  // namespace
}  // namespace robuter
