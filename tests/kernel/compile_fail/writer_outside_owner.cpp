// SPDX-License-Identifier: GPL-3.0-or-later
// Must NOT compile: a module that is not the topic's owner asks for its writable handle.
#include "kernel/blackboard.hpp"

struct Posture {
  int x = 0;  // 0.1 mm
};
class Executor;  // the owner
using PostureTopic = robuter::Topic<Posture, Executor>;

class Intruder {
 public:
  explicit Intruder(PostureTopic& t) : w_(t.writer()) {}  // error: writer() is private
  robuter::Writer<Posture> w_;
};

int main() {
  PostureTopic t;
  Intruder i(t);
  i.w_.publish(Posture{1});
}
