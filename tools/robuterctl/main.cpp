// SPDX-License-Identifier: GPL-3.0-or-later
// robuterctl: interactive console, conformance script runner and latency bench for robuterd's link.
//
// The console is one poll() loop over the terminal and the link, with readline's callback
// interface: replies are paired with their lines by the protocol (pairing.hpp) and printed above
// the prompt when they arrive, so the stop key (Ctrl-X, bound in readline) and the live status
// (the status stream, XS) work at any moment — at the prompt and while a reply is awaited.
#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <poll.h>
#include <readline/history.h>
#include <readline/readline.h>
#include <termios.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "cli/parse_or_usage.hpp"
#include "tools/robuterctl/client.hpp"
#include "tools/robuterctl/commands.hpp"
#include "tools/robuterctl/decode.hpp"
#include "tools/robuterctl/pairing.hpp"
#include "tools/robuterctl/script.hpp"

#ifndef ROBUTER_VERSION
#define ROBUTER_VERSION "unknown"
#endif

namespace {

using namespace robuter::ctl;
using std::chrono::milliseconds;

constexpr char kStopByte = 0x18;
constexpr int kStreamTicks = 10;                 // our status stream: every 100 ms
constexpr milliseconds kPollPeriod{200};         // XE polling when the stream is off
constexpr milliseconds kReplyPatience{3000};     // then "no reply yet" is said once

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t");
  return s.substr(b, e - b + 1);
}

class Console;
Console* g_console = nullptr;

class Console {
 public:
  Console(Client& c, std::string history) : c_(c), history_(std::move(history)) {}

  int run() {
    g_console = this;
    using_history();
    if (read_history(history_.c_str()) != 0) write_history(history_.c_str());  // creates it
    rl_readline_name = "robuterctl";
    rl_attempted_completion_function = complete;
    rl_catch_signals = 0;  // Ctrl-C is ours: it cancels the line
    catch_interrupt();
    std::signal(SIGPIPE, SIG_IGN);
    fmt::print("robuterctl {}: connected. Ctrl-X stops the robot at any moment; `help` lists the commands; "
               "Tab completes; Ctrl-D quits.\n", ROBUTER_VERSION);
    std::fflush(stdout);
    // Live status: subscribe to the status stream; the emergency's cause comes from XE.
    send(fmt::format("XS{}", kStreamTicks), true);
    // Ctrl-X is readline's prefix of C-x sequences (and the inputrc's); a prefix waits for the next
    // key before acting, and rl_bind_key on a prefix binds only its default. So the entry itself
    // is made a plain function, after the inputrc was read: it acts on the key alone, at once.
    rl_initialize();
    for (Keymap map : {emacs_standard_keymap, vi_insertion_keymap, vi_movement_keymap}) {
      map[static_cast<unsigned char>(kStopByte)].type = ISFUNC;
      map[static_cast<unsigned char>(kStopByte)].function = stop_key;
    }
    rl_callback_handler_install(prompt().c_str(), on_line);
    installed_ = true;
    while (!quit_) {
      pollfd p[2] = {{STDIN_FILENO, POLLIN, 0}, {c_.fd(), POLLIN, 0}};
      const int n = ::poll(p, 2, 50);
      if (interrupted()) cancel_line();
      if (n > 0 && (p[0].revents & (POLLIN | POLLHUP))) rl_callback_read_char();
      if (n > 0 && (p[1].revents & (POLLIN | POLLHUP | POLLERR))) {
        const bool open = c_.pump();
        while (auto line = c_.next_line()) handle(*line);
        if (!open) {
          print("link closed (robuterd ended or the port went away)\n");
          quit_ = true;
        }
      }
      housekeeping();
    }
    if (installed_) rl_callback_handler_remove();
    history_truncate_file(history_.c_str(), 1000);
    return 0;
  }

  // Ctrl-X: the stop byte now, whatever is typed or awaited.
  static int stop_key(int, int) {
    if (g_console) g_console->stop();
    return 0;
  }

 private:
  static void on_line(char* raw) { g_console->line(raw); }

  static char* generator(const char* text, int state) {
    static std::size_t index, len;
    if (state == 0) index = 0, len = std::strlen(text);
    const auto table = command_table();
    while (index < table.size()) {
      const auto& c = table[index++];
      if (c.name.size() >= len && c.name.substr(0, len) == text) return strdup(std::string(c.name).c_str());
    }
    return nullptr;
  }
  static char** complete(const char* text, int start, int) {
    rl_attempted_completion_over = 1;
    // The first word is a command; after `help` another command.
    const std::string before(rl_line_buffer, static_cast<std::size_t>(start));
    if (start == 0 || trim(before) == "help") return rl_completion_matches(text, generator);
    return nullptr;
  }

