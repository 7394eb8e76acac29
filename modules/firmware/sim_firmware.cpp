// SPDX-License-Identifier: GPL-3.0-or-later
// The harness: temporary pty, firmware on a virtual clock, line-level client.
#include "modules/firmware/sim_firmware.hpp"

#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>

#include "hal/sitl/byte_pipe.hpp"
#include "hal/sitl/sim_stepper.hpp"
#include "modules/places/place_grid_writer.hpp"
#include "modules/localise/state_file.hpp"
#include "modules/planner/picture_writer.hpp"

namespace robuter::test {

SimFirmware::SimFirmware(const std::string& world, const Config& cfg, hal::SimOptions sim, bool with_ptu,
                         const std::string& planner_pictures) {
  char tmpl[] = "/tmp/robuter-test-XXXXXX";
  dir_ = mkdtemp(tmpl);
  FirmwareOptions opt;
  opt.sim = true;
  sim.world_file = world;
  opt.sim_options = sim;
  if (with_ptu) opt.ptu_pty = opt.ptu_port = dir_ + "/ptu.pty";
  opt.planner_pictures = planner_pictures;
  open(cfg, opt);
}

SimFirmware::SimFirmware(const Config& cfg, FirmwareOptions opt) {
  char tmpl[] = "/tmp/robuter-test-XXXXXX";
  dir_ = mkdtemp(tmpl);
  open(cfg, opt);
}

void SimFirmware::open(const Config& cfg, FirmwareOptions opt) {
  opt.speed = 0.0;  // virtual clock: the test steps time
  pty_path_ = dir_ + "/robuter.pty";
  opt.ptys = {pty_path_};
  fw_ = std::make_unique<Firmware>(cfg, opt);
  if (auto err = fw_->setup()) {
    error_ = *err;
    return;
  }
  client_ = ::open(opt.ptys[0].c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK);
  if (client_ < 0) {
    error_ = "cannot open the pty";
    return;
  }
  termios t{};
  tcgetattr(client_, &t);
  cfmakeraw(&t);
  tcsetattr(client_, TCSANOW, &t);
  if (!fw_->kernel().start()) {
    error_ = "kernel start failed";
    return;
  }
  started_ = true;
}

SimFirmware::~SimFirmware() {
  if (started_) fw_->kernel().shutdown();
  if (started_ && fw_->state_file() != nullptr) fw_->state_file()->drain();  // the pose close() handed over
  if (client_ >= 0) ::close(client_);
  fw_.reset();
  std::error_code ec;
  std::filesystem::remove_all(dir_, ec);
}

void SimFirmware::step() {
  fw_->kernel().step();
  // The firmware's non-real-time point for pictures, as robuterd's writer thread (unless that
  // thread was started): after the tick, outside the kernel's step.
  if (auto* w = fw_->planner_pictures(); w != nullptr && !w->running()) w->drain();
  if (auto* w = fw_->place_grids(); w != nullptr && !w->running()) w->drain();
  if (auto* w = fw_->state_file(); w != nullptr) w->drain();
  if (observer_) observer_();
}

void SimFirmware::run_ticks(int n) {
  for (int i = 0; i < n; ++i) step();
}

std::pair<int, int> SimFirmware::wheels() {
  std::int32_t l = 0, r = 0;
  sim().drive().commanded(l, r);
  return {l, r};
}

double SimFirmware::seconds() const { return fw_->sim() ? fw_->sim()->time() : 0.0; }

std::pair<int, int> SimFirmware::count_lines() {
  int replies = 0, stream = 0;
  char buf[4096];
  for (;;) {
    const ssize_t n = ::read(client_, buf, sizeof buf);
    if (n <= 0) break;
    for (ssize_t i = 0; i < n; ++i) {
      if (at_line_start_) stream_line_ = buf[i] == '@';
      at_line_start_ = buf[i] == '\r';
      if (buf[i] == '\r') ++(stream_line_ ? stream : replies);
    }
  }
  return {replies, stream};
}

void SimFirmware::send_raw(std::string_view bytes) {
  if (client_ < 0) return;  // the client went away (close_client)
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(client_, bytes.data() + done, bytes.size() - done);
    if (n > 0) done += static_cast<std::size_t>(n);
    else step();  // the pty is full: let the firmware read
  }
}

std::optional<std::string> SimFirmware::ask(const std::string& line, int max_ticks) {
  auto r = exchange(line + "\r", 1, max_ticks);
  if (r.empty()) return std::nullopt;
  return r.front();
}

std::vector<std::string> SimFirmware::exchange(std::string_view bytes, std::size_t replies, int max_ticks) {
  std::vector<std::string> out;
  send_raw(bytes);
  for (int i = 0; i <= max_ticks; ++i) {
    char buf[4096];
    for (;;) {
      const ssize_t n = ::read(client_, buf, sizeof buf);
      if (n <= 0) break;
      pending_.append(buf, static_cast<std::size_t>(n));
    }
    for (;;) {
      const auto cr = pending_.find('\r');
      if (cr == std::string::npos) break;
      std::string reply = pending_.substr(0, cr);
      pending_.erase(0, cr + 1);
      if (!reply.empty() && reply[0] == '@') {
        unsolicited_ += reply + "\n";
        continue;
      }
      out.push_back(std::move(reply));
      if (out.size() == replies) return out;
    }
    step();
  }
  return out;
}

// Why dup2 over the master: the emulator's PtyLink keeps its descriptor number, but the pty's
// last master reference goes away, exactly as when a USB adapter is pulled out.
void SimFirmware::unplug_ptu() {
  if (auto* pipe = fw_->ptu_pipe()) {  // the default: the unit wired inside the process
    pipe->unplug();
    return;
  }
  auto* stepper = module<hal::SimStepper>("sim");
  if (stepper == nullptr || stepper->ptu_port() == nullptr) return;
  const int fd = stepper->ptu_port()->stream().fd();
  if (fd < 0) return;
  const int null = ::open("/dev/null", O_RDWR | O_CLOEXEC);
  if (null < 0) return;
  ::dup2(null, fd);
  ::close(null);
}

bool SimFirmware::reconnect() {
  close_client();
  pending_.clear();
  client_ = ::open(pty_path_.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK);
  if (client_ < 0) return false;
  termios t{};
  tcgetattr(client_, &t);
  cfmakeraw(&t);
  tcsetattr(client_, TCSANOW, &t);
  return true;
}

bool SimFirmware::one_shot(std::string_view bytes) {
  const int fd = ::open(pty_path_.c_str(), O_WRONLY | O_NOCTTY);
  if (fd < 0) return false;
  const bool ok = ::write(fd, bytes.data(), bytes.size()) == static_cast<ssize_t>(bytes.size());
  ::close(fd);
  return ok;
}

void SimFirmware::close_client() {
  if (client_ >= 0) ::close(client_);
  client_ = -1;
}

std::string SimFirmware::take_unsolicited() {
  std::string out;
  out.swap(unsolicited_);
  return out;
}

}  // namespace robuter::test
