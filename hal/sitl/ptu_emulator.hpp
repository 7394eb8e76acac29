// SPDX-License-Identifier: GPL-3.0-or-later
// A PTU-46-style pan-tilt unit as a pure byte-level state machine: commands in, replies out, motion as time advances.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

namespace robuter::hal {

// Degrees per pan position (seed 002, ptu.c: angle = position·185/3600, i.e. 0.0514°).
inline constexpr double kPtuDegreesPerPosition = 185.0 / 3600.0;

// What the emulated unit allows and how it starts (power-up state).
struct PtuParams {
  std::int32_t min_position = -1755;     // lowest pan position accepted, positions (seed sweep end)
  std::int32_t max_position = 1655;      // highest pan position accepted, positions (seed sweep end)
  std::int32_t speed = 1500;             // power-up target speed, positions/s (seed SPEED)
  std::int32_t min_speed = 1;            // lowest target speed accepted, positions/s
  std::int32_t max_speed = 5836;         // highest target speed accepted, positions/s (≈300°/s)
  std::int32_t acceleration = 6000;      // power-up acceleration, positions/s² (seed PA6000)
  std::int32_t max_acceleration = 100000;// highest acceleration accepted, positions/s²
  std::int32_t start_position = 0;       // pan position at power-up, positions
  bool echo = true;                      // power-up echo of received characters (EE)
  bool verbose = true;                   // power-up verbose feedback (FV)
};

// The unit: feed() the bytes a host writes, take the reply bytes with read_output(), and
// advance() simulated time to move the pan axis. Nothing allocates after construction.
class PtuEmulator {
 public:
  static constexpr std::size_t kOutputCapacity = 1024;  // reply bytes held for the host
  static constexpr std::size_t kTokenCapacity = 32;     // longest command, characters

  explicit PtuEmulator(const PtuParams& params = {});

  // Bytes from the host: commands delimited by space, CR or LF, executed as each delimiter
  // arrives (immediate mode), their replies queued for read_output().
  void feed(std::span<const std::uint8_t> bytes);
  // Moves the pan axis dt seconds further toward its target.
  void advance(double dt_s);

  // Copies queued reply bytes into `out` without removing them; the count copied.
  std::size_t peek_output(std::span<std::uint8_t> out) const;
  // Removes the first `n` queued reply bytes.
  void consume_output(std::size_t n);
  // peek_output then consume_output: takes up to out.size() reply bytes.
  std::size_t read_output(std::span<std::uint8_t> out);
  std::size_t output_size() const { return out_size_; }
  // Reply bytes lost because the host did not read them (queue full).
  std::uint64_t output_dropped() const { return dropped_; }

  // Direct commands (what pp / ps do, without the protocol): a target clamped to the
  // limits, a speed clamped to the allowed range.
  void command_position(std::int32_t position);
  void command_speed(std::int32_t speed);

  // The position the unit reports (PP): the whole positions stepped so far.
  std::int32_t position() const;
  double exact_position() const { return pos_; }           // positions, continuous
  double velocity() const { return vel_; }                  // positions/s, signed
  double angle_deg() const { return pos_ * kPtuDegreesPerPosition; }  // pan angle, degrees
  std::int32_t target() const { return target_; }           // commanded position, positions
  std::int32_t speed() const { return speed_; }             // target speed, positions/s
  std::int32_t acceleration() const { return accel_; }      // positions/s²
  bool moving() const { return vel_ != 0.0 || pos_ != static_cast<double>(target_); }
  bool echo() const { return echo_; }
  bool verbose() const { return verbose_; }
  const PtuParams& params() const { return params_; }

 private:
  // Runs one complete command token and queues its reply.
  void execute();
  // Pan-axis commands: PP, PS, PA with or without an argument.
  void execute_pan(char code, const char* arg, std::size_t len);
  // "*" (+ " text") + CR LF.
  void reply_ok(const char* text = nullptr);
  // "* <verbose text><n>" in verbose mode, "* <n>" in terse mode.
  void reply_value(const char* verbose_text, std::int64_t n, const char* unit = nullptr);
  // "! <message>" (+ n) + CR LF.
  void reply_error(const char* message, const std::int64_t* n = nullptr, const char* unit = nullptr);
  void put(const char* s);
  void put(char c);
  void put_number(std::int64_t n);

  PtuParams params_;                               // limits and power-up state
  std::array<char, kTokenCapacity> token_{};       // command being received
  std::size_t token_len_ = 0;                      // characters in token_
  bool token_overflow_ = false;                    // the command was longer than token_
  std::array<std::uint8_t, kOutputCapacity> out_{};// reply ring
  std::size_t out_first_ = 0;                      // index of the oldest reply byte
  std::size_t out_size_ = 0;                       // reply bytes queued
  std::uint64_t dropped_ = 0;                      // reply bytes lost to a full ring
  bool echo_ = true;                               // echo received characters
  bool verbose_ = true;                            // verbose (FV) or terse (FT) feedback
  double pos_ = 0.0;                               // pan position, positions
  double vel_ = 0.0;                               // pan velocity, positions/s
  std::int32_t target_ = 0;                        // commanded position, positions
  std::int32_t speed_ = 1500;                      // target speed, positions/s
  std::int32_t accel_ = 6000;                      // acceleration, positions/s²
};

}  // namespace robuter::hal