  std::string prompt() const { return latched_ ? "robuter [EMERGENCY]> " : "robuter> "; }

  // Text printed above the prompt and the line being typed, which are drawn again below it.
  void print(const std::string& text) {
    if (installed_) rl_clear_visible_line();
    std::fwrite(text.data(), 1, text.size(), stdout);
    std::fflush(stdout);
    if (installed_) rl_forced_update_display();
  }
  // The prompt shows a latched emergency; drawn by the next print().
  void set_prompt() {
    if (installed_) rl_set_prompt(prompt().c_str());
  }

  void stop() {
    c_.send_raw(std::string(1, kStopByte));
    c_.note("stop byte 0x18 sent");
    print("\033[1;31m» stop byte sent (0x18): the robot stops and the emergency latches; XR re-enables\033[0m\n");
  }

  void cancel_line() {
    clear_interrupted();
    if (!installed_) return;
    rl_callback_sigcleanup();
    rl_replace_line("", 0);
    rl_point = rl_end = 0;
    std::fputs("^C\n", stdout);
    std::fflush(stdout);
    rl_on_new_line();
    rl_redisplay();
  }

  void send(const std::string& line, bool internal) {
    if (!c_.send_raw(pairing_.outgoing(line, internal))) {
      print("link closed\n");
      quit_ = true;
    }
    if (internal && line == "XE") last_poll_ = std::chrono::steady_clock::now();
  }

  // A line typed and entered (nullptr: Ctrl-D).
  void line(char* raw) {
    if (!raw) {
      std::fputs("\n", stdout);
      quit_ = true;
      rl_callback_handler_remove();
      installed_ = false;
      return;
    }
    const std::string typed(raw);
    std::free(raw);
    const std::string t = trim(typed);
    if (t.empty()) return;
    add_history(typed.c_str());
    append_history(1, history_.c_str());
    const auto space = t.find(' ');
    const std::string word = t.substr(0, space);
    const std::string arg = space == std::string::npos ? "" : trim(t.substr(space + 1));
    if (word == "help" || word == "?") return (void)std::fputs(help_text(arg).c_str(), stdout);
    if (word == "stop") return stop();
    if (word == "quit" || word == "exit") {
      quit_ = true;
      rl_callback_handler_remove();
      installed_ = false;
      return;
    }
    if (word == "clear") return (void)std::fputs("\033[H\033[2J", stdout);
    if (word == "status") {
      std::fputs((last_status_.empty() ? std::string("no status line yet (the stream is off)")
                                       : describe_stream(last_status_)).c_str(), stdout);
      std::fputs("\n", stdout);
      return;
    }
    send(typed, false);
  }

  // One line of the link.
  void handle(const std::string& raw) {
    const Incoming in = pairing_.incoming(raw);
    const std::string bad = in.checksum_bad ? "  \033[1;31m(checksum missing or wrong)\033[0m" : "";
    if (in.kind == Incoming::Kind::stream) {
      last_status_ = in.text;
      if (user_stream_) print(fmt::format("\033[2m{}\033[0m{}\n", in.text, bad));
      const EmergencyView v = read_stream(in.text);
      if (v.valid && v.latched && !latched_ && !xe_in_flight()) send("XE", true);  // its cause
      if (v.valid && !v.latched && latched_) cleared();
      protective_from(v);
      return;
    }
    if (in.kind == Incoming::Kind::unexpected) {
      c_.note("unexpected line: " + in.text);
      print(fmt::format("\033[33m? a line that answers nothing sent (stale or late): {}\033[0m{}\n", in.text, bad));
      return;
    }
    if (in.lost) print(fmt::format("({} earlier line(s) got no reply: robuterd dropped them)\n", in.lost));
    const std::string cmd = trim(in.command);
    if (in.internal) {
      if (cmd.rfind("XS", 0) == 0) live_poll_ = in.text != "ack";  // no stream: poll XE instead
      if (cmd == "XE") emergency_from(read_xe(in.text));
      return;
    }
    std::string out = fmt::format("< {}{}\n", in.text, bad);
    const std::string words = describe_reply(cmd, in.text);
    if (!words.empty()) out += "  " + words + "\n";
    print(out);
    if (cmd == "XE") emergency_from(read_xe(in.text));
    if (cmd == "XR" && in.text == "ack" && latched_) cleared();
    if (cmd.rfind("XS", 0) == 0 && in.text == "ack") {
      user_stream_ = pairing_.stream_period() > 0;
      live_poll_ = !user_stream_;
    }
  }

