// SPDX-License-Identifier: GPL-3.0-or-later
// Must compile: the control case of writer_outside_owner.cpp, the owner takes its handle.
#include "kernel/blackboard.hpp"

struct Posture {
  int x = 0;  // 0.1 mm
};
class Executor;
using PostureTopic = robuter::Topic<Posture, Executor>;

class Executor {
 public:
  explicit Executor(PostureTopic& t) : w_(t.writer()) {}
  robuter::Writer<Posture> w_;
};

int main() {
  PostureTopic t;
  Executor e(t);
  e.w_.publish(Posture{1});
  return t.reader().peek().x == 1 ? 0 : 1;
}
