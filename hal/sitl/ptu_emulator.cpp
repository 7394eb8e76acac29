// SPDX-License-Identifier: GPL-3.0-or-later
// The PTU emulator: command tokenizer, replies in the unit's conventions, trapezoidal pan motion.
#include "hal/sitl/ptu_emulator.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string_view>

namespace robuter::hal {

namespace {
// Upper-case ASCII letter, anything else unchanged (the unit ignores case).
char upper(char c) { return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c; }

// Space, CR and LF end a command.
bool is_delimiter(std::uint8_t b) { return b == ' ' || b == '\r' || b == '\n'; }

// Parses an optional sign and 1..18 digits filling exactly [s, s+len); false otherwise.
bool parse_integer(const char* s, std::size_t len, std::int64_t& out) {
  std::size_t i = 0;
  if (len > 0 && s[0] == '+') i = 1;  // from_chars refuses '+'
  if (i >= len || len - i > 19) return false;
  const auto r = std::from_chars(s + i, s + len, out);
  return r.ec == std::errc() && r.ptr == s + len;
}

constexpr double kEps = 1e-9;       // tolerance on positions and speeds, positions(/s)
constexpr double kBrakeEps = 1e-6;  // tolerance of the braking-point test, positions
}  // namespace

// Power-up state comes from the parameters.
PtuEmulator::PtuEmulator(const PtuParams& params)
    : params_(params),
      echo_(params.echo),
      verbose_(params.verbose),
      pos_(params.start_position),
      target_(params.start_position),
      speed_(params.speed),
      accel_(params.acceleration) {}

// Why byte by byte: the host may split a command across writes, and echo is per character.
void PtuEmulator::feed(std::span<const std::uint8_t> bytes) {
  for (const std::uint8_t b : bytes) {
    if (!is_delimiter(b)) {
      if (echo_) put(static_cast<char>(b));
      if (token_len_ < token_.size()) token_[token_len_++] = static_cast<char>(b);
      else token_overflow_ = true;
      continue;
    }
    if (token_len_ == 0 && !token_overflow_) continue;  // CR LF pairs, repeated spaces
    if (echo_) put(' ');
    execute();
    token_len_ = 0;
    token_overflow_ = false;
  }
}

// Why: the subset seed 002 sends (ED, FT, I, PA, ps, pp, PP) plus their obvious twins (EE, FV,
// the PS/PA queries); everything else gets the unit's error line.
void PtuEmulator::execute() {
  if (token_overflow_) {
    reply_error("Illegal Command");
    return;
  }
  for (std::size_t i = 0; i < token_len_; ++i) token_[i] = upper(token_[i]);
  const char* t = token_.data();
  const std::size_t n = token_len_;
  auto is = [&](const char* word) {
    const std::size_t w = std::char_traits<char>::length(word);
    return n == w && std::equal(word, word + w, t);
  };
  // The mode switches: each sets one flag and is acknowledged.
  struct Switch {
    const char* word;         // the command
    bool PtuEmulator::*flag;  // the mode it sets
    bool value;               // to this
  };
  static constexpr Switch kSwitches[] = {{"ED", &PtuEmulator::echo_, false},
                                         {"EE", &PtuEmulator::echo_, true},
                                         {"FT", &PtuEmulator::verbose_, false},
                                         {"FV", &PtuEmulator::verbose_, true}};
  for (const auto& sw : kSwitches) {
    if (is(sw.word)) {
      this->*sw.flag = sw.value;
      reply_ok();
      return;
    }
  }
  if (is("I")) {
    reply_ok();  // immediate execution: the only mode emulated
  } else if (is("S")) {
    reply_error("Slaved mode is not emulated");
  } else if (n >= 2 && t[0] == 'P') {
    execute_pan(t[1], t + 2, n - 2);
  } else if (t[0] == 'T') {
    reply_error("Tilt axis is not emulated");
  } else {
    reply_error("Illegal Command");
  }
}

// Why: each pan command is a query without an argument and a setting with one.
void PtuEmulator::execute_pan(char code, const char* arg, std::size_t len) {
  if (code != 'P' && code != 'S' && code != 'A') {
    reply_error("Illegal Command");
    return;
  }
  if (len == 0) {
    if (code == 'P') reply_value("Current Pan position is ", position());
    else if (code == 'S') reply_value("Target Pan speed is ", speed_, " positions/sec");
    else reply_value("Pan acceleration is ", accel_, " positions/sec^2");
    return;
  }
  std::int64_t v = 0;
  if (!parse_integer(arg, len, v)) {
    reply_error("Illegal Command Argument");
    return;
  }
  if (code == 'P') {
    const std::int64_t hi = params_.max_position, lo = params_.min_position;
    if (v > hi) return reply_error("Maximum allowable Pan position is ", &hi);
    if (v < lo) return reply_error("Minimum allowable Pan position is ", &lo);
    target_ = static_cast<std::int32_t>(v);
  } else if (code == 'S') {
    const std::int64_t hi = params_.max_speed, lo = params_.min_speed;
    if (v > hi) return reply_error("Pan speed cannot exceed ", &hi, " pos/sec");
    if (v < lo) return reply_error("Pan speed cannot be below ", &lo, " pos/sec");
    speed_ = static_cast<std::int32_t>(v);
  } else {
    const std::int64_t hi = params_.max_acceleration;
    if (v > hi) return reply_error("Pan acceleration cannot exceed ", &hi, " pos/sec^2");
    if (v < 1) return reply_error("Illegal Command Argument");
    accel_ = static_cast<std::int32_t>(v);
  }
  reply_ok();
}

// Why clamp: the direct API (the built-in sweep) has no error line to answer with.
void PtuEmulator::command_position(std::int32_t position) {
  target_ = std::clamp(position, params_.min_position, params_.max_position);
}

// Why clamp: as command_position.
void PtuEmulator::command_speed(std::int32_t speed) {
  speed_ = std::clamp(speed, params_.min_speed, params_.max_speed);
}

// Why: a stepper counts whole steps; while moving, the count is the last step passed.
std::int32_t PtuEmulator::position() const {
  double p = pos_;
  if (vel_ > 0.0) p = std::floor(pos_ + kEps);
  else if (vel_ < 0.0) p = std::ceil(pos_ - kEps);
  else p = std::round(pos_);
  return static_cast<std::int32_t>(p);
}

// Why: a trapezoidal profile (accelerate at PA, cruise at PS, brake to stop on the target),
// integrated in closed form phase by phase so the result does not depend on the step size.
void PtuEmulator::advance(double dt_s) {
  double dt = dt_s;
  const double a = static_cast<double>(accel_);
  for (int guard = 0; guard < 16 && dt > 0.0; ++guard) {
    const double d = static_cast<double>(target_) - pos_;
    if (std::abs(d) < kEps && std::abs(vel_) < kEps) {
      pos_ = target_;
      vel_ = 0.0;
      return;
    }
    // dir: toward the target (or, sitting on it while moving, against the motion).
    const double dir = std::abs(d) >= kEps ? (d > 0.0 ? 1.0 : -1.0) : (vel_ > 0.0 ? -1.0 : 1.0);
    const double s = vel_ * dir;                      // speed toward the target
    const double dist = std::abs(d) >= kEps ? std::abs(d) : 0.0;
    const double vmax = static_cast<double>(speed_);
    double acc = 0.0;  // acceleration along dir for this phase
    double phase = 0.0;  // duration of this phase
    bool arrive = false;  // the phase ends on the target at rest
    if (s < 0.0) {
      acc = a;  // moving away: brake first
      phase = -s / a;
    } else if (s * s / (2.0 * a) >= dist - kBrakeEps) {
      if (s <= kEps) {  // at rest on the target
        pos_ = target_;
        vel_ = 0.0;
        return;
      }
      acc = -s * s / (2.0 * dist);  // the braking curve that stops exactly on the target
      phase = 2.0 * dist / s;
      arrive = true;
    } else if (s > vmax + kEps) {
      acc = -a;  // slow down to a lowered speed (never crosses the braking curve)
      phase = (s - vmax) / a;
    } else if (s < vmax - kEps) {
      acc = a;  // speed up until the speed or the braking point, whichever comes first
      const double c = s * s / (2.0 * a) - dist;
      const double to_brake = (-s + std::sqrt(std::max(0.0, s * s - a * c))) / a;
      phase = std::min((vmax - s) / a, to_brake);
    } else {
      acc = 0.0;  // cruise to the braking point
      phase = (dist - s * s / (2.0 * a)) / s;
    }
    phase = std::max(phase, 0.0);
    const double tau = std::min(dt, phase);
    if (arrive && tau >= phase) {
      pos_ = target_;
      vel_ = 0.0;
    } else {
      pos_ += dir * (s * tau + 0.5 * acc * tau * tau);
      vel_ = dir * (s + acc * tau);
      if (tau >= phase && acc != 0.0) {
        const double end = s + acc * phase;  // snap phase ends: exact speed, or exactly zero
        vel_ = dir * (std::abs(end - vmax) < 1e-6 ? vmax : (std::abs(end) < 1e-6 ? 0.0 : end));
      }
    }
    dt -= tau;
  }
}

// Why peek: a pty may take only part of the bytes; the rest must stay queued.
std::size_t PtuEmulator::peek_output(std::span<std::uint8_t> out) const {
  const std::size_t n = std::min(out.size(), out_size_);
  for (std::size_t i = 0; i < n; ++i) out[i] = out_[(out_first_ + i) % out_.size()];
  return n;
}

// Why separate: only the bytes the host actually took leave the ring.
void PtuEmulator::consume_output(std::size_t n) {
  n = std::min(n, out_size_);
  out_first_ = (out_first_ + n) % out_.size();
  out_size_ -= n;
}

// Why: the common case (tests, a host that takes everything) in one call.
std::size_t PtuEmulator::read_output(std::span<std::uint8_t> out) {
  const std::size_t n = peek_output(out);
  consume_output(n);
  return n;
}

// Why one place: every acknowledgement has the same shape in both feedback modes.
void PtuEmulator::reply_ok(const char* text) {
  put('*');
  if (text) {
    put(' ');
    put(text);
  }
  put("\r\n");
}

// Why: the seed (FT) parses "* <n>" from the third character on; verbose is the unit's default.
void PtuEmulator::reply_value(const char* verbose_text, std::int64_t n, const char* unit) {
  put("* ");
  if (verbose_) put(verbose_text);
  put_number(n);
  if (verbose_ && unit) put(unit);
  put("\r\n");
}

// Why the same text in terse mode: the seed never errs, and a readable message helps whoever does.
void PtuEmulator::reply_error(const char* message, const std::int64_t* n, const char* unit) {
  put("! ");
  put(message);
  if (n) put_number(*n);
  if (unit) put(unit);
  put("\r\n");
}

// Why: replies are assembled from constant pieces without any string object.
void PtuEmulator::put(const char* s) {
  while (*s) put(*s++);
}

// Why: a host that never reads must not grow memory; extra bytes are counted and lost.
void PtuEmulator::put(char c) {
  if (out_size_ == out_.size()) {
    ++dropped_;
    return;
  }
  out_[(out_first_ + out_size_) % out_.size()] = static_cast<std::uint8_t>(c);
  ++out_size_;
}

// Why to_chars: no locale, no allocation.
void PtuEmulator::put_number(std::int64_t n) {
  char buf[24];
  const auto r = std::to_chars(buf, buf + sizeof buf, n);
  for (const char* p = buf; p != r.ptr; ++p) put(*p);
}

}  // namespace robuter::hal
