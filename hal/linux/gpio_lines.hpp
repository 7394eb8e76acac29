// SPDX-License-Identifier: GPL-3.0-or-later
// Bumpers and digital inputs on a Linux GPIO chip (character device, v2 uAPI, edge events).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "hal/api/bumpers.hpp"
#include "hal/api/digital_inputs.hpp"
#include "hal/linux/gpio_decode.hpp"

namespace robuter::hal {

// One line request holding the bumper lines (bits 0…) then the generic inputs. Reading
// pressed() or levels() drains pending edge events without blocking and then reads the levels
// (one read and one ioctl); a contact closed and opened again between two reads still reads
// pressed once.
class GpioLines final : public Bumpers, public DigitalInputs {
 public:
  // Opens `chip` and requests the lines; on failure error() names the chip and the reason.
  GpioLines(const std::string& chip, std::vector<std::uint32_t> bumper_lines, std::vector<std::uint32_t> input_lines,
            bool active_low, std::uint32_t debounce_us);
  // Uses an already requested line descriptor (tests: a pipe carrying hand-made events).
  GpioLines(int line_fd, std::vector<std::uint32_t> bumper_lines, std::vector<std::uint32_t> input_lines);
  ~GpioLines() override;
  GpioLines(const GpioLines&) = delete;
  GpioLines& operator=(const GpioLines&) = delete;

  const std::optional<std::string>& error() const { return error_; }
  std::uint32_t pressed() const override;  // Bumpers: bit i = bumper line i
  std::uint32_t levels() const override;   // DigitalInputs: bit i = input line i
  std::size_t count() const override { return input_count_; }
  // Events that named no requested line, or read errors, count (for diagnostics).
  std::uint64_t bad_events() const { return bad_events_; }

 private:
  // Drains the events queued on the line descriptor, then refreshes the levels.
  void poll() const;

  std::vector<std::uint32_t> offsets_;  // bumper lines then input lines, chip offsets
  std::size_t bumper_count_ = 0;        // lines that are bumpers (the first ones)
  std::size_t input_count_ = 0;         // lines that are generic inputs (the rest)
  int line_fd_ = -1;                    // descriptor of the line request
  std::optional<std::string> error_;    // why the chip or lines could not be had
  mutable gpio::EdgeState state_;       // levels and latched pulses
  mutable std::uint64_t bad_events_ = 0;  // unexpected events or read errors, count
};

}  // namespace robuter::hal
