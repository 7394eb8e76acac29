// SPDX-License-Identifier: GPL-3.0-or-later
// The whole firmware on the simulated robot, on a virtual clock, with a client on a real pty —
// tests and robuter-doors-run step time and talk to robuterd exactly as an operator would.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "modules/firmware/firmware.hpp"

namespace robuter::test {

class SimFirmware {
 public:
  // Builds and starts the firmware (world file, config); ok() tells whether it did. The
  // simulated pan-tilt unit is wired to the PTU module inside the process (robuterd --sim's
  // default); with `with_ptu` it is served on a pty instead and the PTU module opens it
  // (--ptu-pty and --ptu-port on the same temporary path). With `planner_pictures` a folder, the planner's
  // picture of every plan is written there (robuterd --planner-pictures), drawn between ticks.
  explicit SimFirmware(const std::string& world = "", const Config& cfg = Config{}, hal::SimOptions sim = {},
                       bool with_ptu = false, const std::string& planner_pictures = "");
  // Builds and starts the firmware from `opt` as given (e.g. hardware backends on a test CAN
  // bus, opt.sim false), with the harness's virtual clock and pty link added.
  SimFirmware(const Config& cfg, FirmwareOptions opt);
  ~SimFirmware();
  SimFirmware(const SimFirmware&) = delete;
  SimFirmware& operator=(const SimFirmware&) = delete;

  bool ok() const { return error_.empty(); }
  const std::string& error() const { return error_; }

  // Sends `line` and steps the kernel until its reply arrives (at most `max_ticks`).
  std::optional<std::string> ask(const std::string& line, int max_ticks = 50);
  // Writes `bytes` in one write (pipelined lines, stop bytes…) and steps the kernel until
  // `replies` reply lines arrived (at most `max_ticks`); returns those that did, in order.
  std::vector<std::string> exchange(std::string_view bytes, std::size_t replies, int max_ticks = 50);
  // Writes raw bytes to the link (no terminator added).
  void send_raw(std::string_view bytes);
  // Reads what the firmware wrote and counts complete lines without keeping them (no
  // allocation: for the allocation proof). Returns {replies, stream lines}.
  std::pair<int, int> count_lines();
  // Runs `n` ticks.
  void run_ticks(int n);
  // Runs until `pred()` holds or `max_ticks` pass; true if it held.
  template <typename Pred>
  bool run_until(Pred pred, int max_ticks) {
    for (int i = 0; i < max_ticks; ++i) {
      if (pred()) return true;
      step();
    }
    return pred();
  }
  void step();
  // Calls `f` after every tick the harness runs (step, run_ticks, run_until, ask, send_raw):
  // lets a test check an invariant on every tick, including those inside ask(). Empty = none.
  void set_tick_observer(std::function<void()> f) { observer_ = std::move(f); }
  // The module that runs in the process-table row `name`, as a T (null if absent or not a T).
  template <typename T>
  T* module(const char* name) {
    const auto i = fw_->kernel().find(name);
    return i ? dynamic_cast<T*>(fw_->kernel().row(*i).process) : nullptr;
  }
  // Unplugs the emulated pan-tilt unit: its end of the pty is closed (with_ptu) or the
  // in-process pipe hangs up; the PTU module's port is lost either way.
  void unplug_ptu();
  // The client goes away: its end of the link is closed (ask() fails from then on).
  void close_client();
  // A new client: the current one closes, another opens the pty (a fresh session).
  bool reconnect();
  // Another client opens the pty, writes `bytes` and closes it at once, without a tick in
  // between (`printf '…' > pty`); the current client stays as it is.
  bool one_shot(std::string_view bytes);
  // The pty's path (the symbolic link clients open).
  const std::string& pty_path() const { return pty_path_; }
  // Lines that arrived without being asked for (stream lines), since the last call.
  std::string take_unsolicited();

  Firmware& firmware() { return *fw_; }
  Kernel& kernel() { return fw_->kernel(); }
  Blackboard& bb() { return fw_->blackboard(); }
  hal::SimRobot& sim() { return *fw_->sim(); }
  double seconds() const;  // simulated time, s
  // The wheel speeds the simulated drive is commanded now {left, right}, cm/s.
  std::pair<int, int> wheels();

 private:
  // The common start: virtual clock, pty link in a temporary folder, setup, client, kernel start.
  void open(const Config& cfg, FirmwareOptions opt);

  std::string dir_;                 // temporary folder of the pty link
  std::string pty_path_;            // the link's path in dir_
  std::unique_ptr<Firmware> fw_;
  int client_ = -1;                 // the client's end (pty slave)
  std::string pending_;             // bytes read past the last line
  std::string unsolicited_;         // lines read while no reply was awaited
  std::string error_;
  bool started_ = false;
  bool at_line_start_ = true;       // count_lines(): next byte starts a line
  bool stream_line_ = false;        // count_lines(): the current line is a stream line
  std::function<void()> observer_;  // called after every tick (set_tick_observer)
};

}  // namespace robuter::test
