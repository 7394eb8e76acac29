// robuterctl: interactive client, conformance script runner and latency bench for robuterd's link.
#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <readline/history.h>
#include <readline/readline.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "tools/robuterctl/client.hpp"
#include "tools/robuterctl/decode.hpp"
#include "tools/robuterctl/script.hpp"

namespace {

using namespace robuter::ctl;
using std::chrono::milliseconds;

// Every message robuterd knows, for tab completion.
const char* const kCommands[] = {"BO", "BU", "BV", "BC", "BT", "BP", "BF", "BD", "AM ", "ASN", "ASF", "AY", "AC ",
                                 "AW ", "AX", "Ap", "Ag", "AG", "AT", "Ad", "Af", "UT", "UD", "UN", "USN", "USS",
                                 "Ut", "Uu0", "Uu1", "XE", "XR", "XK", "XV", "XS", "XB0", "XB1", "XC0", "XC1", nullptr};

char* command_generator(const char* text, int state) {
  static int index;
  static std::size_t len;
  if (state == 0) {
    index = 0;
    len = std::strlen(text);
  }
  while (const char* c = kCommands[index]) {
    ++index;
    if (std::strncmp(c, text, len) == 0) return strdup(c);
  }
  return nullptr;
}

char** complete(const char* text, int start, int) {
  rl_attempted_completion_over = 1;
  return start == 0 ? rl_completion_matches(text, command_generator) : nullptr;
}

// Interactive session: readline with history and completion, decoded replies, emergency banner.
int interactive(Client& c) {
  const char* home = std::getenv("HOME");
  const std::string history = std::string(home ? home : ".") + "/.robuterctl_history";
  read_history(history.c_str());
  rl_attempted_completion_function = complete;
  fmt::print("robuterctl: connected. Tab completes commands, Ctrl-D quits. AX shuts robuterd down.\n");
  while (char* raw = readline("robuter> ")) {
    std::string line(raw);
    std::free(raw);
    if (line.empty()) continue;
    add_history(line.c_str());
    if (!c.send_line(line)) {
      fmt::print("link closed\n");
      break;
    }
    const auto reply = c.read_line(milliseconds(2000));
    if (!reply) {
      fmt::print("(no reply within 2 s)\n");
      continue;
    }
    fmt::print("< {}\n  {}\n", *reply, describe_reply(line, *reply));
    if (line == "AX") break;
    if (c.send_line("XE")) {
      if (const auto xe = c.read_line(milliseconds(1000))) {
        std::string banner;
        if (emergency_banner(*xe, banner)) fmt::print("\033[1;31m{}\033[0m\n", banner);
      }
    }
  }
  write_history(history.c_str());
  return 0;
}

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

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"robuterctl — talk to robuterd over its command link"};
  std::string port = "/tmp/robuter.pty", bench_line = "BO";
  std::vector<std::string> scripts;
  int bench_n = 0;
  unsigned baud = 0;
  app.add_option("-p,--port", port, "pty or serial device of the link");
  app.add_option("--baud", baud, "serial rate, bit/s (serial devices)");
  app.add_option("-s,--script", scripts, "run conformance scripts (> send, < expect, ! directives) and exit");
  app.add_option("--bench", bench_n, "measure the round-trip latency over N requests and exit");
  app.add_option("--bench-line", bench_line, "the request the bench sends");
  CLI11_PARSE(app, argc, argv);

  Client client(port, baud);
  if (client.error()) {
    fmt::print(stderr, "robuterctl: {}\n", *client.error());
    return 2;
  }
  if (!scripts.empty()) {
    int failed = 0, checks = 0;
    for (const auto& s : scripts) {
      const ScriptResult r = run_script(client, s, stdout);
      checks += r.checks;
      if (r.failures) ++failed;
      fmt::print("{} {} ({} checks)\n", r.failures ? "FAIL" : "ok  ", s, r.checks);
    }
    fmt::print("{} passed, {} failed\n", scripts.size() - static_cast<std::size_t>(failed), failed);
    return failed ? 1 : 0;
  }
  if (bench_n > 0) return bench(client, bench_n, bench_line);
  return interactive(client);
}