  bool xe_in_flight() const {
    for (const auto& w : pairing_.waiting())
      if (w.internal && w.command == "XE") return true;
    return false;
  }

  // A protective stop is shown when it begins, once; it ends by itself.
  void protective_from(const EmergencyView& v) {
    if (!v.valid) return;
    if (v.protective && !protective_ && !v.latched) {
      c_.note("protective stop");
      print(fmt::format("\033[1;43;30m{}\033[0m\n", protective_banner()));
    }
    protective_ = v.protective;
  }

  void emergency_from(const EmergencyView& v) {
    if (!v.valid) return;
    protective_from(v);
    if (v.latched && !latched_) {
      latched_ = true;
      c_.note("emergency latched: " + v.cause);
      set_prompt();
      print(fmt::format("\033[1;41;37m{}\033[0m\n", emergency_banner(v.cause)));
    } else if (!v.latched && latched_) {
      cleared();
    }
  }
  void cleared() {
    latched_ = false;
    c_.note("emergency cleared");
    set_prompt();
    print("\033[1;32memergency cleared: motion commands are accepted again\033[0m\n");
  }

  void housekeeping() {
    const auto now = std::chrono::steady_clock::now();
    for (auto& w : pairing_.waiting()) {
      if (w.internal || w.overdue_told || now - w.sent < kReplyPatience) continue;
      w.overdue_told = true;
      print(fmt::format("(no reply to '{}' within {} s; a late reply is shown when it comes)\n", trim(w.command),
                        kReplyPatience.count() / 1000));
    }
    if (live_poll_ && pairing_.waiting().empty() && now - last_poll_ >= kPollPeriod) send("XE", true);
  }

  Client& c_;
  std::string history_;
  Pairing pairing_;
  bool quit_ = false;
  bool installed_ = false;
  bool latched_ = false;      // an emergency is latched, as far as we know
  bool protective_ = false;   // a protective stop is in force, as far as we know
  bool user_stream_ = false;  // the operator asked for the stream: show its lines
  bool live_poll_ = false;    // no stream: poll XE
  std::chrono::steady_clock::time_point last_poll_{};
  std::string last_status_;
};

// Round-trip latency of `line` over `n` requests: one in flight at a time.
int bench(Client& c, int n, const std::string& line) {
  std::vector<double> us;
  us.reserve(static_cast<std::size_t>(n));
  c.drain(milliseconds(100));
  for (int i = 0; i < n; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    if (!c.send_line(line) || !c.read_line(milliseconds(2000))) {
      fmt::print(stderr, "robuterctl: no reply to request {}\n", i);
      return 1;
    }
    us.push_back(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count());
  }
  std::sort(us.begin(), us.end());
  auto q = [&](double p) { return us[std::min(us.size() - 1, static_cast<std::size_t>(p * static_cast<double>(us.size())))]; };
  double total = 0;
  for (double v : us) total += v;
  fmt::print("{} round trip over {} requests: p50 {:.0f} us, p99 {:.0f} us, max {:.0f} us, mean {:.0f} us ({:.0f} requests/s)\n",
             line, n, q(0.5), q(0.99), us.back(), total / n, 1e6 * n / total);
  return 0;
}

// The terminal in script mode: keys arrive one by one (Ctrl-X without Enter), Ctrl-C still signals.
class KeyTerminal {
 public:
  KeyTerminal() {
    if (!isatty(STDIN_FILENO) || tcgetattr(STDIN_FILENO, &saved_) != 0) return;
    termios t = saved_;
    t.c_lflag &= static_cast<tcflag_t>(~(ICANON | ECHO));
    t.c_cc[VMIN] = 1;
    t.c_cc[VTIME] = 0;
    active_ = tcsetattr(STDIN_FILENO, TCSANOW, &t) == 0;
  }
  ~KeyTerminal() {
    if (active_) tcsetattr(STDIN_FILENO, TCSANOW, &saved_);
  }
  bool active() const { return active_; }

 private:
  termios saved_{};
  bool active_ = false;
};

