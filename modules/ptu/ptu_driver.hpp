// SPDX-License-Identifier: GPL-3.0-or-later
// Drives a PTU-46-style pan-tilt unit over its byte stream and fires its two sonars every 5°.
#pragma once

#include <array>
#include <cstdint>

#include "hal/api/byte_stream.hpp"
#include "hal/api/sonar_ring.hpp"
#include "modules/ptu/ptu_replies.hpp"
#include "modules/ptu/scan_filter.hpp"
#include "modules/topics.hpp"

namespace robuter::ptu {

// The sweep, the protocol's patience and the calibration (seed ptu.c / ptu.h defaults).
struct PtuSettings {
  std::int32_t min_position = -1755;      // one end of the sweep, positions (−90.2°)
  std::int32_t max_position = 1655;       // the other end, positions (85.0°)
  std::int32_t speed = 1500;              // pan speed (ps), positions/s: < 3° per 30 ms activation
  std::int32_t acceleration = 6000;       // pan acceleration (PA), positions/s²
  std::uint32_t reply_timeout_ticks = 20; // a command unanswered this long has timed out, ticks
  std::uint32_t max_failures = 3;         // consecutive time-outs or bad replies that fail the unit
  std::uint32_t echo_timeout_ticks = 10;  // a channel-7 result not back this long is dropped, ticks
  std::int32_t end_tolerance = 2;         // a position this close to the end counts as there, positions
  std::uint32_t stale_ticks = 10;         // no firing from a position older than this, ticks
  double fire_tolerance_deg = 1.0;        // fire within this of a multiple of 5°, degrees (seed ±1°)
  std::uint32_t poll_period_ticks = 3;    // a command (PP) at most this often, ticks (seed: every 30 ms)
  RangeCalibration calibration;           // measured → real range
  SpikeFilter filter;                     // spike filter thresholds
};

enum class DriverState : std::uint8_t { off, starting, scanning, failed };
enum class DriverFault : std::uint8_t {
  none,
  no_unit,   // no port configured or it could not be opened
  silent,    // commands time out
  garbage,   // replies that are not the protocol's
  refused,   // the unit refused a command of the start-up or the sweep ("!")
  lost,      // the port went away (device removed, peer closed)
};

// The host side of seed ptu.c as a non-blocking state machine: one command in flight at a time,
// its reply matched in order and timed in ticks; no read ever waits. Each step() does bounded
// work: at most kMaxReads reads, one command written, one firing and one result. Step it every
// tick: positions are polled every poll_period_ticks (the seed's 30 ms), and between polls the
// angle is predicted so that each 5° firing happens at the tick nearest its angle.
class PtuDriver {
 public:
  static constexpr int kMaxReads = 4;              // reads of the port per step
  static constexpr std::uint8_t kBothSonars = 0x3; // channel-7 mask: both transducers

  // `stream` may be null (no unit fitted): start() then fails with no_unit.
  PtuDriver(hal::ByteStream* stream, hal::SonarRing& ring, const PtuSettings& s);

  // Begins (or resumes) scanning: the start-up sequence first if the unit was never set up or
  // failed; a lost or missing port stays failed.
  void start(std::uint64_t tick);
  // Stops polling and firing; the scan is cleared (the seed zeroed pt_values when off).
  void stop();
  // One activation at `tick`, the robot at `pose`; true when the scan changed.
  bool step(std::uint64_t tick, const SectorPose& pose);

  DriverState state() const { return state_; }
  DriverFault fault() const { return fault_; }
  const PanTiltScan& scan() const { return scan_; }
  std::int32_t position() const { return pos_; }          // last reported pan position, positions
  std::uint64_t firings() const { return firings_; }      // channel-7 firings, count
  std::uint64_t lost_echoes() const { return lost_echoes_; }  // firings whose result never came, count
  std::uint64_t timeouts() const { return timeouts_; }    // commands that timed out, count

 private:
  // The command in flight (its reply is the next line).
  enum class Command : std::uint8_t { none, echo_off, terse, immediate, acceleration, speed, first_move, poll, reverse };

  void fail(DriverFault f);
  // Reads what the unit sent and handles every complete line.
  void pump();
  void handle_line(std::string_view line, bool bad);
  // A bad or missing reply: counts it, fails the unit after max_failures in a row.
  void bad_reply(DriverFault f);
  void on_position(std::int32_t p, std::uint64_t measured_tick);
  // Sends the next command when none is in flight.
  void next_command(std::uint64_t tick);
  void send(Command c, const char* text, std::optional<std::int32_t> n, std::uint64_t tick);
  // Writes what is left of the output buffer.
  void flush();
  void fire_if_due(std::uint64_t tick, const SectorPose& pose);
  bool collect_echo(std::uint64_t tick);
  // The pan position predicted at `tick` from the last reports (speed and acceleration limited).
  double predict(std::uint64_t tick) const;
  void store(int sector, std::uint16_t measured_mm, double direction_deg);
  void clear_scan();

  hal::ByteStream* stream_;             // the unit's port (null: none fitted)
  hal::SonarRing& ring_;                // channel 7 fires the two sonars
  PtuSettings s_;
  DriverState state_ = DriverState::off;
  DriverFault fault_ = DriverFault::none;
  bool set_up_ = false;                 // the start-up sequence completed once
  int init_step_ = 0;                   // start-up command to send next (0 = ED … 5 = pp to the first end)
  ReplyAssembler lines_;                // reply bytes into lines
  std::array<char, 32> out_{};          // command being written
  std::size_t out_len_ = 0;             // bytes in out_
  std::size_t out_done_ = 0;            // bytes of out_ already written
  Command pending_ = Command::none;     // command whose reply is awaited
  std::uint64_t sent_tick_ = 0;         // tick it was sent
  std::uint64_t last_send_ = 0;         // tick the last command was sent (paces the polling)
  std::uint32_t failures_ = 0;          // consecutive time-outs / bad replies
  std::int32_t target_ = 0;             // end the unit is moving to, positions
  bool reverse_due_ = false;            // the unit reached its end: send it to the other
  bool have_pos_ = false;               // pos_ is valid
  std::int32_t pos_ = 0;                // last reported position, positions
  std::uint64_t pos_tick_ = 0;          // tick it was measured (the tick after PP was sent)
  double velocity_ = 0.0;               // estimated pan speed at pos_tick_, positions/tick
  double accel_ = 0.0;                  // estimated pan acceleration, positions/tick²
  double avg_velocity_ = 0.0;           // mean speed over the last poll interval, positions/tick
  bool have_velocity_ = false;          // avg_velocity_ is valid
  int last_sector_ = -1;                // sector fired last (never twice in a row)
  bool echo_pending_ = false;           // a firing waits for its result
  int fire_sector_ = 0;                 // sector of that firing (0..35; +36 for the other sonar)
  double fire_angle_ = 0.0;             // pan angle at that firing, degrees
  std::uint64_t fire_tick_ = 0;         // tick of that firing
  SectorPose fire_pose_{};              // robot posture at that firing
  PanTiltScan scan_{};                  // the 72 sectors
  std::uint64_t firings_ = 0;
  std::uint64_t lost_echoes_ = 0;
  std::uint64_t timeouts_ = 0;
};

}  // namespace robuter::ptu
