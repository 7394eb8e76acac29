// The planner's picture thread: take a snapshot from the mailbox, draw it, free the slot.
#include "modules/planner/picture_writer.hpp"

#include <chrono>
#include <cstdio>

#include "modules/planner/picture/plan_picture.hpp"

namespace robuter::planner {

bool PictureWriter::drain() {
  const plan::PlanSnapshot* snap = box_.take();
  if (snap == nullptr) return false;
  char name[64];
  std::snprintf(name, sizeof name, "/plan-g%03u-%03u.png", snap->goal_seq, snap->plan_number);
  const plan::Status st = plan::write_plan_picture(*snap, dir_ + name);
  box_.release();
  if (!st) {
    // Not the kernel's thread: a message on stderr costs the robot nothing.
    if (failed_.fetch_add(1) == 0) std::fprintf(stderr, "robuterd: planner picture: %s\n", st.error().text().c_str());
    return false;
  }
  written_.fetch_add(1);
  return true;
}

void PictureWriter::start() {
  if (thread_.joinable()) return;
  stop_ = false;
  thread_ = std::thread([this] {
    while (!stop_.load()) {
      if (!drain()) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
  });
}

void PictureWriter::stop() {
  if (thread_.joinable()) {
    stop_ = true;
    thread_.join();
  }
  drain();
}

}  // namespace robuter::planner