int scripts_mode(Client& client, const std::vector<std::string>& scripts, const ScriptOptions& options) {
  catch_interrupt();
  KeyTerminal keys;
  if (keys.active()) {
    client.watch(STDIN_FILENO, [&client] {
      char k = 0;
      if (::read(STDIN_FILENO, &k, 1) == 1 && k == kStopByte) {
        client.send_raw(std::string(1, kStopByte));
        client.note("stop byte 0x18 sent (Ctrl-X)");
        fmt::print("» stop byte sent (Ctrl-X)\n");
        std::fflush(stdout);
      }
    });
  }
  int passed = 0, failed = 0, scripts_failed = 0;
  bool stopped_by_user = false;
  for (const auto& s : scripts) {
    const ScriptResult r = run_script(client, s, stdout, options);
    passed += r.checks;
    failed += r.failures;
    if (r.failures) ++scripts_failed;
    fmt::print("{} {} ({} checks met, {} failed)\n", r.failures ? "FAIL" : "ok  ", s, r.checks, r.failures);
    std::fflush(stdout);
    // Leave the robot stopped (never with the stop byte, which latches it).
    clear_interrupted();
    const std::string left = leave_stopped(client);
    fmt::print("  robot left stopped: {}\n", left);
    client.note("robot left stopped: " + left);
    if (r.interrupted) {
      stopped_by_user = true;
      break;
    }
  }
  fmt::print("{} passed, {} failed{}\n", passed, failed, stopped_by_user ? " (interrupted)" : "");
  return scripts_failed || stopped_by_user ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"robuterctl — talk to robuterd over its command link"};
  std::string port = "/tmp/robuter.pty", bench_line = "BO", log_path, history;
  std::vector<std::string> scripts;
  int bench_n = 0;
  unsigned baud = 0;
  bool keep_going = false;
  app.set_version_flag("--version", std::string("robuterctl ") + ROBUTER_VERSION);
  app.add_option("-p,--port", port, "pty or serial device of the link (default /tmp/robuter.pty, as `make run`)");
  app.add_option("--baud", baud, "serial rate, bit/s (serial devices): 1200 … 921600");
  app.add_option("-s,--script", scripts, "run conformance scripts (> send, < expect, ! directives) and exit");
  app.add_flag("-k,--keep-going", keep_going, "scripts: go on after a failed expectation");
  app.add_option("--log", log_path, "write a transcript with times of every line sent and received to FILE");
  app.add_option("--history", history, "history file (default $HOME/.robuterctl_history)");
  app.add_option("--bench", bench_n, "measure the round-trip latency over N requests and exit");
  app.add_option("--bench-line", bench_line, "the request the bench sends");
  if (const auto status = robuter::cli::parse_or_usage(app, argc, argv)) return *status;  // usage errors: 2
  if (baud && !baud_supported(baud)) {
    fmt::print(stderr, "robuterctl: --baud {}: not a rate a serial device can be set to (1200, 2400, 4800, 9600, 19200, "
                       "38400, 57600, 115200, 230400, 460800, 921600)\n", baud);
    return 2;
  }

  std::FILE* log = nullptr;
  if (!log_path.empty()) {
    log = std::fopen(log_path.c_str(), "a");
    if (!log) {
      fmt::print(stderr, "robuterctl: --log {}: cannot open: {}\n", log_path, std::strerror(errno));
      return 2;
    }
  }
  Client client(port, baud);
  if (client.error()) {
    fmt::print(stderr, "robuterctl: {}\n", *client.error());
    if (client.open_errno() == ENOENT)
      fmt::print(stderr, "  is robuterd running? `make run` starts it on /tmp/robuter.pty; or start "
                         "`robuterd --sim --pty PATH` and give robuterctl --port PATH\n");
    else if (client.open_errno() == EACCES)
      fmt::print(stderr, "  no permission: a serial device usually needs the group dialout\n");
    return 1;
  }
  client.set_log(log);
  client.note(fmt::format("robuterctl {} on {}", ROBUTER_VERSION, port));
  // What an earlier client left unread would otherwise answer our first line.
  if (const std::size_t stale = client.flush_stale(milliseconds(50)); stale && scripts.empty() && bench_n == 0)
    fmt::print("({} bytes an earlier client left unread were dropped)\n", stale);
  int rc = 0;
  if (!scripts.empty()) {
    rc = scripts_mode(client, scripts, ScriptOptions{keep_going});
  } else if (bench_n > 0) {
    rc = bench(client, bench_n, bench_line);
  } else {
    if (history.empty()) {
      const char* home = std::getenv("HOME");
      history = std::string(home ? home : ".") + "/.robuterctl_history";
    }
    rc = Console(client, history).run();
  }
  if (log) std::fclose(log);
  return rc;
}
