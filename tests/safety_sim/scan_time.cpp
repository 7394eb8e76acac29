// SPDX-License-Identifier: GPL-3.0-or-later
// Full-scan time of a stopped robot over the link: UT all ones, UD3, Ut33, then USS and USN.
#include "tests/safety_sim/scan_time.hpp"

#include <cstdlib>

#include "modules/firmware/sim_firmware.hpp"

namespace robuter::test::safety_sim {

namespace {
// The number of an "S <n>" reply, or −1.
int number(const std::optional<std::string>& reply) {
  if (!reply || reply->size() < 3 || reply->compare(0, 2, "S ") != 0) return -1;
  return std::atoi(reply->c_str() + 2);
}
}  // namespace

ScanTime measure_scan_time(const Config& cfg, const std::string& world, int ticks) {
  ScanTime out;
  SimFirmware fw(world, cfg);
  if (!fw.ok()) {
    out.error = fw.error();
    return out;
  }
  for (const char* line : {"UT111111111111111111111111", "UD3", "Ut33"}) {
    if (fw.ask(line) != "ack") {
      out.error = std::string(line) + " refused";
      return out;
    }
  }
  fw.run_ticks(ticks);
  out.scan_ticks = number(fw.ask("USS"));
  out.node_ticks = number(fw.ask("USN"));
  return out;
}

}  // namespace robuter::test::safety_sim
