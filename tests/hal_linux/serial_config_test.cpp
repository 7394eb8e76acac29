// SPDX-License-Identifier: GPL-3.0-or-later
// [links.serial], the [ptu] line keys and [hardware.gpio]: values, defaults and clear
// file:line errors; the rates the configuration accepts are the ones the HAL can set.
#include <gtest/gtest.h>

#include <string>

#include "hal/linux/serial_settings.hpp"
#include "kernel/config.hpp"

namespace robuter {
namespace {

std::optional<ConfigError> parse(const std::string& text, Config& c) { return parse_config(text, "robot.toml", c); }

std::string error_of(const std::string& text) {
  Config c;
  const auto err = parse(text, c);
  return err ? err->message() : "no error";
}

TEST(SerialConfig, DefaultsAreNoDeviceAnd8N1At9600) {
  Config c;
  EXPECT_EQ(c.links.serial.device, "");
  EXPECT_EQ(c.links.serial.baud, 9600u);
  EXPECT_EQ(c.links.serial.parity, "none");
  EXPECT_EQ(c.links.serial.stop_bits, 1u);
  EXPECT_EQ(c.links.serial.flow_control, "none");
  EXPECT_EQ(c.gpio.chip, "");
  EXPECT_TRUE(c.gpio.active_low);
}

TEST(SerialConfig, ReadsEveryKey) {
  Config c;
  const auto err = parse(R"(
[links.serial]
device = "/dev/robuter-link"
baud = 115200
parity = "even"
stop_bits = 2
flow_control = "hardware"
retry_ms = 250

[ptu]
port = "/dev/robuter-ptu"
baud = 19200
parity = "odd"
flow_control = "software"

[hardware.gpio]
chip = "/dev/gpiochip0"
bumper_lines = [17, 27]
input_lines = [5]
active_low = false
debounce_us = 2000
)", c);
  ASSERT_FALSE(err) << err->message();
  EXPECT_EQ(c.links.serial.device, "/dev/robuter-link");
  EXPECT_EQ(c.links.serial.baud, 115200u);
  EXPECT_EQ(c.links.serial.parity, "even");
  EXPECT_EQ(c.links.serial.stop_bits, 2u);
  EXPECT_EQ(c.links.serial.flow_control, "hardware");
  EXPECT_EQ(c.links.serial.retry_ms, 250u);
  EXPECT_EQ(c.ptu.device, "/dev/robuter-ptu");
  EXPECT_EQ(c.ptu.baud, 19200u);
  EXPECT_EQ(c.ptu.parity, "odd");
  EXPECT_EQ(c.ptu.flow_control, "software");
  EXPECT_EQ(c.gpio.chip, "/dev/gpiochip0");
  EXPECT_EQ(c.gpio.bumper_lines, (std::vector<std::uint32_t>{17, 27}));
  EXPECT_EQ(c.gpio.input_lines, (std::vector<std::uint32_t>{5}));
  EXPECT_FALSE(c.gpio.active_low);
  EXPECT_EQ(c.gpio.debounce_us, 2000u);
  EXPECT_EQ(c.gpio.line, 17);  // the line of `chip`
}

TEST(SerialConfig, BadValuesNameFileLineAndKey) {
  EXPECT_EQ(error_of("[links.serial]\nbaud = 9601\n"),
            "robot.toml:2: key 'links.serial.baud': 9601 is not a serial rate (1200, 2400, 4800, 9600, 19200, 38400, "
            "57600, 115200, 230400, 460800, 921600)");
  EXPECT_EQ(error_of("[links.serial]\nparity = \"mark\"\n"),
            "robot.toml:2: key 'links.serial.parity': 'mark' is not one of: none, even, odd");
  EXPECT_EQ(error_of("[links.serial]\nstop_bits = 3\n"), "robot.toml:2: key 'links.serial.stop_bits': 3 is out of range 1..2");
  EXPECT_EQ(error_of("[links.serial]\nflow_control = \"rts\"\n"),
            "robot.toml:2: key 'links.serial.flow_control': 'rts' is not one of: none, hardware, software");
  EXPECT_EQ(error_of("[links.serial]\ndevcie = \"/dev/x\"\n"), "robot.toml:2: key 'links.serial.devcie': unknown key");
  EXPECT_EQ(error_of("[ptu]\nparity = 1\n"), "robot.toml:2: key 'ptu.parity': expected a string, got an integer");
  EXPECT_EQ(error_of("[ptu]\nbaud = 1201\n").substr(0, 43), "robot.toml:2: key 'ptu.baud': 1201 is not a");
  EXPECT_EQ(error_of("[hardware.gpio]\nchip = \"/dev/gpiochip0\"\nbumper_lines = [17, 17]\n"),
            "robot.toml:3: key 'hardware.gpio.bumper_lines': line 17 is listed twice");
  EXPECT_EQ(error_of("[hardware.gpio]\nchip = \"/dev/gpiochip0\"\nbumper_lines = [17]\ninput_lines = [17]\n"),
            "robot.toml:4: key 'hardware.gpio.input_lines': line 17 is listed twice");
  EXPECT_EQ(error_of("[hardware.gpio]\nbumper_lines = [\"a\"]\n"),
            "robot.toml:2: key 'hardware.gpio.bumper_lines': expected line offsets, integers 0..1023");
  EXPECT_EQ(error_of("[hardware.gpio]\nbumper_lines = [4]\n"),
            "robot.toml:2: key 'hardware.gpio.bumper_lines': lines given but no hardware.gpio.chip");
  EXPECT_EQ(error_of("[hardware.gpio]\nchip = \"/dev/gpiochip0\"\n"),
            "robot.toml:2: key 'hardware.gpio.chip': a chip but no hardware.gpio.bumper_lines or input_lines");
  EXPECT_EQ(error_of("[hardware.gpio]\nchip = \"/dev/gpiochip0\"\nbumper_lines = [1]\npins = [4]\n"),
            "robot.toml:4: key 'hardware.gpio.pins': unknown key");
}

TEST(SerialConfig, RatesAgreeWithTheHal) {
  for (const unsigned rate : {1200u, 2400u, 4800u, 9600u, 19200u, 38400u, 57600u, 115200u, 230400u, 460800u, 921600u}) {
    Config c;
    EXPECT_FALSE(parse("[links.serial]\nbaud = " + std::to_string(rate) + "\n", c)) << rate;
    EXPECT_TRUE(hal::valid_baud(rate)) << rate;
  }
  for (const unsigned rate : {1201u, 500000u, 14400u}) {
    Config c;
    EXPECT_TRUE(parse("[links.serial]\nbaud = " + std::to_string(rate) + "\n", c)) << rate;
    EXPECT_FALSE(hal::valid_baud(rate)) << rate;
  }
}

TEST(SerialConfig, ShippedFileHasTheDefaults) {
  Config c;
  const auto err = load_config(ROBUTER_SOURCE_DIR "/config/robuterd.toml", c);
  ASSERT_FALSE(err) << err->message();
  EXPECT_EQ(c.links.serial.device, "");
  EXPECT_EQ(c.links.serial.retry_ms, 500u);
  EXPECT_EQ(c.ptu.parity, "none");
  EXPECT_EQ(c.gpio.chip, "");
}

}  // namespace
}  // namespace robuter
